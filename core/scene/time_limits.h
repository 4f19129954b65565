// Time controls that cannot work are refused when the scene is read (issue
// 22, item 3; docs/scene-reference.md, "Limits"): a step so short against
// the end time that double precision loses it in t + dt, a step below the
// minimum step (the first step would already be a failure), more steps or
// output frames than a run can take.
#pragma once

#include "core/scene/config_node.h"
#include "core/scene/scene.h"

namespace fissure {

/// The shortest step, as a fraction of time.end, that t + dt still resolves
/// to a few digits over a whole run (double precision: 2.2e-16 relative).
inline constexpr double kShortestRelativeStep = 1e-12;
/// The most steps a run may need at its largest time step, and the most
/// output frames, unless time.max_steps stops it earlier.
inline constexpr double kMostSteps = 1e9;
inline constexpr double kMostFrames = 1e6;
/// The default time.min_step: 1e-9 s, shorter for end times below 1 ms.
inline double default_min_step(double end) {
  return std::min(1e-9, 1e-6 * end);
}

/// Reports at `node` a time `value` (a step, the minimum step) shorter than
/// kShortestRelativeStep x `end`; false then.
bool check_resolvable(const ConfigNode& node, double value, double end);

/// Checks a process's (largest) time step `step`, read at `node`, against
/// the scene's time controls (read before the processes' sections; a time
/// section with problems is not checked against). Reports at `node`.
void check_time_step(const ConfigNode& node, double step, const TimeControls& time);

/// Whether `process` steps in pseudo-time (coupling.quasi_static): its steps
/// do not cover the run, so its step is not checked against time.end.
bool runs_in_pseudo_time(const CouplingSettings& coupling, std::string_view process);

}  // namespace fissure
