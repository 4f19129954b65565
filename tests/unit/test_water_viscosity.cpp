// The water viscosity correlation of the flow (flow/network/water_viscosity.h:
// Kestin, Sokolov & Wakeham 1978) against tabulated values, the saturation
// pressure of IAPWS-IF97 against the release's own check values, and the
// classification of the water's state that the flow warns with.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "flow/network/water_viscosity.h"

namespace fissure::flow {
namespace {

TEST(WaterViscosity, MatchesTheTableFrom0To100C) {
  // Viscosity of water at 0.1 MPa (at saturation at 100 C), Pa s: the
  // IAPWS 2008 formulation as tabulated in the NIST Chemistry WebBook
  // (4 digits). The correlation was fitted to the measurements of its time
  // within 0.1-0.3 %; the tolerance is 0.3 %.
  const std::pair<double, double> table[] = {{0, 1.7914e-3},  {10, 1.3060e-3}, {20, 1.0016e-3},
                                             {25, 0.8900e-3}, {30, 0.7972e-3}, {40, 0.6527e-3},
                                             {50, 0.5465e-3}, {60, 0.4665e-3}, {70, 0.4042e-3},
                                             {80, 0.3544e-3}, {90, 0.3145e-3}, {100, 0.2818e-3}};
  double worst = 0;
  for (const auto& [t, mu] : table) {
    const double deviation = water_viscosity(t) / mu - 1;
    EXPECT_LE(std::abs(deviation), 3e-3) << t << " C";
    worst = std::max(worst, std::abs(deviation));
  }
  std::printf("largest deviation from the table: %.3f %%\n", 100 * worst);
  // The reference temperature exactly.
  EXPECT_DOUBLE_EQ(water_viscosity(20), kWaterViscosityAt20C);
}

TEST(WaterViscosity, FallsMonotonicallyAndHasNoValueOutsideItsRange) {
  double last = water_viscosity(kWaterViscosityLowest);
  for (double t = kWaterViscosityLowest + 0.5; t <= kWaterViscosityHighest; t += 0.5) {
    const double mu = water_viscosity(t);
    EXPECT_LT(mu, last) << t;
    last = mu;
  }
  for (double t : {-8.01, 150.01, -273.0, 1e3, std::numeric_limits<double>::quiet_NaN(),
                   std::numeric_limits<double>::infinity()})
    EXPECT_TRUE(std::isnan(water_viscosity(t))) << t;
}

TEST(WaterViscosity, SaturationPressureMatchesTheIf97CheckValues) {
  // IAPWS-IF97, Table 35: p_s at 300, 500 and 600 K.
  EXPECT_NEAR(water_saturation_pressure(300 - 273.15), 0.353658941e-2 * 1e6, 1e-8 * 3.5e3);
  EXPECT_NEAR(water_saturation_pressure(500 - 273.15), 0.263889776e1 * 1e6, 1e-8 * 2.6e6);
  EXPECT_NEAR(water_saturation_pressure(600 - 273.15), 0.123443146e2 * 1e6, 1e-8 * 1.2e7);
  // Boiling at one atmosphere: 99.97 C.
  EXPECT_LT(water_saturation_pressure(99.9), kAtmosphericPressure);
  EXPECT_GT(water_saturation_pressure(100.0), kAtmosphericPressure);
}

TEST(WaterViscosity, StateOfTheWater) {
  EXPECT_EQ(water_state(20, kAtmosphericPressure), WaterState::Liquid);
  EXPECT_EQ(water_state(0, kAtmosphericPressure), WaterState::Liquid);
  EXPECT_EQ(water_state(-5, kAtmosphericPressure), WaterState::Supercooled);
  EXPECT_EQ(water_state(120, kAtmosphericPressure), WaterState::Boiling);
  EXPECT_EQ(water_state(120, 1e6), WaterState::Liquid);  // 198.6 kPa boils it
  EXPECT_EQ(water_state(150, 1e6), WaterState::Liquid);
  EXPECT_EQ(water_state(50, 1e4), WaterState::Boiling);  // 12.35 kPa at 50 C
  for (double t : {-9.0, 151.0, std::numeric_limits<double>::quiet_NaN()})
    EXPECT_EQ(water_state(t, 1e6), WaterState::OutsideCorrelation) << t;
}

}  // namespace
}  // namespace fissure::flow
