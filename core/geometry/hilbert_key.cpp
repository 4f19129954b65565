#include "core/geometry/hilbert_key.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <utility>

namespace fissure {

double hilbert_key(double x, double y, double x_lo, double y_lo, double x_hi, double y_hi) {
  constexpr std::uint32_t kCells = 1u << 16;
  auto cell = [](double v, double lo, double hi) {
    const double s = hi > lo ? (v - lo) / (hi - lo) : 0;
    return static_cast<std::uint32_t>(std::clamp(s, 0.0, 1.0) * (kCells - 1));
  };
  // The classical rotate-and-accumulate walk down the quadrants.
  std::uint32_t cx = cell(x, x_lo, x_hi), cy = cell(y, y_lo, y_hi);
  std::uint64_t d = 0;
  for (std::uint32_t s = kCells / 2; s > 0; s /= 2) {
    const std::uint32_t rx = (cx & s) ? 1 : 0, ry = (cy & s) ? 1 : 0;
    d += static_cast<std::uint64_t>(s) * s * ((3 * rx) ^ ry);
    if (ry == 0) {
      if (rx == 1) {
        cx = kCells - 1 - cx;
        cy = kCells - 1 - cy;
      }
      std::swap(cx, cy);
    }
  }
  return static_cast<double>(d);
}

std::vector<int> hilbert_order(std::span<const Vec2> points, const Vec2& lo, const Vec2& hi) {
  std::vector<double> key(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    key[i] = hilbert_key(points[i].x(), points[i].y(), lo.x(), lo.y(), hi.x(), hi.y());
  std::vector<int> order(points.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&key](int a, int b) { return key[a] < key[b]; });
  return order;
}

}  // namespace fissure
