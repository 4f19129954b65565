// The monitor columns of a material point that moves with its block
// (docs/output.md "monitors.csv"): position x, y, displacement ux, uy and
// velocity vx, vy of the point, and the stress sxx, syy, sxy of its block
// (0 for a point fixed in space). The processes that move the blocks report
// them (Process::monitors).
#pragma once

#include "core/io/monitor_source.h"

namespace fissure {

class BlockMonitors final : public MonitorSource {
 public:
  std::vector<MonitorColumn> columns() const override;
  void values(const RockMass& state, int point, std::span<double> out) const override;
};

}  // namespace fissure
