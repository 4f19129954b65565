// The factors of time of the thermal sources and conditions (thermal_settings.h).
#include <cmath>
#include <numbers>

#include "thermal/conduction/thermal_settings.h"

namespace fissure {

double TimeFactor::at(double t) const {
  if (decay.empty()) return history_factor(history, t);
  double f = 0;
  for (const auto& [a, tau] : decay) f += a * std::exp(-t / tau);
  return f;
}

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
