// The planar subdivision induced by a set of segments (domain and excavation
// edges, fracture traces), as plain arrays: the exact CGAL arrangement
// (segment_arrangement.cpp) exported once, so that everything after it
// (rock classification, merging, blocks, fracture graph) is ordinary code.
//
// Half-edge structure: half-edges h and h ^ 1 are twins (edge h / 2); h runs
// from origin[h] to origin[h ^ 1] and its face lies on its left; next[h] is
// the next half-edge around that face. Outer boundaries of bounded faces run
// counter-clockwise, holes clockwise. A segment that ends inside a face (a
// dangling fracture end) gives an edge with the same face on both sides.
#pragma once

#include <span>
#include <vector>

#include "core/geometry/vec2.h"

namespace fissure {

struct Segment2 {
  Vec2 a = Vec2::Zero(), b = Vec2::Zero();
};

struct PlanarSubdivision {
  /// Exact vertices rounded to doubles, each within 5e-13 x the extent of the
  /// input (or two ulps) of its exact position.
  std::vector<Vec2> vertices;
  std::vector<int> origin, next, face;  ///< per half-edge
  /// Per half-edge: its origin comes before its target in (x, then y) order,
  /// decided exactly. Together with the input segment's own order this says
  /// whether the half-edge runs along the segment or against it.
  std::vector<char> left_to_right;
  /// Per edge: the input segments it lies on (several where they overlap),
  /// increasing: edge e has curves[curve_start[e] .. curve_start[e + 1]).
  std::vector<int> curve_start{0};
  std::vector<int> curves;
  int n_faces = 0;
  int unbounded_face = -1;

  int n_halfedges() const { return static_cast<int>(origin.size()); }
  int n_edges() const { return n_halfedges() / 2; }
  int target(int h) const { return origin[h ^ 1]; }
  std::span<const int> edge_curves(int e) const {
    return {curves.data() + curve_start[e], curves.data() + curve_start[e + 1]};
  }
  double length(int h) const { return (vertices[target(h)] - vertices[origin[h]]).norm(); }
};

/// The arrangement of `segments` (none of zero length), computed exactly
/// (CGAL Arrangement_2, exact predicates and exact constructions, with a
/// sweep line: O((n + k) log n) for n segments and k crossings). Overlapping
/// segments share edges. Throws GeometryError for a zero-length or
/// non-finite segment.
PlanarSubdivision arrange_segments(std::span<const Segment2> segments);

}  // namespace fissure
