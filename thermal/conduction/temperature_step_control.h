// The thermal step limited by the temperature change it may cause
// (thermal.max_temperature_change; theory.md 4.4, the seed's allowable
// increment; docs/thermal.md "Adaptive step"). A step whose largest nodal
// change |dT| exceeds the limit is rejected and retried with the step scaled
// to the limit; after an accepted step the next one is scaled the same way,
// growing by at most kMaxGrowth, and never beyond thermal.time_step. The
// change is close to proportional to the step while it is small, hence the
// linear scaling; the safety factor keeps the retried step from landing just
// above the limit again. Decided from values only (never the clock), so runs
// are reproducible to the bit.
#pragma once

namespace fissure::thermal {

struct TemperatureStepControl {
  static constexpr double kSafety = 0.9;     ///< aim below the limit
  static constexpr double kMaxGrowth = 2.0;  ///< per accepted step
  double max_change = 0;                     ///< K; 0: off (the step is thermal.time_step)
  double max_step = 0;                       ///< s; thermal.time_step

  bool enabled() const { return max_change > 0; }
  /// Whether a step whose largest nodal change is `change` (K) is accepted.
  bool accepts(double change) const { return !enabled() || change <= max_change; }
  /// The step to retry a rejected step `dt` with (< dt).
  double retry_step(double dt, double change) const;
  /// The step to propose after an accepted step `dt` that changed the
  /// temperatures by at most `change`.
  double next_step(double dt, double change) const;
};

}  // namespace fissure::thermal
