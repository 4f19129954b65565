#include "core/geometry/polygon_locator.h"

#include "core/geometry/polygon_checks.h"  // locate_point
#include "core/geometry/segment_predicates.h"

namespace fissure {

namespace {

/// Below this many edges a plain loop beats building and querying a grid.
constexpr std::size_t kGridMinEdges = 32;

/// The location rule (PolygonLocator::locate), over the edges that
/// `for_each_edge_near(box, f)` gives: every edge whose box overlaps `box`.
template <class ForEachEdgeNear>
int locate_among(const Polygon& polygon, const Box& bounds, const Vec2& p, double tol,
                 ForEachEdgeNear&& for_each_edge_near) {
  if (bounds.empty() || !p.allFinite()) return -1;
  const Vec2 pad(tol, tol);
  if ((p.array() < (bounds.lo - pad).array()).any() ||
      (p.array() > (bounds.hi + pad).array()).any())
    return -1;
  const std::vector<Vec2>& vertices = polygon.vertices;

  // On the boundary: any edge within tol.
  Box near;
  near.extend(p - pad);
  near.extend(p + pad);
  bool on_boundary = false;
  for_each_edge_near(near, [&](int v) {
    if (!on_boundary)
      on_boundary = point_segment_distance(p, vertices[v], vertices[polygon.next(v)]) <= tol;
  });
  if (on_boundary) return 0;

  // Even-odd count of edges crossing the ray from p towards +x. Every edge is
  // farther than tol from p, so the orientation sign is reliable. Half-open
  // rule in y (an edge counts when exactly one end is above p) so that a ray
  // through a vertex counts it once.
  Box ray;
  ray.extend(p);
  ray.extend(Vec2(bounds.hi.x(), p.y()));
  bool inside = false;
  for_each_edge_near(ray, [&](int v) {
    const Vec2& a = vertices[v];
    const Vec2& b = vertices[polygon.next(v)];
    if ((a.y() > p.y()) == (b.y() > p.y())) return;
    const double o = orient(a, b, p);
    if (b.y() > a.y() ? o > 0 : o < 0) inside = !inside;
  });
  return inside ? 1 : -1;
}

/// Calls f(v, box) for every edge v -> next(v) of all loops with finite ends.
template <class F>
void for_each_finite_edge(const Polygon& polygon, int first_loop, int end_loop, F&& f) {
  for (int k = first_loop; k < end_loop; ++k) {
    for (int v = polygon.loop_offsets[k]; v < polygon.loop_offsets[k + 1]; ++v) {
      const Vec2& a = polygon.vertices[v];
      const Vec2& b = polygon.vertices[polygon.next(v)];
      if (!a.allFinite() || !b.allFinite()) continue;
      Box box;
      box.extend(a);
      box.extend(b);
      f(v, box);
    }
  }
}

}  // namespace

PolygonLocator::PolygonLocator(const Polygon& polygon, int first_loop, int end_loop)
    : polygon_(&polygon) {
  if (end_loop < 0) end_loop = polygon.n_loops();
  for_each_finite_edge(polygon, first_loop, end_loop, [this](int v, const Box& box) {
    edges_.push_back(v);
    boxes_.push_back(box);
    bounds_.extend(box);
  });
  use_grid_ = edges_.size() >= kGridMinEdges;
  if (use_grid_) grid_.build(boxes_);
}

int PolygonLocator::locate(const Vec2& p, double tol) const {
  return locate_among(*polygon_, bounds_, p, tol,
                      [this](const Box& query, auto&& f) { for_each_edge_near(query, f); });
}

int locate_point(const Polygon& polygon, const Vec2& p, double tolerance) {
  if (polygon.n_vertices() >= static_cast<int>(kGridMinEdges))
    return PolygonLocator(polygon).locate(p, tolerance);
  // A small polygon, queried once (contact detection asks for each
  // penetrating vertex): the same rule over its edges as they come, without
  // building an index (a locator's allocations were 3 % of a shaken cliff's run).
  Box bounds;
  for_each_finite_edge(polygon, 0, polygon.n_loops(),
                       [&](int, const Box& box) { bounds.extend(box); });
  return locate_among(polygon, bounds, p, tolerance, [&](const Box& query, auto&& f) {
    for_each_finite_edge(polygon, 0, polygon.n_loops(), [&](int v, const Box& box) {
      if (box.overlaps(query)) f(v);
    });
  });
}

}  // namespace fissure
