// find_overlapping_pairs (polygon_checks.h).
//
// Criterion: A and B overlap when one of them penetrates the other by more
// than tol, i.e. some point of B (a vertex, a point of an edge, or an interior
// point) lies inside A at a distance > tol from A's boundary, or the same with
// A and B swapped. Touching along edges or at vertices, and gaps or
// penetrations up to tol, are not overlaps.
//
// Broad phase: BoxGrid over bounding boxes shrunk by min(tol/4, half extent);
// a penetration deeper than tol leaves the shrunk boxes overlapping by tol/2,
// while boxes that merely touch (a brick wall) are separated and never reach
// the narrow phase.
//
// Narrow phase, for the part of both polygons inside the intersection of
// their boxes: (1) vertices of one polygon located in the other; (2) every
// edge of one polygon is split where the other's boundary crosses or touches
// it, and the midpoint of each piece is located in the other (this finds
// crossings, and partial overlaps whose boundaries run along each other);
// (3) an interior point of each polygon located in the other (identical
// polygons, containment with coincident boundaries).
#include <algorithm>
#include <memory>
#include <optional>
#include <tuple>
#include <utility>

#include "core/geometry/box_grid.h"
#include "core/geometry/interior_point.h"
#include "core/geometry/polygon_checks.h"
#include "core/geometry/polygon_locator.h"
#include "core/geometry/segment_predicates.h"

namespace fissure {

namespace {

/// Above this many candidate edge pairs, split points are found with a grid.
constexpr std::size_t kGridMinEdgePairs = 1024;

struct SplitPoint {
  int side;  ///< 0: edge of polygon a, 1: edge of polygon b
  int edge;  ///< index into that side's candidate edge list
  double t;  ///< parameter along the edge
  bool operator<(const SplitPoint& o) const {
    return std::tie(side, edge, t) < std::tie(o.side, o.edge, o.t);
  }
};

Box inflated(Box b, double d) {
  b.lo.array() -= d;
  b.hi.array() += d;
  return b;
}

Box intersection(const Box& a, const Box& b) {
  Box r;
  r.lo = a.lo.cwiseMax(b.lo);
  r.hi = a.hi.cwiseMin(b.hi);
  return r;
}

class OverlapTester {
 public:
  OverlapTester(std::span<const Polygon> polygons, std::span<const Box> boxes, double tol)
      : polygons_(polygons),
        boxes_(boxes),
        tol_(tol),
        locators_(polygons.size()),
        interiors_(polygons.size()) {}

  bool overlap(int a, int b) {
    const Box region = intersection(boxes_[a], boxes_[b]);
    const Box near = inflated(region, tol_);
    std::vector<int>& ea = edges_[0];
    std::vector<int>& eb = edges_[1];
    ea.clear();
    eb.clear();
    locator(a).for_each_edge_near(near, [&](int v) { ea.push_back(v); });
    locator(b).for_each_edge_near(near, [&](int v) { eb.push_back(v); });
    return vertex_inside(b, eb, a, region) || vertex_inside(a, ea, b, region) ||
           piece_inside(a, b) || interior_inside(b, a) || interior_inside(a, b);
  }

 private:
  const PolygonLocator& locator(int i) {
    if (!locators_[i]) locators_[i] = std::make_unique<PolygonLocator>(polygons_[i]);
    return *locators_[i];
  }

  Vec2 start(int side_polygon, int v) const { return polygons_[side_polygon].vertices[v]; }
  Vec2 end(int side_polygon, int v) const {
    const Polygon& p = polygons_[side_polygon];
    return p.vertices[p.next(v)];
  }

  /// A vertex of polygon `b` (edge starts in `eb`) strictly inside `a`.
  bool vertex_inside(int b, const std::vector<int>& eb, int a, const Box& region) {
    for (int v : eb) {
      const Vec2& p = polygons_[b].vertices[v];
      if (!region.overlaps(Box{p, p})) continue;
      if (locator(a).locate(p, tol_) > 0) return true;
    }
    return false;
  }

  bool interior_inside(int b, int a) {
    if (!interiors_[b]) interiors_[b] = interior_point(polygons_[b]);
    return interiors_[b]->depth > 0 && locator(a).locate(interiors_[b]->point, tol_) > 0;
  }

