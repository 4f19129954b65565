#include "core/io/block_monitors.h"

#include <algorithm>
#include <limits>

#include "core/state/monitor_values.h"

namespace fissure {

std::vector<MonitorColumn> BlockMonitors::columns() const {
  return {{"x", 0, true}, {"y", 0, true}, {"ux", 0, true}, {"uy", 0, true}, {"vx", 0},
          {"vy", 0},      {"sxx", 3},     {"syy", 3},      {"sxy", 3}};
}

void BlockMonitors::values(const RockMass& state, int point, std::span<double> out) const {
  const MonitorValues v = evaluate_monitor(state, point);
  if (state.points[point].block < 0) {
    // Fixed in space: where it is, and nothing of the blocks (a continuum
    // around them may watch it, monitor_writer.h).
    std::fill(out.begin(), out.end(), std::numeric_limits<double>::quiet_NaN());
    out[0] = v.position.x();
    out[1] = v.position.y();
    return;
  }
  const double values[] = {v.position.x(),     v.position.y(), v.displacement.x(),
                           v.displacement.y(), v.velocity.x(), v.velocity.y(),
                           v.stress(0),        v.stress(1),    v.stress(2)};
  std::copy(std::begin(values), std::end(values), out.begin());
}

}  // namespace fissure
