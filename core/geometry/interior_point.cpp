#include "core/geometry/interior_point.h"

#include <algorithm>
#include <numeric>
#include <utility>
#include <vector>

#include "core/geometry/segment_predicates.h"

namespace fissure {

namespace {

/// Number of bands tried on large polygons (all bands on small ones).
constexpr std::size_t kMaxBands = 16;

/// Deepest interval midpoint on the line y = y_mid inside the band of half
/// height `half_gap` (no vertex lies strictly inside the band).
InteriorPoint best_on_line(const Polygon& polygon, double y_mid, double half_gap,
                           std::vector<std::pair<double, int>>& crossings) {
  const std::vector<Vec2>& vs = polygon.vertices;
  crossings.clear();
  for (int v = 0; v < polygon.n_vertices(); ++v) {
    const Vec2& a = vs[v];
    const Vec2& b = vs[polygon.next(v)];
    if (!a.allFinite() || !b.allFinite()) continue;
    if ((a.y() > y_mid) == (b.y() > y_mid)) continue;
    const double x = a.x() + (y_mid - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
    crossings.emplace_back(x, v);
  }
  std::sort(crossings.begin(), crossings.end());
  InteriorPoint best;
  for (std::size_t k = 0; k + 1 < crossings.size(); k += 2) {
    const Vec2 mid(0.5 * (crossings[k].first + crossings[k + 1].first), y_mid);
    const int e0 = crossings[k].second, e1 = crossings[k + 1].second;
    // Any boundary point inside the band lies beyond one of the two bounding
    // edges (they span the band), and any point outside is half_gap away.
    const double depth =
        std::min({half_gap, point_segment_distance(mid, vs[e0], vs[polygon.next(e0)]),
                  point_segment_distance(mid, vs[e1], vs[polygon.next(e1)])});
    if (depth > best.depth) best = {mid, depth};
  }
  return best;
}

}  // namespace

InteriorPoint interior_point(const Polygon& polygon) {
  std::vector<double> ys;
  ys.reserve(polygon.vertices.size());
  for (const Vec2& p : polygon.vertices)
    if (p.allFinite()) ys.push_back(p.y());
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  if (ys.size() < 2) return {};

  std::vector<std::size_t> bands(ys.size() - 1);
  std::iota(bands.begin(), bands.end(), std::size_t{0});
  const auto wider = [&](std::size_t a, std::size_t b) {
    return ys[a + 1] - ys[a] > ys[b + 1] - ys[b];
  };
  if (bands.size() > kMaxBands) {
    std::partial_sort(bands.begin(), bands.begin() + kMaxBands, bands.end(), wider);
    bands.resize(kMaxBands);
  }

  InteriorPoint best;
  std::vector<std::pair<double, int>> crossings;
  for (std::size_t g : bands) {
    const double y_mid = 0.5 * (ys[g] + ys[g + 1]);
    const InteriorPoint candidate =
        best_on_line(polygon, y_mid, 0.5 * (ys[g + 1] - ys[g]), crossings);
    if (candidate.depth > best.depth) best = candidate;
  }
  return best;
}

}  // namespace fissure
