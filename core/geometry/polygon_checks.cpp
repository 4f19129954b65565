// check_polygon (orchestration; the checks live in loop_checks.cpp and
// loop_crossings.cpp) and orient_loops. locate_point is in
// polygon_locator.cpp, find_overlapping_pairs in polygon_overlap.cpp.
#include "core/geometry/polygon_checks.h"

#include <algorithm>

#include <fmt/format.h>

#include "core/geometry/loop_checks.h"

namespace fissure {

namespace {

bool offsets_well_formed(const Polygon& polygon) {
  const std::vector<int>& o = polygon.loop_offsets;
  return !o.empty() && o.front() == 0 && o.back() == polygon.n_vertices() &&
         std::is_sorted(o.begin(), o.end());
}

}  // namespace

std::vector<PolygonProblem> check_polygon(const Polygon& polygon, double tolerance) {
  std::vector<PolygonProblem> problems;
  if (!offsets_well_formed(polygon)) {
    problems.push_back({0, -1,
                        fmt::format("malformed loop offsets [{}] for {} vertices",
                                    fmt::join(polygon.loop_offsets, ", "), polygon.n_vertices())});
    return problems;
  }
  if (polygon.n_loops() == 0) {
    problems.emplace_back().what = "polygon has no loops";  // loop 0, no vertex
    return problems;
  }
  if (!(tolerance >= 0)) {
    problems.push_back({0, -1, fmt::format("tolerance {} is not a length >= 0", tolerance)});
    return problems;
  }
  const std::vector<CleanLoop> loops = check_loops(polygon, tolerance, problems);
  check_crossings(polygon, loops, tolerance, problems);
  return problems;
}

void orient_loops(Polygon& polygon) {
  for (int k = 0; k < polygon.n_loops(); ++k) {
    const double area = signed_area(polygon.loop(k));
    if (k == 0 ? area < 0 : area > 0) {
      // Keep the first vertex first; reverse the rest.
      auto first = polygon.vertices.begin() + polygon.loop_offsets[k];
      auto last = polygon.vertices.begin() + polygon.loop_offsets[k + 1];
      if (last - first > 2) std::reverse(first + 1, last);
    }
  }
}

}  // namespace fissure
