// Thermal conditions that vary in time (thermal.conditions[].history,
// decay, cycle; docs/thermal.md 4) against closed forms for a half-space
// whose surface temperature is prescribed (Carslaw and Jaeger, Conduction of
// Heat in Solids, 2nd ed., 2.5 and 2.6):
//   * a ramp T_s = C t from T = 0:  T(x, t) = 4 C t i^2erfc(x / 2 sqrt(kappa t)),
//     i^2erfc(u) = ((1 + 2 u^2) erfc(u) - 2 u exp(-u^2) / sqrt(pi)) / 4;
//   * any T_s(t) from T = 0 (Duhamel's theorem):
//     T(x, t) = T_s(0) erfc(x / 2 sqrt(kappa t))
//               + int_0^t T_s'(tau) erfc(x / 2 sqrt(kappa (t - tau))) dtau,
//     here a daily cycle T_s = A cos(2 pi (t - peak) / P), the integral by
//     composite Simpson on 20,000 intervals (its error is far below the
//     tolerance: the integrand is smooth and bounded by A omega);
// and a decaying flux whose energy must enter exactly as the steps apply it.
// Rock of verification.md (h): lambda = 3 W/(m K), rho c = 2.484 MJ/(m^3 K).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "tests/support/thermal_runs.h"

