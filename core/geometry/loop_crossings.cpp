// Edge-pair checks of check_polygon: self-intersection within a loop, holes
// crossing or touching the outer loop or each other, and the placement of
// holes that touch nothing (outside the outer loop, inside another hole).
#include <algorithm>
#include <memory>
#include <set>
#include <utility>

#include <fmt/format.h>

#include "core/geometry/box_grid.h"
#include "core/geometry/loop_checks.h"
#include "core/geometry/polygon_locator.h"
#include "core/geometry/segment_predicates.h"

namespace fissure {

namespace {

/// A badly broken polygon can have O(n^2) crossing pairs; list this many and
/// count the rest.
constexpr std::size_t kMaxCrossingReports = 100;

struct Edge {
  int a, b;  ///< global vertex indices
  int loop;
};

using LoopPairs = std::set<std::pair<int, int>>;

std::string point_text(const Vec2& p) {
  return fmt::format("({}, {})", p.x(), p.y());
}

std::vector<Edge> usable_edges(const std::vector<CleanLoop>& loops) {
  std::vector<Edge> edges;
  for (int k = 0; k < static_cast<int>(loops.size()); ++k) {
    if (!loops[k].usable) continue;
    const std::vector<int>& vs = loops[k].vertices;
    for (std::size_t m = 0; m < vs.size(); ++m)
      edges.push_back({vs[m], vs[(m + 1) % vs.size()], k});
  }
  return edges;
}

PolygonProblem crossing_problem(const Polygon& polygon, const Edge& e, const Edge& f) {
  const std::vector<Vec2>& vs = polygon.vertices;
  const Vec2 &a = vs[e.a], &b = vs[e.b], &c = vs[f.a], &d = vs[f.b];
  const char* verb = segments_cross(a, b, c, d, 0) ? "intersect" : "touch";
  const std::string at = point_text(meeting_point(a, b, c, d));
  const int oe = polygon.loop_offsets[e.loop], of = polygon.loop_offsets[f.loop];
  const int ea = e.a - oe, eb = e.b - oe, fa = f.a - of, fb = f.b - of;
  if (e.loop == f.loop)
    return {
        e.loop, ea,
        fmt::format("loop {}: edges {}-{} and {}-{} {} at {}", e.loop, ea, eb, fa, fb, verb, at)};
  if (e.loop == 0)
    return {f.loop, fa,
            fmt::format("hole {} and the outer loop {}: edge {}-{} of the outer loop and edge "
                        "{}-{} of hole {} at {}",
                        f.loop, verb, ea, eb, fa, fb, f.loop, at)};
  return {f.loop, fa,
          fmt::format("holes {} and {} {}: edge {}-{} of hole {} and edge {}-{} of hole {} at {}",
                      e.loop, f.loop, verb, ea, eb, e.loop, fa, fb, f.loop, at)};
}

/// Non-adjacent edges closer than tol. Adjacent edges (sharing a vertex) can
/// only meet again by folding back, which check_loops reports. Returns the
/// pairs of loops (k <= m) that meet.
LoopPairs check_edge_pairs(const Polygon& polygon, const std::vector<CleanLoop>& loops, double tol,
                           std::vector<PolygonProblem>& problems) {
  const std::vector<Vec2>& vs = polygon.vertices;
  const std::vector<Edge> edges = usable_edges(loops);
  std::vector<Box> boxes(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) {
    boxes[i].extend(vs[edges[i].a]);
    boxes[i].extend(vs[edges[i].b]);
    boxes[i].lo.array() -= tol;
    boxes[i].hi.array() += tol;
  }
  BoxGrid grid;
  grid.build(boxes);
  // Collected up to a bound: a jagged loop of n vertices can have ~n^2 / 2
  // meeting pairs (5e7 at 10,000 vertices), and one is already an error.
  constexpr std::size_t kMostHits = 100000;
  std::vector<std::pair<int, int>> hits;
  grid.for_each_pair([&](int i, int j) {
    const Edge &e = edges[i], &f = edges[j];
    if (e.loop == f.loop && (e.a == f.b || e.b == f.a)) return false;
    if (segment_distance(vs[e.a], vs[e.b], vs[f.a], vs[f.b]) <= tol) hits.emplace_back(i, j);
    return hits.size() >= kMostHits;
  });
  const bool bounded = hits.size() >= kMostHits;
  std::sort(hits.begin(), hits.end());  // report in loop and vertex order

  // Several edge pairs meeting at one point (edges ending at a vertex that
  // touches another edge, two holes sharing a corner) are reported once.
  struct Reported {
    int loop_e, loop_f;
    Vec2 at;
  };
  std::vector<Reported> reported;
  std::size_t n_unlisted = 0;
  LoopPairs meeting;
  for (const auto& [i, j] : hits) {
    const Edge &e = edges[i], &f = edges[j];
    meeting.emplace(e.loop, f.loop);
    if (reported.size() == kMaxCrossingReports) {  // O(1) per pair from here on
      ++n_unlisted;
      continue;
    }
    const Vec2 at = meeting_point(vs[e.a], vs[e.b], vs[f.a], vs[f.b]);
    const bool repeated = std::any_of(reported.begin(), reported.end(), [&](const Reported& r) {
      return r.loop_e == e.loop && r.loop_f == f.loop && (r.at - at).norm() <= tol;
    });
    if (repeated) continue;
    reported.push_back({e.loop, f.loop, at});
    problems.push_back(crossing_problem(polygon, e, f));
  }
  if (n_unlisted > 0)
    problems.push_back(
        {0, -1,
         fmt::format("{}{} further intersecting or touching edge pairs are not listed",
                     bounded ? "at least " : "", n_unlisted)});
  return meeting;
}

/// Holes that meet no other loop are either strictly inside the outer loop
/// or wrong: outside it, or inside another hole (then overlapping it).
void check_hole_placement(const Polygon& polygon, const std::vector<CleanLoop>& loops,
                          const LoopPairs& meeting, double tol,
                          std::vector<PolygonProblem>& problems) {
  const int n_loops = static_cast<int>(loops.size());
  const std::vector<Vec2>& vs = polygon.vertices;
  auto first_vertex = [&](int k) { return loops[k].vertices.front(); };
  auto local = [&](int v) { return v - polygon.loop_offsets[polygon.loop_of(v)]; };

  if (loops[0].usable) {
    const PolygonLocator outer(polygon, 0, 1);
    for (int k = 1; k < n_loops; ++k) {
      if (!loops[k].usable || meeting.count({0, k})) continue;
      const int v = first_vertex(k);
      if (outer.locate(vs[v], tol) < 0)
        problems.push_back({k, local(v),
                            fmt::format("hole {} lies outside the outer loop (its vertex {} at {})",
                                        k, local(v), point_text(vs[v]))});
    }
  }

  std::vector<int> holes;
  std::vector<Box> boxes;
  for (int k = 1; k < n_loops; ++k) {
    if (!loops[k].usable) continue;
    holes.push_back(k);
    Box box;
    for (int v : loops[k].vertices) box.extend(vs[v]);
    boxes.push_back(box);
  }
  std::vector<std::unique_ptr<PolygonLocator>> locators(n_loops);
  auto inside_hole = [&](int outer_hole, int inner_hole) {
    auto& locator = locators[outer_hole];
    if (!locator) locator = std::make_unique<PolygonLocator>(polygon, outer_hole, outer_hole + 1);
    return locator->locate(vs[first_vertex(inner_hole)], tol) > 0;
  };
  std::vector<std::pair<int, int>> nested;  // (outer hole, inner hole)
  BoxGrid grid;
  grid.build(boxes);
  grid.for_each_pair([&](int i, int j) {
    const int hi = holes[i], hj = holes[j];
    if (meeting.count({hi, hj})) return;
    if (inside_hole(hi, hj))
      nested.emplace_back(hi, hj);
    else if (inside_hole(hj, hi))
      nested.emplace_back(hj, hi);
  });
  std::sort(nested.begin(), nested.end());
  for (const auto& [outer_hole, inner_hole] : nested)
    problems.push_back({inner_hole, -1,
                        fmt::format("hole {} lies inside hole {} (holes must not overlap)",
                                    inner_hole, outer_hole)});
}

}  // namespace

void check_crossings(const Polygon& polygon, const std::vector<CleanLoop>& loops, double tol,
                     std::vector<PolygonProblem>& problems) {
  if (loops.empty()) return;
  const LoopPairs meeting = check_edge_pairs(polygon, loops, tol, problems);
  check_hole_placement(polygon, loops, meeting, tol, problems);
}

}  // namespace fissure