  /// Records where edge ea[i] of `a` and edge eb[j] of `b` cross or touch.
  void split_pair(int a, int b, int i, int j) {
    const int u = edges_[0][i], v = edges_[1][j];
    const Vec2 p0 = start(a, u), p1 = end(a, u), q0 = start(b, v), q1 = end(b, v);
    // Cheap rejection: edge boxes farther apart than tol.
    if ((p0.cwiseMax(p1).array() + tol_ < q0.cwiseMin(q1).array()).any() ||
        (q0.cwiseMax(q1).array() + tol_ < p0.cwiseMin(p1).array()).any())
      return;
    if (segments_cross(p0, p1, q0, q1, 0)) {
      splits_.push_back({0, i, crossing_parameter(p0, p1, q0, q1)});
      splits_.push_back({1, j, crossing_parameter(q0, q1, p0, p1)});
    }
    for (const Vec2& q : {q0, q1})
      if (point_segment_distance(q, p0, p1) <= tol_)
        splits_.push_back({0, i, closest_parameter(q, p0, p1)});
    for (const Vec2& p : {p0, p1})
      if (point_segment_distance(p, q0, q1) <= tol_)
        splits_.push_back({1, j, closest_parameter(p, q0, q1)});
  }

  void find_splits(int a, int b) {
    const std::vector<int>& ea = edges_[0];
    const std::vector<int>& eb = edges_[1];
    if (ea.size() * eb.size() <= kGridMinEdgePairs) {
      for (std::size_t i = 0; i < ea.size(); ++i)
        for (std::size_t j = 0; j < eb.size(); ++j)
          split_pair(a, b, static_cast<int>(i), static_cast<int>(j));
      return;
    }
    std::vector<Box> boxes;
    for (int side = 0; side < 2; ++side) {
      const int poly = side == 0 ? a : b;
      for (int v : edges_[side]) {
        Box box;
        box.extend(start(poly, v));
        box.extend(end(poly, v));
        boxes.push_back(inflated(box, tol_));
      }
    }
    const int na = static_cast<int>(ea.size());
    BoxGrid grid;
    grid.build(boxes);
    grid.for_each_pair([&](int i, int j) {
      if (i < na && j >= na) split_pair(a, b, i, j - na);
    });
  }

  /// Splits every candidate edge of each polygon at the other's boundary and
  /// locates the midpoints of the pieces in the other polygon.
  bool piece_inside(int a, int b) {
    splits_.clear();
    for (int side = 0; side < 2; ++side)
      for (int i = 0; i < static_cast<int>(edges_[side].size()); ++i) {
        splits_.push_back({side, i, 0.0});
        splits_.push_back({side, i, 1.0});
      }
    find_splits(a, b);
    std::sort(splits_.begin(), splits_.end());
    for (std::size_t k = 0; k + 1 < splits_.size(); ++k) {
      const SplitPoint &s = splits_[k], &n = splits_[k + 1];
      if (s.side != n.side || s.edge != n.edge || n.t <= s.t) continue;
      const int own = s.side == 0 ? a : b, other = s.side == 0 ? b : a;
      const int v = edges_[s.side][s.edge];
      const Vec2 p0 = start(own, v), p1 = end(own, v);
      const Vec2 mid = p0 + 0.5 * (s.t + n.t) * (p1 - p0);
      if (locator(other).locate(mid, tol_) > 0) return true;
    }
    return false;
  }

  std::span<const Polygon> polygons_;
  std::span<const Box> boxes_;
  double tol_;
  std::vector<std::unique_ptr<PolygonLocator>> locators_;
  std::vector<std::optional<InteriorPoint>> interiors_;
  std::vector<int> edges_[2];  ///< candidate edges (start vertices) of a and b
  std::vector<SplitPoint> splits_;
};

/// Usable for overlap tests: well-formed loops, >= 3 vertices, all finite.
bool usable(const Polygon& p) {
  return p.n_vertices() >= 3 && !p.loop_offsets.empty() && p.loop_offsets.front() == 0 &&
         p.loop_offsets.back() == p.n_vertices() &&
         std::all_of(p.vertices.begin(), p.vertices.end(),
                     [](const Vec2& v) { return v.allFinite(); });
}

}  // namespace

std::vector<std::pair<int, int>> find_overlapping_pairs(std::span<const Polygon> polygons,
                                                        double tolerance, std::size_t max_pairs) {
  const double tol = std::max(tolerance, 0.0);
  std::vector<Box> boxes(polygons.size());
  std::vector<Box> shrunk;
  std::vector<int> ids;
  for (int i = 0; i < static_cast<int>(polygons.size()); ++i) {
    if (!usable(polygons[i])) continue;
    boxes[i] = bounding_box(polygons[i]);
    Box s = boxes[i];
    const Vec2 d = (0.5 * s.size()).cwiseMin(Vec2::Constant(0.25 * tol));
    s.lo += d;
    s.hi -= d;
    shrunk.push_back(s);
    ids.push_back(i);
  }

  BoxGrid grid;
  grid.build(shrunk);
  OverlapTester tester(polygons, boxes, tol);
  std::vector<std::pair<int, int>> pairs;
  grid.for_each_pair([&](int i, int j) {
    if (tester.overlap(ids[i], ids[j])) pairs.emplace_back(ids[i], ids[j]);
    return pairs.size() >= max_pairs;
  });
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace fissure
