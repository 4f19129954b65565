#include "flow/network/water_viscosity.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fissure::flow {

double water_viscosity(double t) {
  if (!(t >= kWaterViscosityLowest && t <= kWaterViscosityHighest))
    return std::numeric_limits<double>::quiet_NaN();
  const double d = 20 - t;
  const double exponent =
      d / (t + 96) * (1.2378 - 1.303e-3 * d + 3.06e-6 * d * d + 2.55e-8 * d * d * d);
  return kWaterViscosityAt20C * std::pow(10.0, exponent);
}

double water_saturation_pressure(double celsius) {
  // IAPWS-IF97 (2007 revision), region 4, equations 29b and 30 (p in MPa, T in K).
  constexpr double n[] = {0.11670521452767e4,  -0.72421316703206e6, -0.17073846940092e2,
                          0.12020824702470e5,  -0.32325550322333e7, 0.14915108613530e2,
                          -0.48232657361591e4, 0.40511340542057e6,  -0.23855557567849,
                          0.65017534844798e3};
  const double T = celsius + 273.15;
  const double theta = T + n[8] / (T - n[9]);
  const double A = theta * theta + n[0] * theta + n[1];
  const double B = n[2] * theta * theta + n[3] * theta + n[4];
  const double C = n[5] * theta * theta + n[6] * theta + n[7];
  const double root = 2 * C / (-B + std::sqrt(B * B - 4 * A * C));
  return 1e6 * root * root * root * root;
}

WaterState water_state(double celsius, double absolute_pressure) {
  if (!(celsius >= kWaterViscosityLowest && celsius <= kWaterViscosityHighest))
    return WaterState::OutsideCorrelation;
  if (celsius < 0) return WaterState::Supercooled;
  // Between 0 and 0.01 C (the triple point) IF97's line is not defined: its
  // value at the triple point, 611.657 Pa.
  if (absolute_pressure < water_saturation_pressure(std::max(celsius, 0.01)))
    return WaterState::Boiling;
  return WaterState::Liquid;
}

}  // namespace fissure::flow
