#include "core/state/monitor_values.h"

#include <algorithm>

namespace fissure {

Vec2 block_velocity_at(const Block& b, const Vec2& x) {
  const Vec2 r = x - b.section.centroid;
  const Vector6& v = b.velocity;
  return Vec2(v(0) - r.y() * v(2) + r.x() * v(3) + r.y() * v(5) / 2,
              v(1) + r.x() * v(2) + r.y() * v(4) + r.x() * v(5) / 2);
}

MonitorValues evaluate_monitor(const RockMass& state, int point_index) {
  const MaterialPoint& p = state.points[point_index];
  MonitorValues m;
  m.position = p.current;
  m.displacement = p.current - p.initial;
  if (p.block >= 0) {
    const Block& b = state.blocks[p.block];
    m.velocity = block_velocity_at(b, p.current);
    m.stress = b.stress;
  }
  return m;
}

double fastest_block_point(const RockMass& state) {
  double fastest = 0;
  for (const Block& b : state.blocks)
    for (const Vec2& x : b.polygon.vertices)
      fastest = std::max(fastest, block_velocity_at(b, x).norm());
  return fastest;
}

}  // namespace fissure
