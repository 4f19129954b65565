// Block heat conduction (theory.md 4.1, docs/thermal.md) against closed-form
// solutions: verification.md (h) 1D conduction (erfc) and its two-block
// variants, the line source E1 (verification.md (l), 2D), the observed
// orders in time and space, the patch test, the energy balance and the
// maximum principle. Rock of verification.md (h): rho c = 2760 x 900 =
// 2.484 MJ/(m^3 K), lambda = 3 W/(m K), kappa = 1.20773e-6 m^2/s.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "coupling/process_registry.h"
#include "rockmass/fields/block_thermal_strain.h"
#include "tests/support/run_scene.h"
#include "tests/support/thermal_runs.h"
#include "thermal/conduction/thermal_state.h"

namespace fissure::testing {
namespace {

constexpr double kLambda = 3, kRhoC = 2760.0 * 900.0, kKappa = kLambda / kRhoC;
const ThermalMaterial kRock{Eigen::Vector3d(kLambda, kLambda, 0), kRhoC};

ThermalCondition condition(const std::string& boundary, ThermalCondition::Type type, double value,
                           double external = 0) {
  ThermalCondition c;
  c.boundary = boundary;
  c.type = type;
  c.value = value;
  c.external_temperature = external;
  return c;
}

ThermalControls controls(double h, double initial = 0) {
  ThermalControls c;
  c.element_size = h;
  c.initial_temperature = initial;
  return c;
}

/// The largest nodal difference from f(x) over the mesh.
template <class F>
double max_error(const ThermalRun& run, F f) {
  double e = 0;
  const auto& nodes = run.process->mesh().nodes;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    e = std::max(e, std::abs(run.thermal().temperature[i] - f(nodes[i])));
  return e;
}

TEST(thermal_conduction, ReferenceValuesOfCase_h) {
  // verification.md (h)'s table: theta = erfc(x / 2 sqrt(kappa t)).
  EXPECT_NEAR(std::erfc(0.1 / (2 * std::sqrt(kKappa * 1e4))), 0.519946, 1e-6);
  EXPECT_NEAR(std::erfc(0.5 / (2 * std::sqrt(kKappa * 1e6))), 0.747669, 1e-6);
}

// (h): T = 0 initially, T = 1 on the left side of a 4.4 m strip (>= 4
// sqrt(kappa 1e6 s), St. John); backward Euler, lumped capacity, h = 0.01 m,
// dt = 100 s. The catalogue's tolerance is 0.005; the discretization errors
// are O(dt / (x^2 / kappa)) and O(h^2 / x^2), a few 1e-3 at x = 0.1 m, t = 1e4 s.
TEST(thermal_conduction, ErfcHalfSpace_h) {
  ThermalControls c = controls(0.01);
  c.conditions = {condition("left", ThermalCondition::Type::Temperature, 1)};
  ThermalRun run(thermal_scene({box(0, 0, 4.4, 0.02)}, c, kRock));
  const struct {
    double x, t, theta;
  } table[] = {
      {0.1, 1e4, 0.519946}, {0.1, 1e5, 0.838768}, {0.5, 1e6, 0.747669}, {1.0, 1e6, 0.519946}};
  for (const auto& row : table) {
    run.run(100, static_cast<int>(std::lround((row.t - run.state.time) / 100)));
    const double theta = run.temperature_at(Vec2(row.x, 0.01));
    EXPECT_NEAR(theta, row.theta, 0.005) << "x = " << row.x << " m, t = " << row.t << " s";
    std::printf("x = %g m, t = %g s: theta %.6f, erfc %.6f, error %.2e\n", row.x, row.t, theta,
                row.theta, theta - row.theta);
  }
}

// A smooth decaying mode on [0, L] with T = 0 at both ends: T = sin(pi x / L)
// exp(-kappa (pi / L)^2 t). Its errors measure the orders cleanly (no
// start-up singularity).
double mode(const Vec2& x, double length, double t) {
  const double k = std::numbers::pi / length;
  return std::sin(k * x.x()) * std::exp(-kKappa * k * k * t);
}

ThermalRun mode_run(double h, ThermalControls::Scheme scheme, double length = 1) {
  ThermalControls c = controls(h);
  c.scheme = scheme;
  c.conditions = {condition("left", ThermalCondition::Type::Temperature, 0),
                  condition("right", ThermalCondition::Type::Temperature, 0)};
  ThermalRun run(thermal_scene({box(0, 0, length, 0.1)}, c, kRock));
  const auto& nodes = run.process->mesh().nodes;
  std::vector<double> t(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) t[i] = mode(nodes[i], length, 0);
  run.process->set_temperature(run.state, std::move(t));
  return run;
}

/// Order in time: the same mesh, against its own solution with a 64 times
/// smaller BDF2 step (the time error of the reference is 1e-4 of the
/// coarsest's), at t = 4e4 s (about half the decay time).
TEST(thermal_conduction, OrderInTime) {
  using Scheme = ThermalControls::Scheme;
  const double end = 4e4;
  ThermalRun reference = mode_run(0.05, Scheme::Bdf2);
  reference.run(end / 640, 640);
  const std::vector<double> exact = reference.thermal().temperature;
  for (const Scheme scheme : {Scheme::BackwardEuler, Scheme::Bdf2}) {
    std::vector<double> errors;
    for (const int steps : {10, 20, 40}) {
      ThermalRun run = mode_run(0.05, scheme);
      run.run(end / steps, steps);
      double e = 0;
      for (std::size_t i = 0; i < exact.size(); ++i)
        e = std::max(e, std::abs(run.thermal().temperature[i] - exact[i]));
      errors.push_back(e);
    }
    const double expected = scheme == Scheme::Bdf2 ? 2 : 1;
    for (std::size_t k = 1; k < errors.size(); ++k) {
      const double order = std::log2(errors[k - 1] / errors[k]);
      std::printf("%s: errors %.3e -> %.3e, order %.3f\n",
                  scheme == Scheme::Bdf2 ? "bdf2" : "backward Euler", errors[k - 1], errors[k],
                  order);
      // Asymptotic orders within 10 %: the coarsest steps are 1/4 of the
      // decay time, where the next error terms are still a few percent.
      EXPECT_NEAR(order, expected, 0.1 * expected)
          << (scheme == Scheme::Bdf2 ? "bdf2" : "backward Euler") << ", errors " << errors[k - 1]
          << " -> " << errors[k];
    }
  }
}

/// Order in space: BDF2 with steps small enough that the time error is 1e-3
/// of the space error, against the exact mode; P1 nodal errors fall as h^2.
TEST(thermal_conduction, OrderInSpace) {
  const double end = 2e4;
  std::vector<double> errors;
  for (const double h : {0.1, 0.05, 0.025}) {
    ThermalRun run = mode_run(h, ThermalControls::Scheme::Bdf2);
    run.run(end / 200, 200);
    errors.push_back(max_error(run, [&](const Vec2& x) { return mode(x, 1, end); }));
  }
  for (std::size_t k = 1; k < errors.size(); ++k) {
    const double order = std::log2(errors[k - 1] / errors[k]);
    std::printf("space: errors %.3e -> %.3e, order %.3f\n", errors[k - 1], errors[k], order);
    // Unstructured meshes halve h only on average: orders within 0.3 of 2.
    EXPECT_NEAR(order, 2, 0.3) << "errors " << errors[k - 1] << " -> " << errors[k];
  }
}

// Two blocks with perfect contact against one block with the same triangles:
// a parallelogram strip whose boundary points (every 0.25 m below, shifted
// by 0.125 m above, 0.2 m apart) form acute triangles that the mesher keeps
// as they are, cut in two along one of its mesh edges. The coordinates are
// the same bits (divisions by powers of two), so the two runs differ by the
// order of summation only: round-off, 1e-12 of the temperature range.
TEST(thermal_conduction, PerfectContactIsOneBlock_h) {
  const double h = 0.26, s = 0.125, w = 0.2;
  ThermalControls c = controls(h);
  const std::vector<Vec2> whole = {Vec2(0, 0), Vec2(2, 0), Vec2(2 + s, w), Vec2(s, w)};
  const std::vector<Vec2> left = {Vec2(0, 0), Vec2(1, 0), Vec2(1 + s, w), Vec2(s, w)};
  const std::vector<Vec2> right = {Vec2(1, 0), Vec2(2, 0), Vec2(2 + s, w), Vec2(1 + s, w)};
  c.conditions = {condition("bottom", ThermalCondition::Type::Temperature, 1),
                  condition("top", ThermalCondition::Type::Convection, 50, -1)};
  ThermalRun a(thermal_scene({whole}, c, kRock));
  ThermalRun b(thermal_scene({left, right}, c, kRock));
  ASSERT_EQ(a.process->mesh().n_triangles(), b.process->mesh().n_triangles());
  EXPECT_EQ(a.process->mesh().n_triangles(), 16);
  a.run(1e3, 20);
  b.run(1e3, 20);
  double diff = 0;
  for (const Vec2& p : b.process->mesh().nodes)
    diff = std::max(diff, std::abs(a.temperature_at(p) - b.temperature_at(p)));
  EXPECT_LT(diff, 1e-12);
  std::printf("perfect contact: largest difference %.2e K\n", diff);
  EXPECT_GT(a.temperature_at(Vec2(1, 0.1)), 0.1);  // heat did cross the joint
}

// A contact conductance h_c between two bars of 1 m, T = 1 and 0 at the
// far ends, at steady state (one backward-Euler step of 1e20 s): q = 1 /
// (L1 / lambda + 1 / h_c + L2 / lambda), jump q / h_c. Each block holds a
// linear field, which P1 represents exactly: round-off tolerance.
TEST(thermal_conduction, ContactConductanceJump_h) {
  for (const bool lumped : {true, false}) {
    ThermalControls c = controls(0.1);
    c.lumped_capacity = lumped;
    c.perfect_contact = false;
    c.contact_conductance = 10;
    c.conditions = {condition("left", ThermalCondition::Type::Temperature, 1),
                    condition("right", ThermalCondition::Type::Temperature, 0)};
    ThermalRun run(thermal_scene({box(0, 0, 1, 0.3), box(1, 0, 2, 0.3)}, c, kRock));
    run.run(1e20, 1);
    const double q = 1 / (1 / kLambda + 1 / 10.0 + 1 / kLambda);
    const double jump =
        run.temperature_at(Vec2(1 - 1e-12, 0.15)) - run.temperature_at(Vec2(1 + 1e-12, 0.15));
    EXPECT_NEAR(jump, q / 10, 1e-9);
    std::printf("jump %.15f, closed form %.15f\n", jump, q / 10);
    EXPECT_NEAR(run.temperature_at(Vec2(0.5, 0.2)), 1 - q * 0.5 / kLambda, 1e-9);
  }
}

// A point source in the plane (a line source across it, verification.md
// (l), 2D form): Q' = 1 kW/m from t = 0 in a 60 m square (adiabatic sides
// 30 m away: E1(30^2 / 4 kappa t) ~ 1e-3 K at 1 year), dT = Q' / (4 pi
// lambda) E1(r^2 / 4 kappa t). Elements of 0.05 m at the source, growing by
// 0.2 r: r = 1, 2, 5 m are 4 or more elements from it. BDF2, 100 steps to a
// year. The catalogue's tolerance: 2 % beyond three elements.
TEST(thermal_conduction, LineSourceE1_l) {
  const ThermalControls c = line_source_controls(3, 0.05, 0.2, 0);
  ThermalRun run(thermal_scene({box(-30, -30, 30, 30)}, c, kRock));
  const double year = 365.25 * 86400;
  run.run(year / 100, 100);
  for (const double r : {1.0, 2.0, 5.0}) {
    const double exact =
        1000 / (4 * std::numbers::pi * kLambda) * -std::expint(-r * r / (4 * kKappa * year));
    for (const Vec2& direction : {Vec2(1, 0), Vec2(0.6, 0.8)}) {
      const double t = run.temperature_at(r * direction);
      EXPECT_NEAR(t, exact, 0.02 * exact) << "r = " << r;
      std::printf("r = %g m: %.4f K, E1 %.4f K, relative error %.2e\n", r, t, exact, t / exact - 1);
    }
  }
}

// Patch test: a linear field T = 5 + 20 x is the exact solution with its
// values on the left and right sides and its fluxes on the top and bottom
// (anisotropic lambda: heat flows across the gradient too); it stays so in
// every step, on the unstructured (and graded, around a source of zero
// power) mesh, lumped or consistent, BE or BDF2: round-off, 1e-10 K.
TEST(thermal_conduction, PatchTestLinearField) {
  const Eigen::Vector3d k(3, 2, 0.7);
  for (const bool lumped : {true, false}) {
    ThermalControls c = controls(0.2);
    c.lumped_capacity = lumped;
    c.scheme = lumped ? ThermalControls::Scheme::BackwardEuler : ThermalControls::Scheme::Bdf2;
    c.initial_temperature = 5;
    c.source_element_size = 0.02;
    HeatSource nothing;
    nothing.points = {Vec2(0.37, 0.61)};
    nothing.power = 0;
    nothing.path = "test";
    c.sources = {nothing};
    // The field T = 5 + 20 x: its values on the left and right sides, and
    // on the top and bottom the flux into the rock lambda grad T . n_out,
    // +-kxy 20 (the tensor's off-diagonal turns the gradient).
    c.gradient = Vec2(20, 0);
    c.conditions = {condition("left", ThermalCondition::Type::Temperature, 5),
                    condition("right", ThermalCondition::Type::Temperature, 25),
                    condition("top", ThermalCondition::Type::Flux, k[2] * 20),
                    condition("bottom", ThermalCondition::Type::Flux, -k[2] * 20)};
    ThermalRun run(thermal_scene({box(0, 0, 1, 1)}, c, ThermalMaterial{k, kRhoC}));
    run.run(1e4, 5);
    EXPECT_LT(max_error(run, [](const Vec2& x) { return 5 + 20 * x.x(); }), 1e-10);
  }
}

// A closed system: adiabatic blocks with a contact conductance between
// them, a point source with a decaying power and an area source. Per step
// the stored energy equals the supplied one to 1e-10 of it (the
// conductance and joint terms cancel exactly; what remains is the solver's
// round-off).
TEST(thermal_conduction, ClosedSystemBalancesEnergy) {
  ThermalControls c = controls(0.1);
  c.perfect_contact = false;
  c.contact_conductance = 100;
  HeatSource point, area;
  point.points = {Vec2(0.3, 0.5)};
  point.power = 200;
  point.factor.decay = {{0.7, 3e3}, {0.3, 3e4}};
  point.path = "test";
  area.shape = HeatSource::Shape::Area;
  area.points = {Vec2(1.2, 0.2), Vec2(1.6, 0.2), Vec2(1.6, 0.6), Vec2(1.2, 0.6)};
  area.power = 50;
  area.factor.history = {{0, 1}, {1e4, 0.5}};
  area.path = "test";
  c.sources = {point, area};
  ThermalRun run(thermal_scene({box(0, 0, 1, 1), box(1, 0, 2, 1)}, c, kRock));
  for (int k = 0; k < 10; ++k) {
    run.run(2e3, 1);
    const thermal::EnergyBalance& b = run.thermal().balance;
    EXPECT_GT(b.last_step_supplied, 0);
    EXPECT_NEAR(b.last_step_stored, b.last_step_supplied, 1e-10 * b.last_step_supplied);
    EXPECT_EQ(b.last_step_boundary, 0);
  }
  // The supplied energy is the discrete one: dt P(t_n+1) per step.
}

// Maximum principle: lumped capacity and backward Euler give an M-matrix on
// the Delaunay meshes, so a cold block heated from one side stays within
// [0, 1] for any step, from seconds to a century.
TEST(thermal_conduction, MaximumPrincipleForLargeSteps) {
  for (const double dt : {1.0, 1e4, 1e8, 3e9}) {
    ThermalControls c = controls(0.05);
    c.conditions = {condition("left", ThermalCondition::Type::Temperature, 1)};
    ThermalRun run(thermal_scene({box(0, 0, 1, 0.5), box(1, 0, 1.7, 0.5)}, c, kRock));
    for (int k = 0; k < 5; ++k) {
      run.run(dt, 1);
      for (const double t : run.thermal().temperature) {
        EXPECT_GE(t, -1e-12) << "dt = " << dt;
        EXPECT_LE(t, 1 + 1e-12) << "dt = " << dt;
      }
    }
  }
}

// An excavation's wall is a named boundary: a rock mass cut by two joint
// sets around a circular drift, the wall held at 1 degC, everything else
// adiabatic and at 0: the steady state (one backward-Euler step of 1e20 s)
// is 1 everywhere, across every joint (perfect contact): 1e-9.
TEST(thermal_conduction, ExcavationWallIsABoundary) {
  const Scene scene = read_scene_text(R"(
name: drift
physics: [thermal]
materials:
  - {name: rock, density: 2650, young_modulus: 50 GPa, poisson_ratio: 0.25}
rock_mass:
  domain: [[0, 0], [20, 0], [20, 20], [0, 20]]
  excavations:
    - {name: drift, circle: {centre: [10, 10], radius: 2, segments: 24}}
  material: rock
  joint_sets:
    - {name: a, dip: 60, spacing: 4 m}
    - {name: b, dip: 150, spacing: 5 m}
time: {end: 1}
thermal:
  materials: [{name: rock, conductivity: 3, heat_capacity: 2.4e6}]
  time_step: 1
  mesh: {element_size: 1}
  initial: {temperature: 0}
  conditions: [{boundary: drift, temperature: 1}]
)",
                                      "drift.yaml");
  ThermalRun run(scene);
  const std::vector<int>* wall = run.process->mesh().boundary("drift");
  ASSERT_TRUE(wall);
  EXPECT_GE(wall->size(), 24u);
  run.run(1e20, 1);
  for (const double t : run.thermal().temperature) EXPECT_NEAR(t, 1, 1e-9);
}

// With mechanics, heat crosses a joint only while its contact is closed: a
// block resting under gravity on a fixed base heated from below (closed,
// loaded contact), and the same block hanging under a fixed heated block,
// falling away from it (open from the first steps on). kappa = 1e6 m^2/s
// makes heat cross 1 m in microseconds: a closed joint brings the block to
// the heated side's 100 degC within the 0.1 s run (1e-6: steady to
// round-off after the first steps), an open one leaves it at its initial 0.
double lower_block_warming(bool falls) {
  const std::string heated =
      falls ? "[[0, 1], [1, 1], [1, 2], [0, 2]]" : "[[0, -1], [1, -1], [1, 0], [0, 0]]";
  const std::string text = R"(
name: joint_opens
physics: [mechanics, thermal]
gravity: [0, -9.8]
materials:
  - {name: rock, density: 2700, young_modulus: 10 GPa, poisson_ratio: 0.25}
joints:
  - {name: joint, friction_angle: 30}
blocks:
  - {name: lower, vertices: [[0, 0], [1, 0], [1, 1], [0, 1]]}
  - {name: heated, fixed: true, vertices: )" +
                           heated + R"(}
mechanics:
  dda: {time_step: 1 ms}
time: {end: 0.1}
output: {hdf5: false}
thermal:
  materials: [{name: rock, conductivity: 1e4, heat_capacity: 1e-2}]
  mesh: {element_size: 0.25}
  initial: {temperature: 0}
  joints: {conductance: perfect}
  conditions: [{boundary: )" +
                           std::string(falls ? "top" : "bottom") + R"(, temperature: 100}]
)";
  const RunResult r =
      run_scene(read_scene_text(text, "joint_opens.yaml"), falls ? "joint_opens" : "joint_stays");
  EXPECT_EQ(r.summary.status, "completed");
  return thermal_state(r).block_temperature_change[0];
}

TEST(thermal_conduction, HeatCrossesClosedJointsOnly) {
  const double closed = lower_block_warming(false), open = lower_block_warming(true);
  EXPECT_NEAR(closed, 100, 1e-6);
  // The mechanics moves first in a coupling step: the joint is open at the
  // first thermal step already.
  EXPECT_LT(std::abs(open), 1e-9);
  std::printf("lower block: +%.6g K resting, +%.6g K falling away\n", closed, open);
}

// The thermal process owns the linear thermal expansion: it publishes, per
// block, the free strain alpha_T dT of the block's material (the field
// block_thermal_strain), dT the block's mean temperature change. Two blocks
// of two materials (alpha_T = 1e-5 and 0 1/K) in perfect contact, every
// exterior side held at 100 degC from 0 degC, kappa = 1e6 m^2/s: after ten
// steps of 1 ms both blocks are at +100 K to round-off (backward Euler
// leaves 1 / (1 + lambda dt) ~ 1e-4 of the slowest mode per step: 1e-40).
TEST(thermal_conduction, PublishesEachBlocksFreeThermalStrain) {
  const Scene scene = read_scene_text(R"(
name: expansion
physics: [thermal]
gravity: [0, 0]
materials:
  - {name: expanding, density: 2700, young_modulus: 10 GPa, poisson_ratio: 0.25}
  - {name: rigid, density: 2700, young_modulus: 10 GPa, poisson_ratio: 0.25}
blocks:
  - {name: a, material: expanding, vertices: [[0, 0], [1, 0], [1, 1], [0, 1]]}
  - {name: b, material: rigid, vertices: [[1, 0], [2, 0], [2, 1], [1, 1]]}
time: {end: 0.01}
output: {hdf5: false}
thermal:
  materials:
    - {name: expanding, conductivity: 1e4, heat_capacity: 1e-2, thermal_expansion: 1e-5 1/K}
    - {name: rigid, conductivity: 1e4, heat_capacity: 1e-2}
  time_step: 1 ms
  mesh: {element_size: 0.25}
  initial: {temperature: 0}
  conditions: [{boundary: exterior, temperature: 100}]
)",
                                      "expansion.yaml");
  ThermalRun run(scene);
  run.run(1e-3, 10);
  const std::vector<double>& change = run.thermal().block_temperature_change;
  const std::vector<double>& strain = run.state.fields.get(kBlockThermalStrain);
  ASSERT_EQ(strain.size(), 2u);
  EXPECT_NEAR(change[0], 100, 1e-9);
  EXPECT_NEAR(change[1], 100, 1e-9);
  EXPECT_EQ(strain[0], 1e-5 * change[0]);  // one product: exact
  EXPECT_EQ(strain[1], 0.0);               // alpha_T = 0: no thermal strain
  std::printf("block a: dT %.12g K, strain %.12g; block b: dT %.12g K, strain %g\n", change[0],
              strain[0], change[1], strain[1]);
}

