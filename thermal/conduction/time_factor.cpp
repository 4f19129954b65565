// The values in time of the thermal conditions (thermal_settings.h); their
// factors of time are core/scene/time_history.h's.
#include <cmath>
#include <numbers>

#include "thermal/conduction/thermal_settings.h"

namespace fissure {

double TemperatureCycle::at(double t) const {
  if (amplitude == 0) return 0;
  return amplitude * std::cos(2 * std::numbers::pi * (t - peak) / period);
}

double ThermalCondition::value_at(double t) const {
  const double v = value * factor.at(t);
  return type == Type::Temperature ? v + cycle.at(t) : v;
}

double ThermalCondition::external_temperature_at(double t) const {
  return external_temperature * factor.at(t) + cycle.at(t);
}

}  // namespace fissure