namespace fissure::testing {
namespace {

constexpr double kLambda = 3, kRhoC = 2760.0 * 900.0, kKappa = kLambda / kRhoC;
const ThermalMaterial kRock{Eigen::Vector3d(kLambda, kLambda, 0), kRhoC};

/// A strip [0, length] x [0, 0.02] heated from its left side.
ThermalRun strip(double length, double h, const ThermalCondition& left,
                 ThermalControls::Scheme scheme = ThermalControls::Scheme::BackwardEuler) {
  ThermalControls c;
  c.element_size = h;
  c.initial_temperature = 0;
  c.scheme = scheme;
  c.conditions = {left};
  return ThermalRun(thermal_scene({box(0, 0, length, 0.02)}, c, kRock));
}

double i2erfc(double u) {
  return ((1 + 2 * u * u) * std::erfc(u) - 2 * u * std::exp(-u * u) / std::sqrt(std::numbers::pi)) /
         4;
}

// Ramp: 10 degC at t = 1e5 s through the history [[0, 0], [1e5, 1]] of a
// fixed temperature of 10 degC, then held. At t = 1e5 s, x = 0.1 ... 0.6 m
// (sqrt(kappa t) = 0.35 m): BDF2 with dt = 250 s and h = 0.01 m make errors
// of O((dt / t)^2) and O(h^2 / (kappa t)), about 1e-4 of the 10 K; the
// tolerance 0.01 K is 0.1 % of the ramp's height.
TEST(thermal_boundary_histories, RampedSurfaceTemperature) {
  ThermalCondition left;
  left.boundary = "left";
  left.type = ThermalCondition::Type::Temperature;
  left.value = 10;
  left.factor.history = {{0, 0}, {1e5, 1}};
  ThermalRun run = strip(4.4, 0.01, left, ThermalControls::Scheme::Bdf2);
  run.run(250, 400);
  const double t = 1e5, rate = 10 / 1e5;
  for (const double x : {0.1, 0.2, 0.4, 0.6}) {
    const double exact = 4 * rate * t * i2erfc(x / (2 * std::sqrt(kKappa * t)));
    const double value = run.temperature_at(Vec2(x, 0.01));
    std::printf("ramp: x = %.1f m: T = %.5f, exact %.5f, error %.2e K\n", x, value, exact,
                value - exact);
    EXPECT_NEAR(value, exact, 0.01) << "x = " << x;
  }
}

double daily(double t, double amplitude, double period, double peak) {
  return amplitude * std::cos(2 * std::numbers::pi * (t - peak) / period);
}

/// Duhamel's integral for the surface temperature A cos(w (t - peak)).
double duhamel_cycle(double x, double t, double amplitude, double period, double peak) {
  const double w = 2 * std::numbers::pi / period;
  const auto kernel = [&](double s) {  // erfc(x / 2 sqrt(kappa s)), s = t - tau
    return s <= 0 ? 0.0 : std::erfc(x / (2 * std::sqrt(kKappa * s)));
  };
  const auto integrand = [&](double tau) {
    return -amplitude * w * std::sin(w * (tau - peak)) * kernel(t - tau);
  };
  const int n = 20000;
  const double d = t / n;
  double sum = integrand(0) + integrand(t);
  for (int k = 1; k < n; ++k) sum += (k % 2 ? 4 : 2) * integrand(k * d);
  return daily(0, amplitude, period, peak) * kernel(t) + sum * d / 3;
}

// A daily cycle of +-8 K (peak at 14 h) on the surface, from T = 0: after
// two days at depths 0 to 0.3 m (the skin depth sqrt(2 kappa / w) is 0.18 m:
// the amplitude falls to 18 % at 0.3 m, with a lag). BDF2 with dt = P / 288
// (5 min): a phase error of O((w dt)^2) ~ 5e-4 of A; h = 0.005 m: O((h /
// d)^2) ~ 1e-3 of A. Tolerance 0.02 K = 0.25 % of A.
TEST(thermal_boundary_histories, DailyCycleMatchesDuhamel) {
  const double amplitude = 8, period = 86400, peak = 14 * 3600.0;
  ThermalCondition left;
  left.boundary = "left";
  left.type = ThermalCondition::Type::Temperature;
  left.value = 0;
  left.cycle = {amplitude, period, peak};
  ThermalRun run = strip(1.5, 0.005, left, ThermalControls::Scheme::Bdf2);
  const double dt = period / 288;
  for (const double t : {1.25 * period, 2.0 * period}) {
    run.run(dt, static_cast<int>(std::lround((t - run.state.time) / dt)));
    for (const double x : {0.0, 0.05, 0.1, 0.3}) {
      const double exact =
          x == 0 ? daily(t, amplitude, period, peak) : duhamel_cycle(x, t, amplitude, period, peak);
      const double value = run.temperature_at(Vec2(x, 0.01));
      std::printf("cycle: t = %.2f d, x = %.2f m: T = %.5f, exact %.5f, error %.2e K\n", t / period,
                  x, value, exact, value - exact);
      EXPECT_NEAR(value, exact, 0.02) << "x = " << x << ", t = " << t;
    }
  }
}

// A flux that decays as 50 W/m^2 (0.6 e^(-t / 1e4 s) + 0.4 e^(-t / 1e5 s))
// into an otherwise insulated block: backward Euler applies q(t_{n+1})
// over each step, so the heat through the boundary is sum dt q(t_{n+1})
// times the side's 0.02 m, and the heat stored is the same, to round-off.
TEST(thermal_boundary_histories, DecayingFluxEntersAsApplied) {
  ThermalCondition left;
  left.boundary = "left";
  left.type = ThermalCondition::Type::Flux;
  left.value = 50;
  left.factor.decay = {{0.6, 1e4}, {0.4, 1e5}};
  ThermalRun run = strip(0.5, 0.02, left);
  const double dt = 500;
  double expected = 0;
  for (int n = 1; n <= 100; ++n) expected += dt * 0.02 * left.value_at(n * dt);
  run.run(dt, 100);
  const auto& balance = run.thermal().balance;
  std::printf("decaying flux: %.10g J/m in, through boundary %.10g, stored %.10g\n", expected,
              balance.boundary, balance.stored);
  EXPECT_NEAR(balance.boundary, expected, 1e-12 * expected);
  EXPECT_NEAR(balance.stored, expected, 1e-10 * expected);
  // The factor itself: 0.6 e^-1 + 0.4 e^-0.1 at t = 1e4 s.
  EXPECT_DOUBLE_EQ(left.value_at(1e4), 50 * (0.6 * std::exp(-1.0) + 0.4 * std::exp(-0.1)));
}

}  // namespace
}  // namespace fissure::testing
