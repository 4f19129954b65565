// The fracture network as flow and heat transport see it (theory.md 3.3):
// nodes at fracture ends and intersections, straight segments between them.
// Built from a DFN or joint sets by block cutting (rockmass/), or from the
// current block system's contacts (flow/). Node and segment order is
// deterministic for a given scene and seed. It is the shared field
// "fracture_graph" of the state (kFractureGraph).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/base/named_values.h"
#include "core/geometry/vec2.h"

namespace fissure {

/// One side of a segment: the block face it bounds, if any.
struct BlockFace {
  int block = -1;  ///< -1: no block on this side (domain boundary, or excavation)
  int edge = -1;   ///< the block's polygon edge that starts at this vertex index
};

struct FractureSegment {
  int node_a = -1, node_b = -1;
  int fracture = -1;    ///< generating fracture (DFN fracture or joint trace), -1 if none
  int joint_set = -1;   ///< joint set / DFN family, -1 if none
  double aperture = 0;  ///< hydraulic aperture at zero normal displacement, e0 (m)
  /// Block faces on the left and right of node_a -> node_b. A segment inside a
  /// block (a dangling fracture end that does not separate rock) has the same
  /// block on both sides and no edges.
  BlockFace left, right;
};

struct FractureGraph {
  std::vector<Vec2> nodes;
  std::vector<FractureSegment> segments;
  /// Named boundaries (e.g. "left", "top", a tunnel's name): the nodes that lie
  /// on them, sorted.
  std::map<std::string, std::vector<int>> boundary_nodes;
  /// Name of each joint set / DFN family (index = FractureSegment::joint_set),
  /// for output and plots; may be empty.
  std::vector<std::string> set_names;

  int n_nodes() const { return static_cast<int>(nodes.size()); }
  int n_segments() const { return static_cast<int>(segments.size()); }
  double length(int segment) const {
    return (nodes[segments[segment].node_b] - nodes[segments[segment].node_a]).norm();
  }
  /// Adds the nodes within `tol` of the sides of the box [lo, hi] to the
  /// boundaries "left", "right", "bottom" and "top" (created even if empty).
  void add_box_sides(const Vec2& lo, const Vec2& hi, double tol);
};

inline constexpr Key<FractureGraph> kFractureGraph{"fracture_graph"};

}  // namespace fissure
