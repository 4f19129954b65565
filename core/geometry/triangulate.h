// Triangulation of a polygon with holes, for output and plotting (block faces
// in results.xdmf). Only the polygon's own vertices are used, so the
// triangulation stays valid while the block moves and deforms with DDA's
// affine displacement field.
#pragma once

#include <array>
#include <vector>

#include "core/geometry/polygon.h"

namespace fissure {

/// Triangles as indices into polygon.vertices, counter-clockwise, covering
/// exactly the polygon (holes excluded). Constrained Delaunay triangulation
/// (CGAL, exact predicates) with every polygon edge as a constraint, so every
/// polygon edge is a triangle edge; no Steiner points, so a polygon with n
/// vertices and h holes gives n + 2h - 2 triangles. Works for concave
/// polygons, holes, collinear (180-degree) vertices and either loop
/// orientation. Fewer than 3 vertices: no triangles. Precondition: a valid
/// polygon (check_polygon empty); throws GeometryError for non-finite
/// coordinates or edges that cross.
std::vector<std::array<int, 3>> triangulate(const Polygon& polygon);

}  // namespace fissure
