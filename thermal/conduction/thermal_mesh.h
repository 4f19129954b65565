// The triangle meshes of all blocks (docs/thermal.md 2), in the blocks'
// reference geometry (their vertices when the thermal process starts).
//
// Block edges are split before meshing, deterministically: every vertex of
// another block that lies on an edge splits it (T-junctions), and each piece
// is divided evenly by the size field, always from its lexicographically
// smaller end, so two blocks that share a piece get bit-identical boundary
// nodes there. The mesher keeps exactly these boundary nodes. Coincident
// boundary edges of two blocks are then found by their coordinates: they are
// the joint faces through which heat crosses (contact conductance, or merged
// nodes for perfect contact).
//
// For heat coming from outside the block meshes (the fracture fluid of issue
// 23 item 2), `edge_nodes` lists, per block and polygon edge, the mesh nodes
// along that edge in order: a fracture segment's BlockFace (block, edge)
// finds the wall nodes to give heat to.
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "core/geometry/vec2.h"
#include "core/state/rock_mass.h"
#include "thermal/conduction/thermal_settings.h"

namespace fissure::thermal {

/// The element size at a point: h near the sources, growing with the
/// distance d as h_s + grading d, at most the global h.
class SizeField {
 public:
  SizeField(const ThermalControls& c, double extent);
  double operator()(const Vec2& x) const;
  double global() const { return h_; }
  double at_sources() const { return h_source_; }
  /// Estimated number of triangles of the blocks' meshes (docs/thermal.md
  /// 2: an upper estimate).
  double estimate_elements(const std::vector<Block>& blocks) const;

 private:
  double h_ = 1, h_source_ = 1, grading_ = 0.3;
  std::vector<HeatSource> sources_;
};

/// A mesh edge on a block's boundary, oriented with the block's polygon
/// (the block on its left).
struct BoundaryEdge {
  int a = -1, b = -1;     ///< global nodes
  int block = -1;         ///< the block
  int polygon_edge = -1;  ///< the block's polygon edge it lies on (vertex index)
  int partner = -1;       ///< the coincident edge of another block, or -1 (exterior)
};

struct ThermalMesh {
  std::vector<Vec2> nodes;  ///< reference positions
  std::vector<int> node_block;
  std::vector<std::array<int, 3>> triangles;  ///< global node indices, counter-clockwise
  std::vector<int> triangle_block;
  std::vector<double> triangle_area;  ///< m^2 (reference geometry)
  std::vector<int>
      block_first_node;  ///< per block + 1: nodes of block b are [first[b], first[b+1])
  std::vector<BoundaryEdge> boundary_edges;
  /// Per block and polygon edge: the nodes along it, from the edge's first
  /// vertex to the next one (both included).
  std::vector<std::vector<std::vector<int>>> edge_nodes;
  /// Named boundaries: indices of boundary_edges (exterior edges only).
  std::vector<std::pair<std::string, std::vector<int>>> boundaries;

  int n_nodes() const { return static_cast<int>(nodes.size()); }
  int n_triangles() const { return static_cast<int>(triangles.size()); }
  const std::vector<int>* boundary(const std::string& name) const;

  /// Where a point is: the triangle (of `block`, or of any block when
  /// block < 0) whose smallest barycentric coordinate at p is largest, and
  /// those coordinates (all >= 0 inside it). A linear search.
  struct Place {
    int triangle = -1;
    Eigen::Vector3d weights = Eigen::Vector3d::Zero();
  };
  Place locate(const Vec2& p, int block) const;
};

/// The boundaries every rock has, in this order: the sides of its bounding
/// box and the whole exterior (ThermalMesh::boundaries starts with them).
inline constexpr std::string_view kNamedSides[] = {"left", "right", "bottom", "top", "exterior"};

/// A named wall that is not a side of the rock's bounding box: an
/// excavation's outline (closed polygon).
struct NamedWall {
  std::string name;
  std::vector<Vec2> outline;
};

/// Meshes every block of `state` (its current geometry is the reference)
/// with the size field, with nodes at the sources and edges along them
/// (each source in its block, source_block[s]). Exterior edges on a wall's
/// outline form a boundary of its name. Throws fissure::Error.
ThermalMesh build_thermal_mesh(const std::vector<Block>& blocks, const SizeField& size,
                               const std::vector<HeatSource>& sources,
                               const std::vector<int>& source_block,
                               const std::vector<NamedWall>& walls);

}  // namespace fissure::thermal
