// The continuum's triangle mesh (docs/continuum.md 2): straight-sided
// triangles of the domain, their vertices the P1 nodes of pressure and
// temperature, and the vertices plus the edges' midpoints the P2 nodes of
// the displacement (Taylor-Hood, theory.md 5.2). Boundary edges carry the
// names of the domain's sides they lie on (left, right, bottom, top) and
// `exterior`.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "continuum/poroelasticity/continuum_settings.h"
#include "core/geometry/polygon_mesher.h"
#include "core/geometry/vec2.h"

namespace fissure::continuum {

/// A mesh edge on the domain's boundary, the domain on its left.
struct BoundaryEdge {
  int a = -1, b = -1;  ///< vertices
  int mid = -1;        ///< its P2 midpoint node
};

struct ContinuumMesh {
  /// P2 nodes: the triangles' vertices first (the P1 nodes, 0 to
  /// n_vertices - 1), then one midpoint per edge.
  std::vector<Vec2> nodes;
  int n_vertices = 0;
  /// Per triangle: vertices 0, 1, 2 (counter-clockwise), then the midpoints
  /// of edges 0-1, 1-2 and 2-0.
  std::vector<std::array<int, 6>> triangles;
  std::vector<int> triangle_material;  ///< index of Scene::materials
  std::vector<std::pair<std::string, std::vector<BoundaryEdge>>> boundaries;

  int n_nodes() const { return static_cast<int>(nodes.size()); }
  int n_triangles() const { return static_cast<int>(triangles.size()); }
  /// The boundary's edges; null for a name the mesh does not have.
  const std::vector<BoundaryEdge>* boundary(std::string_view name) const;

  /// Where a point is: the triangle whose smallest barycentric coordinate at
  /// p is largest, and those coordinates. A linear search (monitors only).
  struct Place {
    int triangle = -1;
    Eigen::Vector3d weights = Eigen::Vector3d::Zero();
  };
  Place locate(const Vec2& p) const;
};

/// The boundaries every domain has, in this order.
inline constexpr std::string_view kNamedSides[] = {"left", "right", "bottom", "top", "exterior"};

/// The element size at a point: element_size, graded down to
/// fine_element_size at the sources.
SizeFunction size_function(const ContinuumControls& c);

/// The estimated number of triangles of the settings' mesh (refused above
/// max_elements before meshing).
double estimate_elements(const ContinuumControls& c);

/// Meshes the domain: the structured grid of its bounding box when
/// `divisions` are given (the domain must then be that rectangle), CGAL's
/// quality mesher with `element_size` otherwise; regions assign materials by
/// the triangles' centroids, the last region that holds one wins. Throws
/// fissure::Error.
ContinuumMesh build_continuum_mesh(const ContinuumControls& c);

}  // namespace fissure::continuum
