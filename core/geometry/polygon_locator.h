// Point location in a polygon with holes, built once for many queries. Edges
// are indexed in a BoxGrid when there are many of them, so a query costs about
// one grid row instead of a pass over every edge. The tolerance rule is the
// one of segment_predicates.h: within tol of an edge means on the boundary.
#pragma once

#include <vector>

#include "core/geometry/box_grid.h"
#include "core/geometry/polygon.h"

namespace fissure {

class PolygonLocator {
 public:
  /// Indexes the edges of loops [first_loop, end_loop) of `polygon` (all loops
  /// when end_loop < 0). Edges with a non-finite end are left out. The polygon
  /// must outlive the locator and stay unchanged.
  explicit PolygonLocator(const Polygon& polygon, int first_loop = 0, int end_loop = -1);
  PolygonLocator(const PolygonLocator&) = delete;
  PolygonLocator& operator=(const PolygonLocator&) = delete;
  PolygonLocator(PolygonLocator&&) = default;
  PolygonLocator& operator=(PolygonLocator&&) = default;

  /// +1 inside, 0 within tol of an indexed edge, -1 outside. Inside is the
  /// even-odd rule over the indexed loops, so holes are respected whatever the
  /// orientation of the loops.
  int locate(const Vec2& p, double tol) const;

  /// Calls f(v) for every indexed edge v -> polygon.next(v) whose bounding box
  /// overlaps `query`.
  template <class F>
  void for_each_edge_near(const Box& query, F&& f) const;

  const Box& bounds() const { return bounds_; }

 private:
  const Polygon* polygon_;
  std::vector<int> edges_;  ///< start vertex of each indexed edge
  std::vector<Box> boxes_;  ///< bounding box of each indexed edge
  BoxGrid grid_;            ///< built only when there are many edges
  bool use_grid_ = false;
  Box bounds_;
};

template <class F>
void PolygonLocator::for_each_edge_near(const Box& query, F&& f) const {
  if (use_grid_) {
    grid_.for_each_overlapping(query, [&](int e) { f(edges_[e]); });
    return;
  }
  for (std::size_t e = 0; e < edges_.size(); ++e)
    if (boxes_[e].overlaps(query)) f(edges_[e]);
}

}  // namespace fissure
