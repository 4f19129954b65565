#include "core/geometry/polygon.h"

namespace fissure {

Polygon::Polygon(std::vector<Vec2> outer)
    : vertices(std::move(outer)), loop_offsets{0, static_cast<int>(vertices.size())} {}

std::span<const Vec2> Polygon::loop(int k) const {
  return std::span<const Vec2>(vertices).subspan(loop_offsets[k],
                                                 loop_offsets[k + 1] - loop_offsets[k]);
}

void Polygon::add_loop(std::span<const Vec2> loop) {
  vertices.insert(vertices.end(), loop.begin(), loop.end());
  loop_offsets.push_back(static_cast<int>(vertices.size()));
}

AreaMoments area_moments(const Polygon& polygon, const Vec2& origin) {
  AreaMoments m;
  const int n = polygon.n_vertices();
  for (int a = 0; a < n; ++a) {
    const Vec2 p = polygon.vertices[a] - origin;
    const Vec2 q = polygon.vertices[polygon.next(a)] - origin;
    const double c = p.x() * q.y() - q.x() * p.y();
    m.S += c;
    m.Sx += c * (p.x() + q.x());
    m.Sy += c * (p.y() + q.y());
    m.Sxx += c * (p.x() * p.x() + p.x() * q.x() + q.x() * q.x());
    m.Syy += c * (p.y() * p.y() + p.y() * q.y() + q.y() * q.y());
    m.Sxy += c * (2 * p.x() * p.y() + p.x() * q.y() + q.x() * p.y() + 2 * q.x() * q.y());
  }
  m.S /= 2;
  m.Sx /= 6;
  m.Sy /= 6;
  m.Sxx /= 12;
  m.Syy /= 12;
  m.Sxy /= 24;
  return m;
}

SectionProperties section_properties(const Polygon& polygon) {
  SectionProperties s;
  if (polygon.vertices.empty()) return s;
  const Vec2 origin = polygon.vertices.front();
  const AreaMoments m = area_moments(polygon, origin);
  s.area = m.S;
  const double xc = m.Sx / m.S, yc = m.Sy / m.S;
  s.centroid = origin + Vec2(xc, yc);
  s.Ixx = m.Sxx - m.Sx * xc;
  s.Iyy = m.Syy - m.Sy * yc;
  s.Ixy = m.Sxy - m.Sx * yc;
  return s;
}

double signed_area(std::span<const Vec2> loop) {
  // Relative to the first vertex: no cancellation far from the origin.
  double a = 0;
  const std::size_t n = loop.size();
  for (std::size_t i = 1; i + 1 < n; ++i) a += cross(loop[i] - loop[0], loop[i + 1] - loop[0]);
  return a / 2;
}

Box bounding_box(const Polygon& polygon) {
  Box b;
  for (const Vec2& p : polygon.vertices) b.extend(p);
  return b;
}

}  // namespace fissure
