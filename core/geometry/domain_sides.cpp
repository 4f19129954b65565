#include "core/geometry/domain_sides.h"

#include <algorithm>
#include <cmath>

namespace fissure {

std::vector<std::vector<std::string>> domain_side_names(std::span<const Vec2> loop) {
  const int n = static_cast<int>(loop.size());
  std::vector<std::vector<std::string>> names(n);
  if (n < 3) return names;
  double x0 = loop[0].x(), x1 = x0, y0 = loop[0].y(), y1 = y0;
  for (const Vec2& p : loop) {
    x0 = std::min(x0, p.x());
    x1 = std::max(x1, p.x());
    y0 = std::min(y0, p.y());
    y1 = std::max(y1, p.y());
  }
  for (int edge = 0; edge < n; ++edge) {
    const Vec2& a = loop[edge];
    const Vec2& b = loop[(edge + 1) % n];
    if (a.x() == b.x() && a.y() != b.y()) {
      if (a.x() == x0) names[edge].emplace_back("left");
      if (a.x() == x1) names[edge].emplace_back("right");
    }
    if (a.y() == b.y() && a.x() != b.x()) {
      if (a.y() == y0) names[edge].emplace_back("bottom");
      if (a.y() == y1) names[edge].emplace_back("top");
    }
  }
  return names;
}

std::vector<std::string> domain_sides(std::span<const Vec2> loop) {
  std::vector<std::string> found;
  for (std::vector<std::string>& edge : domain_side_names(loop))
    for (std::string& name : edge) found.push_back(std::move(name));
  std::vector<std::string> sides;
  for (const char* s : {"left", "right", "bottom", "top"})
    if (std::find(found.begin(), found.end(), s) != found.end()) sides.emplace_back(s);
  return sides;
}

std::vector<Vec2> regular_polygon(const Vec2& centre, double radius, int n) {
  std::vector<Vec2> p;
  p.reserve(n);
  const double pi = 3.14159265358979323846;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * pi * k / n;
    p.push_back(centre + radius * Vec2(std::cos(t), std::sin(t)));
  }
  return p;
}

}  // namespace fissure
