#include "core/io/block_monitors.h"

#include "core/state/monitor_values.h"

namespace fissure {

std::vector<MonitorColumn> BlockMonitors::columns() const {
  return {{"x", 0, true}, {"y", 0, true}, {"ux", 0, true}, {"uy", 0, true}, {"vx", 0},
          {"vy", 0},      {"sxx", 3},     {"syy", 3},      {"sxy", 3}};
}

void BlockMonitors::values(const RockMass& state, int point, std::span<double> out) const {
  const MonitorValues v = evaluate_monitor(state, point);
  const double values[] = {v.position.x(),     v.position.y(), v.displacement.x(),
                           v.displacement.y(), v.velocity.x(), v.velocity.y(),
                           v.stress(0),        v.stress(1),    v.stress(2)};
  std::copy(std::begin(values), std::end(values), out.begin());
}

}  // namespace fissure
