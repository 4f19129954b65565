// What a module writes into monitors.csv and the final monitor values of
// summary.json (docs/architecture.md 6, docs/output.md): its columns per monitor
// and their values at a monitor's material point. Each active process
// brings its own (Process::monitors), so core/io names no physics.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/state/rock_mass.h"

namespace fissure {

/// One column per monitor m, "m.<name>". `rank` orders the columns of all
/// processes within a monitor as docs/output.md lists them: the point's
/// motion (0), the fluid (1), heat (2), then the stresses (3); columns of
/// equal rank keep the order of the processes.
struct MonitorColumn {
  std::string name;
  int rank = 0;
  bool brief = false;  ///< among the values `fissure run` prints when it ends
};

class MonitorSource {
 public:
  virtual ~MonitorSource() = default;
  virtual std::vector<MonitorColumn> columns() const = 0;
  /// The values of columns() at material point `point` (a monitor: the
  /// first material points are the monitors, RockMass::points); NaN where
  /// there is no value.
  virtual void values(const RockMass& state, int point, std::span<double> out) const = 0;
  /// Why the value of `column` at `point` is NaN, for the warning that the
  /// monitor writer prints once per monitor and column ("is not on the
  /// fracture network (...)"); empty: no warning.
  virtual std::string why_missing(const RockMass& /*state*/, int /*point*/,
                                  std::string_view /*column*/) const {
    return {};
  }
};

}  // namespace fissure
