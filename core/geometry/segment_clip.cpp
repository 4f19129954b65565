#include "core/geometry/segment_clip.h"

#include <algorithm>

namespace fissure {

bool clip_to_box(Vec2& a, Vec2& b, const Box& box) {
  double t0 = 0, t1 = 1;
  const Vec2 d = b - a;
  const double p[4] = {-d.x(), d.x(), -d.y(), d.y()};
  const double q[4] = {a.x() - box.lo.x(), box.hi.x() - a.x(), a.y() - box.lo.y(),
                       box.hi.y() - a.y()};
  for (int k = 0; k < 4; ++k) {
    if (p[k] == 0) {
      if (q[k] < 0) return false;
      continue;
    }
    const double r = q[k] / p[k];
    if (p[k] < 0)
      t0 = std::max(t0, r);
    else
      t1 = std::min(t1, r);
    if (t0 > t1) return false;
  }
  const Vec2 a0 = a;
  a = a0 + t0 * d;
  b = a0 + t1 * d;
  return true;
}

}  // namespace fissure
