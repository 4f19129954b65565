#include "core/geometry/segment_predicates.h"

#include <algorithm>
#include <array>

namespace fissure {

double closest_parameter(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double len2 = d.squaredNorm();
  if (!(len2 > 0)) return 0;
  return std::clamp((p - a).dot(d) / len2, 0.0, 1.0);
}

double point_segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const double t = closest_parameter(p, a, b);
  return (p - (a + t * (b - a))).norm();
}

int side_of_line(const Vec2& a, const Vec2& b, const Vec2& c, double tol) {
  const double o = orient(a, b, c);
  const double band = tol * (b - a).norm();
  if (o > band) return 1;
  if (o < -band) return -1;
  return 0;
}

bool segments_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, double tol) {
  const int sa = side_of_line(c, d, a, tol), sb = side_of_line(c, d, b, tol);
  if (sa * sb >= 0) return false;
  const int sc = side_of_line(a, b, c, tol), sd = side_of_line(a, b, d, tol);
  return sc * sd < 0;
}

double segment_distance(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  if (segments_cross(a, b, c, d, 0)) return 0;
  return std::min({point_segment_distance(a, c, d), point_segment_distance(b, c, d),
                   point_segment_distance(c, a, b), point_segment_distance(d, a, b)});
}

double crossing_parameter(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double oa = orient(c, d, a), ob = orient(c, d, b);
  if (oa == ob) return 0;
  return std::clamp(oa / (oa - ob), 0.0, 1.0);
}

Vec2 meeting_point(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  if (segments_cross(a, b, c, d, 0)) return a + crossing_parameter(a, b, c, d) * (b - a);
  // Closest approach is attained at an endpoint of one of the segments.
  const std::array<Vec2, 4> p{a, b, c, d};
  const std::array<Vec2, 4> s0{c, c, a, a}, s1{d, d, b, b};
  int best = 0;
  double best_dist = -1;
  for (int k = 0; k < 4; ++k) {
    const double dist = point_segment_distance(p[k], s0[k], s1[k]);
    if (best_dist < 0 || dist < best_dist) {
      best = k;
      best_dist = dist;
    }
  }
  const Vec2 q = s0[best] + closest_parameter(p[best], s0[best], s1[best]) * (s1[best] - s0[best]);
  return 0.5 * (p[best] + q);
}

}  // namespace fissure
