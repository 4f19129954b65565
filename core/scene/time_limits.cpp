#include "core/scene/time_limits.h"

#include <fmt/format.h>

namespace fissure {

void check_time_step(const ConfigNode& node, double step, const TimeControls& time) {
  if (!(time.end_time > 0) || !(step > 0)) return;
  if (step < kShortestRelativeStep * time.end_time)
    node.error(
        fmt::format("found {}; expected a time step of at least {:g} x time.end = {:g} s "
                    "(shorter steps are lost in the rounding of t + dt)",
                    node.found(), kShortestRelativeStep, kShortestRelativeStep * time.end_time));
  else if (step < time.min_step)
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

}  // namespace fissure
