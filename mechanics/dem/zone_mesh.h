// The zones of a deformable DEM block (docs/dem.md, "Deformable blocks"):
// its polygon, convex or not, with or without holes, meshed into triangles
// by the shared CGAL mesher (core/geometry/polygon_mesher.h: constrained
// Delaunay refinement, smallest angle about 20.7 degrees where the boundary
// allows it). Each polygon edge is first divided into equal pieces no
// longer than the zone size (core/geometry/edge_division.h, from the
// lexicographically smaller end: two blocks meeting along an edge get the
// same points), and the mesher keeps exactly these boundary nodes, so the
// block's boundary is a loop of nodes through every polygon vertex, where
// contacts act.
#pragma once

#include <array>
#include <vector>

#include "core/geometry/polygon.h"
#include "core/geometry/polygon_mesher.h"

namespace fissure::dem {

struct ZoneMesh {
  std::vector<Vec2> nodes;
  std::vector<std::array<int, 3>> zones;  ///< node indices, counter-clockwise
  /// The boundary as loops of node indices (no repeated first node): loop 0
  /// the outer boundary, counter-clockwise, then the holes, clockwise (the
  /// block on the left of every boundary edge, as in Polygon).
  std::vector<std::vector<int>> boundary;
  /// The node at each vertex of the polygon (same order as its vertices,
  /// loop after loop).
  std::vector<int> corner_nodes;
};

/// Meshes `polygon` into triangular zones whose edges are at most
/// `zone_size` (m) long (inside, up to about a quarter longer where a zone
/// meets the boundary). Throws GeometryError for a non-positive size, a
/// polygon without area or one whose loops cross.
ZoneMesh mesh_block(const Polygon& polygon, double zone_size);
/// The same with a zone size that varies in space (m; positive).
ZoneMesh mesh_block(const Polygon& polygon, const SizeFunction& zone_size);

}  // namespace fissure::dem
