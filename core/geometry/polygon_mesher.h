// Quality triangulation of one polygon (the meshes of the physics modules'
// docs, section 2): CGAL's
// constrained Delaunay mesher (Chew/Ruppert refinement of the interior, a
// minimum angle of about 20.7 degrees where the boundary allows it), with an
// element size that varies in space. The boundary is given already split
// into the nodes the mesh must have there, and the mesher keeps exactly
// these (no Steiner points on the boundary), so that two blocks that share an
// edge, split the same way, get the same boundary nodes.
#pragma once

#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "core/geometry/vec2.h"

namespace fissure {

struct MesherInput {
  /// Closed loops (the last point joins the first): the outer boundary
  /// first, then the holes.
  std::vector<std::vector<Vec2>> loops;
  /// A point inside each hole (not meshed).
  std::vector<Vec2> hole_seeds;
  /// Points the mesh must have inside (point sources, monitors).
  std::vector<Vec2> points;
  /// Open polylines the mesh edges must follow inside (line and area sources).
  std::vector<std::vector<Vec2>> polylines;
};

struct TriangleMesh {
  /// The loops' points first, in input order (loop after loop), then the
  /// nodes the mesher added.
  std::vector<Vec2> nodes;
  std::vector<std::array<int, 3>> triangles;  ///< counter-clockwise
};

/// Largest edge length of a triangle at a point (m).
using SizeFunction = std::function<double(const Vec2&)>;

/// Upper estimates of the triangles mesh_polygon makes, for refusing a mesh
/// before it is made. The mean triangle area of its meshes with edges at
/// most h is 0.19-0.21 h^2 (measured on the block meshes of an example scene, h =
/// 0.25-1 m); 0.17 h^2 makes the estimate an upper one by 10-20 %.
inline constexpr double kMeshedAreaPerTriangle = 0.17;

/// The extra triangles of the zone refined around a point, where the size
/// grows from h_fine by `grading` per metre up to h: the integral of
/// 1 / (c h(r)^2) over the zone, less what h counts there.
inline double refined_point_triangles(double h, double h_fine, double grading) {
  const double c = kMeshedAreaPerTriangle, g = grading, hs = h_fine, r = (h - hs) / g;
  return 2 * std::numbers::pi / (g * g) * (std::log(h / hs) + hs / h - 1) / c -
         std::numbers::pi * r * r / (c * h * h);
}

/// The same per metre of a line refined along its length (both sides).
inline double refined_line_triangles_per_length(double h, double h_fine, double grading) {
  const double c = kMeshedAreaPerTriangle, g = grading, hs = h_fine, r = (h - hs) / g;
  return 2 * ((1 / hs - 1 / h) / g / c - r / (c * h * h));
}

/// Meshes the region inside the loops. Deterministic: the same input gives
/// the same mesh. Throws fissure::Error when a loop crosses another.
TriangleMesh mesh_polygon(const MesherInput& input, const SizeFunction& size);

}  // namespace fissure
