// The continuum's convective (Robin) thermal boundary and its fluid point
// sources against closed forms (docs/continuum.md 4 and 6): a slab between
// a temperature and heat transfer to an ambient temperature (steady: the
// linear profile; transient: the heated semi-infinite solid of Carslaw and
// Jaeger), and a line source of fluid in an almost rigid medium (Theis),
// with its global mass balance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "coupling/process_registry.h"
#include "tests/support/continuum_runs.h"

namespace fissure {
namespace {

using testing::ContinuumRun;

constexpr double kConductivity = 2.5;                     // W/(m K)
constexpr double kHeatCapacity = 2.5e6;                   // J/(m^3 K)
constexpr double kCoefficient = 10;                       // h, W/(m^2 K)
constexpr double kKappa = kConductivity / kHeatCapacity;  // m^2/s

/// A slab [x0, x1] x [0, height] of `cells` elements along x, insulated
/// top and bottom, held at rest (rollers on the left and bottom; no thermal
/// expansion); `thermal` are its thermal conditions. Axisymmetric: a ring.
std::string slab(double x0, double x1, double height, int cells, const std::string& thermal,
                 double end, double step, double initial, bool axisymmetric = false) {
  char text[2048];
  std::snprintf(text, sizeof text, R"(name: robin_slab
physics: [continuum]
gravity: [0, 0]
materials:
  - {name: rock, density: 2500, young_modulus: 10 GPa, poisson_ratio: 0.25}
time: {end: %.17g s}
continuum:
  geometry: %s
  domain: [[%.17g, 0], [%.17g, 0], [%.17g, %.17g], [%.17g, %.17g]]
  mesh: {divisions: [%d, 1]}
  materials:
    - {name: rock, biot_modulus: 10 GPa, permeability: 1e-18 m^2, conductivity: 2.5 W/m/K,
       heat_capacity: 2.5 MJ/m^3/K}
  initial: {temperature: %.17g}
  conditions:
    - {boundary: left, displacement: [0, free]}
    - {boundary: bottom, displacement: [free, 0]}
%s  scheme: monolithic
  time_step: %.17g s
)",
                end, axisymmetric ? "axisymmetric" : "plane_strain", x0, x1, x1, height, x0, height,
                cells, initial, thermal.c_str(), step);
  return text;
}

// Steady conduction through a slab of L = 1 m, T = 50 degC on the left,
// heat transfer h = 10 W/(m^2 K) to T_inf = 10 degC on the right: the
// profile is linear, and the Robin face is at T_R = (k T_left / L + h
// T_inf) / (k / L + h) = 18 degC (the conducted 80 W/m^2 leave by the
// transfer). P1 elements hold a linear field exactly, and two steps of
// 1e14 s leave (C / (dt (L_T + R)))^2 ~ 1e-17 of the start: what remains is
// round-off, so the tolerance is 1e-9 K.
TEST(ContinuumSources, HeatTransferSlabReachesTheLinearSteadyState) {
  const double length = 1, t_left = 50, t_inf = 10;
  const std::string thermal =
      "    - {boundary: left, temperature: 50}\n"
      "    - {boundary: right, heat_transfer: {coefficient: 10 W/m^2/K, temperature: 10}}\n";
  ContinuumRun run(
      read_scene_text(slab(0, length, 0.1, 10, thermal, 2e14, 1e14, 30), "robin_slab.yaml"));
  ASSERT_TRUE(run.process().controls().with_temperature());
  run.advance_to(2e14, 1e14);
  const double t_right = (kConductivity * t_left / length + kCoefficient * t_inf) /
                         (kConductivity / length + kCoefficient);
  EXPECT_DOUBLE_EQ(t_right, 18);
  double largest = 0;
  for (double x : {0.0, 0.13, 0.25, 0.5, 0.77, 0.95, 1.0})
    for (double y : {0.0, 0.05, 0.1}) {
      const double exact = t_left + (t_right - t_left) * x / length;
      const double t = run.at({x, y}).temperature;
      EXPECT_NEAR(t, exact, 1e-9) << "x = " << x << ", y = " << y;
      largest = std::max(largest, std::abs(t - exact));
    }
  std::printf("steady Robin slab: T_R = %.12f degC (exact 18), largest error %.2e K\n",
              run.at({length, 0.05}).temperature, largest);
}

// The same in axisymmetry, where the transfer's boundary matrix carries the
// ring weight 2 pi r: a thick cylinder a = 1 m to b = 2 m, 50 degC at r = a,
// h = 10 W/(m^2 K) to 10 degC at r = b. Steady: T = T_a + (T_b - T_a)
// ln(r/a) / ln(b/a), with k (T_a - T_b) / (b ln(b/a)) = h (T_b - T_inf),
// so T_b = 16.111 degC. The logarithm is no P1 field: 20 elements across
// leave an O(h^2) error, about (0.05 m / a)^2 / 12 x 34 K = 7e-3 K; the
// tolerance is 1e-2 K. A wrong weight (2 pi r missing, or taken at the
// wrong end) would move T_b by about 3 K.
TEST(ContinuumSources, HeatTransferOnARingCarriesTheRingWeight) {
  const double a = 1, b = 2, t_a = 50, t_inf = 10;
  const std::string thermal =
      "    - {boundary: left, temperature: 50}\n"
      "    - {boundary: right, heat_transfer: {coefficient: 10 W/m^2/K, temperature: 10}}\n";
  ContinuumRun run(
      read_scene_text(slab(a, b, 0.1, 20, thermal, 2e14, 1e14, 30, true), "robin_ring.yaml"));
  run.advance_to(2e14, 1e14);
  const double g = kConductivity / (b * std::log(b / a));
  const double t_b = (g * t_a + kCoefficient * t_inf) / (g + kCoefficient);
  double largest = 0;
  for (double r : {1.0, 1.2, 1.5, 1.8, 2.0}) {
    const double exact = t_a + (t_b - t_a) * std::log(r / a) / std::log(b / a);
    const double t = run.at({r, 0.05}).temperature;
    EXPECT_NEAR(t, exact, 1e-2) << "r = " << r;
    largest = std::max(largest, std::abs(t - exact));
  }
  std::printf("axisymmetric Robin ring: T_b = %.6f degC (exact %.6f), largest error %.2e K\n",
              run.at({b, 0.05}).temperature, t_b, largest);
}

// The transient: a semi-infinite solid at T0 = 20 degC whose face x = 0
// exchanges heat with T_inf = 80 degC from t = 0 (Carslaw and Jaeger 1959,
// 2.7 (9)): (T - T0) / (T_inf - T0) = erfc(xi) - exp(H x + H^2 kappa t)
// erfc(xi + H sqrt(kappa t)), xi = x / (2 sqrt(kappa t)), H = h / k = 4 /m.
// At t = 1e5 s the diffusion length 2 sqrt(kappa t) is 0.63 m; the slab is
// 5 m long (insulated far end: erfc(7.9) ~ 1e-28 of the change reaches
// it), with 5 cm elements and 200 steps of 500 s. Backward Euler's error is
// at most of order dt / (2 t) = 0.25 % of the change and P1's (h / 0.6
// m)^2 / 12 = 0.06 %; the tolerance is 0.5 % of T_inf - T0 at each point.
TEST(ContinuumSources, HeatTransferIntoAHalfSpaceFollowsCarslawAndJaeger) {
  const double t0 = 20, t_inf = 80, end = 1e5;
  const std::string thermal =
      "    - {boundary: left, heat_transfer: {coefficient: 10 W/m^2/K, temperature: 80}}\n";
  ContinuumRun run(
      read_scene_text(slab(0, 5, 0.05, 100, thermal, end, 500, t0), "robin_half.yaml"));
  run.advance_to(end, 500);
  const double h = kCoefficient / kConductivity, root = std::sqrt(kKappa * end);
  for (double x : {0.0, 0.1, 0.2, 0.5, 1.0}) {
    const double xi = x / (2 * root);
    const double exact =
        t0 + (t_inf - t0) *
                 (std::erfc(xi) - std::exp(h * x + h * h * root * root) * std::erfc(xi + h * root));
    const double t = run.at({x, 0.025}).temperature;
    EXPECT_NEAR(t, exact, 0.005 * (t_inf - t0)) << "x = " << x;
    std::printf("Robin half space x = %.2f m: %.4f degC, exact %.4f, error %.3f %% of the change\n",
                x, t, exact, 100 * (t - exact) / (t_inf - t0));
  }
}

// A line source of fluid, Q = 1e-5 m^3/s per metre from t = 0, in an
// infinite medium that is almost rigid to the pore pressure (alpha = 1e-3:
// alpha^2 M / K_v = 8e-8 of the storage), so the pressure obeys the
// diffusion equation with S = 1/M and c = k M / mu = 0.1 m^2/s (Theis
// 1935): p = Q mu / (4 pi k) E1(r^2 / (4 c t)). A quarter model, 100 m
// square, Q / 4 at its corner; its far sides are closed, and E1(100^2 / 4 c
// t) = 5e-13 at t = 1000 s. Mesh 0.1 m at the source, growing 0.15 per
// metre (0.4 m at 2 m, 1.6 m at 10 m); 200 steps of 5 s. At r = 2, 5, 10 m
// (>= 4 elements from the source, where the point load's local error has
// decayed) P1's error is about (h / r)^2 / 12 = 0.2 to 0.35 %, backward
// Euler's (dt / 2) |p_tt| / |p| below 0.1 %: the tolerance is 1 %.
std::string line_source(const std::string& rate) {
  return R"(name: line_source
physics: [continuum]
gravity: [0, 0]
materials:
  - {name: rock, density: 2500, young_modulus: 10 GPa, poisson_ratio: 0.25}
time: {end: 1000 s}
continuum:
  domain: [[0, 0], [100, 0], [100, 100], [0, 100]]
  mesh: {element_size: 10 m, fine_element_size: 0.1 m, size_grading: 0.15}
  materials:
    - {name: rock, biot_coefficient: 0.001, biot_modulus: 1 GPa, permeability: 1e-13 m^2}
  sources: [{name: well, point: [0, 0], )" +
         rate + R"(}]
  conditions:
    - {boundary: left, displacement: [0, free]}
    - {boundary: bottom, displacement: [free, 0]}
    - {boundary: right, displacement: [0, free]}
    - {boundary: top, displacement: [free, 0]}
  scheme: monolithic
  time_step: 5 s
)";
}

TEST(ContinuumSources, FluidLineSourceFollowsTheisAndConservesMass) {
  const double q = 1e-5, mu = 1e-3, k = 1e-13, m = 1e9, c = k * m / mu, t = 1000;
  ContinuumRun run(read_scene_text(line_source("fluid_rate: 2.5e-6 m^2/s"), "line_source.yaml"));
  EXPECT_FALSE(run.process().controls().with_temperature()) << "a fluid source is no heat";
  run.advance_to(t, 5);
  for (double r : {2.0, 5.0, 10.0})
    for (const Vec2& direction : {Vec2(1, 0), Vec2(0.6, 0.8)}) {
      const double exact = q * mu / (4 * std::numbers::pi * k) * -std::expint(-r * r / (4 * c * t));
      const double p = run.at(r * direction).pressure;
      EXPECT_NEAR(p / exact, 1, 0.01) << "r = " << r << " along " << direction.transpose();
      std::printf("Theis r = %4.1f m along (%.1f, %.1f): p = %.3f Pa, E1 %.3f Pa, error %+.3f %%\n",
                  r, direction.x(), direction.y(), p, exact, 100 * (p / exact - 1));
    }
  EXPECT_NEAR(run.at({5, 5}).temperature, 20, 1e-12) << "the temperature stays the initial";

  // The mass balance: the injected volume Q / 4 t is stored, int p / M dA +
  // alpha int div u dA. The second is 0 here: rollers on every side hold
  // u . n = 0, and int div u = int u . n ds. Nothing leaves through the
  // closed sides, and the row sums of the flow equation (1^T H = 0) make
  // the balance exact up to the solvers' round-off: the tolerance is 1e-9.
  const continuum::ContinuumMesh& mesh = run.process().mesh();
  const continuum::PoroState& fields = run.process().fields();
  double pressure_integral = 0;  // exact for the P1 pressure
  for (const auto& tri : mesh.triangles) {
    const Vec2 a = mesh.nodes[tri[0]], b = mesh.nodes[tri[1]], d = mesh.nodes[tri[2]];
    const double area = 0.5 * ((b - a).x() * (d - a).y() - (b - a).y() * (d - a).x());
    pressure_integral +=
        area / 3 * (fields.pressure(tri[0]) + fields.pressure(tri[1]) + fields.pressure(tri[2]));
  }
  const double injected = q / 4 * t, stored = pressure_integral / m;
  EXPECT_NEAR(stored / injected, 1, 1e-9);
  std::printf("mass balance: injected %.6e m^3/m, stored %.6e, relative error %.2e\n", injected,
              stored, stored / injected - 1);
}

// Extraction is injection with the sign changed, and the history scales the
// rate: half the rate as extraction halves and reverses the pressure.
TEST(ContinuumSources, ExtractionWithAHistoryIsTheScaledInjection) {
  ContinuumRun injection(
      read_scene_text(line_source("fluid_rate: 2.5e-6 m^2/s"), "line_source.yaml"));
  ContinuumRun extraction(
      read_scene_text(line_source("fluid_rate: -5e-6 m^2/s, history: [[0, 0.25], [1e4, 0.25]]"),
                      "line_source.yaml"));
  injection.advance_to(200, 5);
  extraction.advance_to(200, 5);
  for (double r : {1.0, 3.0}) {
    const double p = injection.at({r, 0}).pressure;
    EXPECT_NEAR(extraction.at({r, 0}).pressure, -0.5 * p, 1e-9 * std::abs(p)) << "r = " << r;
  }
}

}  // namespace
}  // namespace fissure