// T -> M through the coordinator: a free block (no gravity, no support) of
// E = 10 GPa, nu = 0.25, alpha_T = 1e-5 1/K, its sides held at 100 degC
// from 0 degC (kappa = 1e6 m^2/s: +100 K after the first thermal step),
// static DDA (k01 = 0) in plane strain. It expands freely: both in-plane
// strains (1 + nu) alpha_T dT = 1.25e-3, no in-plane stress. The mechanics'
// steps of 1 ms settle it by the ratio of the inertia term 2M/dt^2 to the
// stiffness, ~0.05 per step, so after the ten steps it is at rest to ~1e-10:
// 1e-6, verification.md (m)'s bound for the free block, holds.
TEST(thermal_conduction, HeatedFreeBlockExpandsByItsMaterialsThermalStrain) {
  const Scene scene = read_scene_text(R"(
name: free_expansion
physics: [mechanics, thermal]
gravity: [0, 0]
materials:
  - {name: rock, density: 2700, young_modulus: 10 GPa, poisson_ratio: 0.25}
joints:
  - {name: joint, friction_angle: 30}
blocks:
  - {name: block, vertices: [[0, 0], [1, 0], [1, 1], [0, 1]]}
mechanics:
  dda: {time_step: 1 ms, velocity_carry_over: 0}
time: {end: 0.01}
output: {hdf5: false}
thermal:
  materials:
    - {name: rock, conductivity: 1e4, heat_capacity: 1e-2, thermal_expansion: 1e-5 1/K}
  mesh: {element_size: 0.25}
  initial: {temperature: 0}
  conditions: [{boundary: exterior, temperature: 100}]
)",
                                      "free_expansion.yaml");
  const RunResult r = run_scene(scene, "free_expansion");
  ASSERT_EQ(r.summary.status, "completed") << r.summary.message;
  const Block& b = r.state.blocks[0];
  const double e = (1 + 0.25) * 1e-5 * 100;
  EXPECT_NEAR(b.strain(0), e, 1e-6 * e);
  EXPECT_NEAR(b.strain(1), e, 1e-6 * e);
  EXPECT_NEAR(b.strain(2), 0, 1e-6 * e);
  const double stress_scale = 10e9 * 1e-5 * 100;  // E alpha_T dT
  EXPECT_NEAR(b.stress(0), 0, 1e-6 * stress_scale);
  EXPECT_NEAR(b.stress(1), 0, 1e-6 * stress_scale);
  std::printf("strains %.9g %.9g (expected %.9g), stresses %.3g %.3g Pa\n", b.strain(0),
              b.strain(1), e, b.stress(0), b.stress(1));
}

}  // namespace
}  // namespace fissure::testing
