#include "thermal/conduction/temperature_step_control.h"

#include <algorithm>

namespace fissure::thermal {

double TemperatureStepControl::retry_step(double dt, double change) const {
  // change > max_change here: the factor is below kSafety < 1.
  return dt * kSafety * max_change / change;
}

double TemperatureStepControl::next_step(double dt, double change) const {
  const double factor =
      change > 0 ? std::min(kMaxGrowth, kSafety * max_change / change) : kMaxGrowth;
  return std::min(max_step, dt * factor);
}

}  // namespace fissure::thermal
