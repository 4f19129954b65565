// A polygon with holes stored as flat vertex loops: loop 0 is the outer
// boundary (counter-clockwise), further loops are holes (clockwise). With this
// orientation every boundary integral is a plain sum over all loops, so
// concave blocks and blocks with holes need no special case (theory.md 1.2).
#pragma once

#include <algorithm>
#include <span>
#include <vector>

#include "core/geometry/vec2.h"

namespace fissure {

struct Polygon {
  std::vector<Vec2> vertices;
  /// Loop k holds vertices [loop_offsets[k], loop_offsets[k+1]); the last entry
  /// equals vertices.size().
  std::vector<int> loop_offsets{0};

  Polygon() = default;
  /// Single outer loop (no holes).
  explicit Polygon(std::vector<Vec2> outer);

  int n_vertices() const { return static_cast<int>(vertices.size()); }
  int n_loops() const { return static_cast<int>(loop_offsets.size()) - 1; }
  std::span<const Vec2> loop(int k) const;
  void add_loop(std::span<const Vec2> loop);

  /// Index of the loop that contains vertex v. Inline, with a shortcut for
  /// the usual single loop: contact detection and the contact springs walk
  /// the loops (next, prev) for every contact in every step.
  int loop_of(int v) const {
    if (loop_offsets.size() == 2) return 0;
    const auto it = std::upper_bound(loop_offsets.begin(), loop_offsets.end(), v);
    return static_cast<int>(it - loop_offsets.begin()) - 1;
  }
  /// Next / previous vertex of v along its own loop (edge v -> next(v)).
  int next(int v) const {
    const int k = loop_of(v);
    return v + 1 < loop_offsets[k + 1] ? v + 1 : loop_offsets[k];
  }
  int prev(int v) const {
    const int k = loop_of(v);
    return v > loop_offsets[k] ? v - 1 : loop_offsets[k + 1] - 1;
  }
};

/// Area moments S, Sx, Sy, Sxx, Syy, Sxy of a polygon (Shi's simplex
/// integration, theory.md 1.2), taken about `origin`.
struct AreaMoments {
  double S = 0, Sx = 0, Sy = 0, Sxx = 0, Syy = 0, Sxy = 0;
};
AreaMoments area_moments(const Polygon& polygon, const Vec2& origin);

/// Area, centroid and the central second moments (about the centroid).
struct SectionProperties {
  double area = 0;
  Vec2 centroid = Vec2::Zero();
  double Ixx = 0, Iyy = 0, Ixy = 0;  ///< integrals of X^2, Y^2, XY about the centroid
};
/// Moments are accumulated about the first vertex, which avoids cancellation
/// for blocks far from the global origin.
SectionProperties section_properties(const Polygon& polygon);

/// Signed area of one closed loop (> 0 counter-clockwise).
double signed_area(std::span<const Vec2> loop);

/// Axis-aligned bounding box.
struct Box {
  Vec2 lo{1e300, 1e300};
  Vec2 hi{-1e300, -1e300};
  void extend(const Vec2& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  void extend(const Box& b) {
    lo = lo.cwiseMin(b.lo);
    hi = hi.cwiseMax(b.hi);
  }
  bool empty() const { return lo.x() > hi.x(); }
  bool overlaps(const Box& b) const {
    return lo.x() <= b.hi.x() && b.lo.x() <= hi.x() && lo.y() <= b.hi.y() && b.lo.y() <= hi.y();
  }
  Vec2 size() const { return hi - lo; }
};
Box bounding_box(const Polygon& polygon);

}  // namespace fissure
