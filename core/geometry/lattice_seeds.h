// Seed points for the mesher of a large polygon (polygon_mesher.h):
// Delaunay refinement inserts its points one at a time, each a bad triangle
// taken from a queue, which at a million nodes is CGAL's mesher's whole cost
// (95 % of a 1e6-node block's meshing, docs/performance.md
// "continuum_vs_fenicsx"). The interior of a large polygon is instead filled
// with a triangular lattice of near-equilateral triangles whose edges fit
// the size function, inserted in one spatially sorted batch; the refinement
// then only mends the band along the boundary, the constrained lines and
// points, and the seams where the lattice's spacing changes.
#pragma once

#include <vector>

#include "core/geometry/polygon_mesher.h"

namespace fissure {

/// The lattice spacing as a fraction of the element size h: equilateral
/// triangles of edge 0.68 h have the mean area (0.20 h^2) of the triangles
/// the refinement alone makes (polygon_mesher.h), so that a seeded mesh has
/// about the nodes of an unseeded one.
inline constexpr double kLatticeSpacing = 0.68;

/// Lattice points are kept this many spacings away from the boundary, the
/// constrained lines and points: closer, they would make slivers there.
inline constexpr double kLatticeMargin = 0.5;

/// The points of the lattice inside the region of `input` (the outer loop
/// less the holes), at least kLatticeMargin spacings from every loop edge,
/// polyline segment and required point. The spacing is kLatticeSpacing
/// h(x), halved or doubled in steps (the lattices of spacing s and s / 2
/// share the coarser one's points) and chosen per cell of a grid that is
/// split where h varies. Deterministic.
std::vector<Vec2> lattice_seeds(const MesherInput& input, const SizeFunction& size);

}  // namespace fissure
