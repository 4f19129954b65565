#include "core/scene/time_limits.h"

#include <fmt/format.h>

#include <algorithm>

namespace fissure {

bool check_resolvable(const ConfigNode& node, double value, double end) {
  if (value >= kShortestRelativeStep * end) return true;
  node.error(
      fmt::format("found {}; expected a time of at least {:g} x time.end = {:g} s "
                  "(shorter steps are lost in the rounding of t + dt)",
                  node.found(), kShortestRelativeStep, kShortestRelativeStep * end));
  return false;
}

void check_time_step(const ConfigNode& node, double step, const TimeControls& time) {
  if (!(time.end_time > 0) || !(step > 0)) return;
  if (!check_resolvable(node, step, time.end_time)) return;
  if (step < time.min_step)
    node.error(
        fmt::format("found {}; expected a time step of at least time.min_step = {:g} s "
                    "(a shorter first step already ends the run as diverged)",
                    node.found(), time.min_step));
  else if (time.end_time / step > kMostSteps && (time.max_steps < 0 || time.max_steps > kMostSteps))
    node.error(
        fmt::format("found {}; expected a time step of at least time.end / {:g} = {:g} s "
                    "(the run would take more than {:g} steps; or set time.max_steps)",
                    node.found(), kMostSteps, time.end_time / kMostSteps, kMostSteps));
}

bool runs_in_pseudo_time(const CouplingSettings& coupling, std::string_view process) {
  if (!coupling.quasi_static) return false;
  const std::vector<std::string>& names = coupling.quasi_static->processes;
  return std::find(names.begin(), names.end(), process) != names.end();
}

}  // namespace fissure
