// Where a state holds a value that is not a finite number (issue 22, item
// 4): the coordinator checks every accepted step with these, retries it
// smaller or stops with the diagnosis, so that no nan or inf reaches the
// output files.
#pragma once

#include <string>
#include <vector>

#include "core/io/monitor_writer.h"
#include "core/state/rock_mass.h"

namespace fissure {

/// "block 'b7' (7): non-finite velocity (nan, 0, ...)" for the first block
/// whose vertices, velocity, stress, strain or rotation are not finite; ""
/// if none.
std::string non_finite_block(const RockMass& state);

/// "monitor 'top', column top.p = inf (written by the process of that
/// column)" for the first monitor value that is not finite and that its
/// source cannot explain as missing (MonitorSource::why_missing); "" if
/// none.
std::string non_finite_monitor(const RockMass& state, const MonitorLayout& layout,
                               const std::vector<Monitor>& monitors);

}  // namespace fissure
