#include "core/geometry/loop_checks.h"

#include <cmath>

#include <fmt/format.h>

#include "core/geometry/segment_predicates.h"

namespace fissure {

namespace {

std::string point_text(const Vec2& p) {
  return fmt::format("({}, {})", p.x(), p.y());
}

/// Merges runs of coincident consecutive vertices (including last-first).
std::vector<int> merge_duplicates(const Polygon& polygon, int k, double tol) {
  const std::vector<Vec2>& vs = polygon.vertices;
  std::vector<int> kept;
  for (int v = polygon.loop_offsets[k]; v < polygon.loop_offsets[k + 1]; ++v)
    if (kept.empty() || !coincide(vs[v], vs[kept.back()], tol)) kept.push_back(v);
  while (kept.size() > 1 && coincide(vs[kept.back()], vs[kept.front()], tol)) kept.pop_back();
  return kept;
}

void check_vertices(const Polygon& polygon, int k, double tol, CleanLoop& loop,
                    std::vector<PolygonProblem>& problems) {
  const int first = polygon.loop_offsets[k], n = polygon.loop_offsets[k + 1] - first;
  const std::vector<Vec2>& vs = polygon.vertices;
  if (n < 3)
    problems.push_back(
        {k, -1, fmt::format("loop {} has {} vertices; at least 3 are needed", k, n)});
  for (int i = 0; i < n; ++i) {
    if (vs[first + i].allFinite()) continue;
    loop.finite = false;
    problems.push_back({k, i,
                        fmt::format("loop {}: vertex {} has non-finite coordinates {}", k, i,
                                    point_text(vs[first + i]))});
  }
  if (!loop.finite || n < 2) return;
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    if (n == 2 && j == 0) break;  // a two-vertex loop has one distinct pair
    const Vec2 &a = vs[first + i], &b = vs[first + j];
    if (!coincide(a, b, tol)) continue;
    problems.push_back(
        {k, i,
         fmt::format("loop {}: consecutive vertices {} {} and {} {} coincide (distance {} < "
                     "tolerance {})",
                     k, i, point_text(a), j, point_text(b), (b - a).norm(), tol)});
  }
}

void check_area(int k, double tol, CleanLoop& loop, std::span<const Vec2> vs,
                std::vector<PolygonProblem>& problems) {
  loop.area = signed_area(vs);
  for (std::size_t i = 0; i < vs.size(); ++i)
    loop.perimeter += (vs[(i + 1) % vs.size()] - vs[i]).norm();
  if (std::abs(loop.area) <= tol * loop.perimeter)
    problems.push_back({k, -1,
                        fmt::format("loop {} has zero area: |area| = {} <= tolerance x perimeter "
                                    "= {} x {}",
                                    k, std::abs(loop.area), tol, loop.perimeter)});
}

/// Adjacent edges u-v, v-w that run back over each other (a spike of zero
/// width): w within tol of edge u-v, or u within tol of edge v-w.
void check_folds(const Polygon& polygon, int k, double tol, const CleanLoop& loop,
                 std::vector<PolygonProblem>& problems) {
  const std::vector<Vec2>& vs = polygon.vertices;
  const int first = polygon.loop_offsets[k];
  const std::size_t n = loop.vertices.size();
  for (std::size_t m = 0; m < n; ++m) {
    const int u = loop.vertices[(m + n - 1) % n], v = loop.vertices[m],
              w = loop.vertices[(m + 1) % n];
    if (point_segment_distance(vs[w], vs[u], vs[v]) > tol &&
        point_segment_distance(vs[u], vs[v], vs[w]) > tol)
      continue;
    problems.push_back(
        {k, v - first,
         fmt::format("loop {}: edges {}-{} and {}-{} fold back on each other at "
                     "vertex {} {}",
                     k, u - first, v - first, v - first, w - first, v - first, point_text(vs[v]))});
  }
}

}  // namespace

bool coincide(const Vec2& a, const Vec2& b, double tol) {
  const double d = (b - a).norm();
  return d < tol || d == 0;
}

std::vector<CleanLoop> check_loops(const Polygon& polygon, double tol,
                                   std::vector<PolygonProblem>& problems) {
  const int n_loops = polygon.n_loops();
  std::vector<CleanLoop> loops(n_loops);
  for (int k = 0; k < n_loops; ++k) {
    CleanLoop& loop = loops[k];
    check_vertices(polygon, k, tol, loop, problems);
    if (!loop.finite || polygon.loop(k).size() < 3) continue;
    check_area(k, tol, loop, polygon.loop(k), problems);
    loop.vertices = merge_duplicates(polygon, k, tol);
    loop.usable = loop.vertices.size() >= 3;
    if (loop.usable) check_folds(polygon, k, tol, loop, problems);
  }

  // Net area: the outer loop minus the holes (orientation-independent).
  if (n_loops > 1 && loops[0].finite && polygon.loop(0).size() >= 3) {
    double holes = 0, perimeter = loops[0].perimeter;
    for (int k = 1; k < n_loops; ++k) {
      holes += std::abs(loops[k].area);
      perimeter += loops[k].perimeter;
    }
    const double net = std::abs(loops[0].area) - holes;
    if (net <= tol * perimeter)
      problems.push_back({0, -1,
                          fmt::format("polygon has zero net area: outer area {} minus hole area "
                                      "{} = {} <= tolerance x perimeter = {} x {}",
                                      std::abs(loops[0].area), holes, net, tol, perimeter)});
  }
  return loops;
}

}  // namespace fissure
