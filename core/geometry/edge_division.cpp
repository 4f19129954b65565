#include "core/geometry/edge_division.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fissure {

namespace {

/// Lexicographic order of points: pieces are divided from their smaller end.
bool lexicographic_less(const Vec2& a, const Vec2& b) {
  return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
}

}  // namespace

std::vector<Vec2> divide_edge(const Vec2& a, const Vec2& b, const SizeFunction& size) {
  const bool forward = lexicographic_less(a, b);
  const Vec2 p = forward ? a : b, q = forward ? b : a;
  double h = std::numeric_limits<double>::infinity();
  constexpr int kSamples = 8;
  for (int k = 0; k <= kSamples; ++k) h = std::min(h, size(p + (q - p) * (double(k) / kSamples)));
  const int n = std::max(1, static_cast<int>(std::ceil((q - p).norm() / h - 1e-9)));
  std::vector<Vec2> points;
  for (int k = 1; k < n; ++k) points.push_back(p + (q - p) * (double(k) / n));
  if (!forward) std::reverse(points.begin(), points.end());
  return points;
}

}  // namespace fissure
