// Heat carried by the water in the fractures (theory.md 4.2, docs/thermal.md
// 7) against verification.md (i), Lauwerier's single fracture: water at
// T_in = 1 enters a straight fracture (full aperture b = 1 mm, v = 0.01
// m/s, so Q = b v = 1e-5 m^2/s) between two rock blocks initially at 0; the
// rock conducts across the fracture only (the tensor [0, lambda, 0]:
// verification.md's strict test) and the water has its walls' temperature
// (h -> infinity). Reference at t = 1e6 s:
//   theta_f = erfc(x sqrt(lambda rho_r c_r) / (rho_f c_f Q sqrt(t - x/v))).
// The flow field is the real flow process's: heads giving 120 Pa/m over the
// 20 m fracture, solved once when it starts (the steps below advance the
// thermal process only, so the water's viscosity stays 1e-3 Pa s and Q
// stays 1e-5 m^2/s; the flow would otherwise take mu(T) from the water's
// temperature, as it does in a coupled run). Also: the energy the water
// gives is the energy the rock receives, and a front at a Peclet number of
// 1e3 without overshoot.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>

#include "coupling/process_registry.h"
#include "flow/cubic_law/cubic_law_process.h"
#include "rockmass/fields/fracture_flow.h"
#include "rockmass/fields/fracture_temperature.h"
#include "rockmass/fracture_graph.h"
#include "tests/support/convection_runs.h"
#include "tests/support/run_scene.h"
#include "thermal/conduction/thermal_process.h"

namespace fissure {
namespace {

using testing::ConvectionRun;
using testing::fracture_scene;
using testing::lauwerier;
constexpr double kLambda = testing::kLauwerierLambda, kRhoC = testing::kLauwerierRockRhoC,
                 kFluidRhoC = testing::kLauwerierFluidRhoC;
constexpr double kFlux = testing::kLauwerierFlux;

TEST(ThermalFractureConvection, ReferenceValuesOfCase_i) {
  // verification.md (i)'s table, and how little the water's storage
  // (t - x/v instead of t) changes it at 1e6 s.
  const double x[] = {2, 5, 10, 15}, theta[] = {0.86671, 0.67474, 0.40118, 0.20782};
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(lauwerier(x[k], 1e6), theta[k], 1e-5);
    const double without_storage =
        std::erfc(x[k] * std::sqrt(kLambda * kRhoC) / (kFluidRhoC * kFlux * std::sqrt(1e6)));
    std::printf("x = %g m: theta %.5f, without storage %.5f\n", x[k], theta[k], without_storage);
  }
}

// (i): 2 x 4 m of rock (4 sqrt(kappa t) = 4.0 m), a 20 m fracture, the
// wall-temperature limit, the strict test: conduction across the fracture
// only. Two meshes, h = 0.5 and 0.25 m with dt = 2e4 and 1e4 s (backward
// Euler: errors O(h^2 / kappa t) + O(dt / t) in the boundary layer of
// sqrt(kappa t) = 1 m).
TEST(ThermalFractureConvection, Lauwerier_i) {
  const double x[] = {2, 5, 10, 15};
  double previous_worst = 1;
  const std::string dir = testing::scratch_dir("thermal_fracture_convection");
  for (const auto& [h, dt] : {std::pair{0.5, 2e4}, std::pair{0.25, 1e4}}) {
    Scene scene =
        read_scene_text(fracture_scene(20, 4, h, 2400, "wall_temperature"), "lauwerier.yaml");
    thermal_controls(scene).materials[0].conductivity = Eigen::Vector3d(0, kLambda, 0);
    ConvectionRun run(std::move(scene));
    ASSERT_NEAR(std::abs(run.state.fields.get(kFractureFlow).flux.at(0)), kFlux, 1e-12 * kFlux);
    run.run(dt, static_cast<int>(std::lround(1e6 / dt)));
    double worst = 0;
    for (const double xk : x) {
      const double theta = run.fluid_at(xk), exact = lauwerier(xk, 1e6);
      std::printf("h = %g m, dt = %g s: x = %g m: theta_f %.5f, Lauwerier %.5f, error %+.5f\n", h,
                  dt, xk, theta, exact, theta - exact);
      EXPECT_NEAR(theta, exact, 0.02) << "h = " << h << " m, x = " << xk << " m";
      worst = std::max(worst, std::abs(theta - exact));
    }
    EXPECT_LT(worst, previous_worst) << "the error grows as the mesh is refined";
    // The profile along the fracture, for the figure of docs/thermal.md 7
    // (scripts/plot_lauwerier.py).
    std::ofstream csv(dir + fmt::format("/lauwerier_h{}.csv", h));
    csv << "x,theta_f,lauwerier\n";
    const thermal::FluidGrid& g = run.thermal->fluid()->grid();
    std::vector<std::pair<double, double>> profile;
    for (int i = 0; i < g.n_nodes(); ++i)
      profile.emplace_back(g.positions[i].x(), run.s().fluid_temperature[i]);
    std::sort(profile.begin(), profile.end());
    for (const auto& [xi, theta] : profile)
      csv << fmt::format("{:.6f},{:.8f},{:.8f}\n", xi, theta, xi > 0 ? lauwerier(xi, 1e6) : 1.0);
    // One steady flow, one step length: one factorization for all steps.
    EXPECT_EQ(run.thermal->statistics()["factorizations"], 1);
    previous_worst = worst;
  }
}

// The heat transfer coefficient's limit: Nu -> infinity approaches the
// wall-temperature limit (h = Nu lambda_f / 2e = 300 Nu W/(m^2 K) here;
// the rock's own conductance over an element, lambda / h = 5 W/(m^2 K), is
// far below it already at Nu = 8.23).
TEST(ThermalFractureConvection, LargeNusseltTendsToTheWallTemperature) {
  const auto theta_at_10 = [](const std::string& nusselt) {
    Scene scene = read_scene_text(fracture_scene(20, 4, 0.5, 2400, nusselt), "lauwerier.yaml");
    thermal_controls(scene).materials[0].conductivity = Eigen::Vector3d(0, kLambda, 0);
    ConvectionRun run(std::move(scene));
    run.run(2e4, 50);
    return run.fluid_at(10);
  };
  const double wall = theta_at_10("wall_temperature");
  double previous = 1;
  for (const char* nu : {"8.23", "1000", "100000"}) {
    const double difference = std::abs(theta_at_10(nu) - wall);
    std::printf("Nu = %s: theta_f(10 m) differs from the wall-temperature limit by %.3e\n", nu,
                difference);
    EXPECT_LT(difference, previous);
    previous = difference;
  }
  // Nu = 1e5: h = 3e7 W/(m^2 K), 6e6 times the rock's element conductance.
  EXPECT_LT(previous, 1e-5);
}

/// Per step, the heat the water gave (its exchange integrals) against what
/// the rock stored (with BDF2 its difference: the stored change and the
/// correction, docs/thermal.md 5), and the water's own balance; relative to
/// the step's exchange.
void expect_step_balances(const ConvectionRun& run) {
  const thermal::EnergyBalance& b = run.s().balance;
  const double exchanged = b.last_step_fluid.exchanged;
  ASSERT_GT(std::abs(exchanged), 0);
  EXPECT_NEAR(b.last_step_stored + b.last_step_bdf2_correction, exchanged,
              1e-10 * std::abs(exchanged));
  EXPECT_NEAR(b.last_step_fluid.carried(), -exchanged, 1e-10 * std::abs(exchanged));
  EXPECT_NEAR(b.last_step_residual(), 0, 1e-10 * b.last_step_fluid.advected_in);
}

// Energy: the rock is insulated (no condition: adiabatic), so all the heat
// it gains is what the water gave it, and the water's balance is storage,
// what the flow carries in and out, and the exchange. Nu = 8.23 (the
// exchange is its own integrals, not a difference), both capacities
// (trapezoidal and Gauss exchange), isotropic rock; backward Euler, and
// BDF2 with growing steps (its balance holds the correction of section 5).
TEST(ThermalFractureConvection, TheWaterGivesWhatTheRockReceives) {
  for (const bool bdf2 : {false, true})
    for (const char* capacity : {"lumped", "consistent"}) {
      SCOPED_TRACE(std::string(capacity) + (bdf2 ? ", bdf2" : ", backward Euler"));
      Scene scene = read_scene_text(fracture_scene(20, 4, 0.5, 2400, "8.23", 100), "energy.yaml");
      thermal_controls(scene).lumped_capacity = std::string(capacity) == "lumped";
      if (bdf2) thermal_controls(scene).scheme = ThermalControls::Scheme::Bdf2;
      ConvectionRun run(std::move(scene));
      for (int k = 0; k < 20; ++k) {
        run.run(bdf2 ? 1e4 * (1 + k % 4) : 5e4, 1);
        expect_step_balances(run);
      }
      const thermal::EnergyBalance& b = run.s().balance;
      std::printf(
          "%s%s: stored in the rock %.6e J/m (bdf2_correction %.3e), given by the water "
          "%.6e J/m, residual %.2e J/m\n",
          capacity, bdf2 ? ", BDF2" : "", b.stored, b.bdf2_correction, b.fluid.exchanged,
          b.residual());
      EXPECT_NEAR(b.stored + b.bdf2_correction, b.fluid.exchanged, 1e-10 * b.fluid.exchanged);
      EXPECT_NEAR(b.residual(), 0, 1e-10 * b.fluid.advected_in);
    }
}

// Stability: a hot front (100 degC into rock at 0) at a Peclet number
// rho_f c_f Q / lambda_r = 1e3 (Q = 5.95e-4 m^2/s, v = 0.6 m/s; the rock
// conducts along the fracture too): upwinding keeps every temperature of
// the water and the rock within [0, 100] to 1 % of the range at every step,
// with steps from 3 s (the water crosses 1/10 of the fracture per step) to
// 3000 s, 30 steps each; both Nu = 8.23 and the wall-temperature limit.
TEST(ThermalFractureConvection, NoOvershootAtPeclet1000) {
  const double q = 1e3 * kLambda / kFluidRhoC;
  const double drop = 12 * 1e-3 * q * 20 / 1e-9;  // the cubic law's pressure drop over 20 m
  for (const char* nusselt : {"8.23", "wall_temperature"}) {
    for (const double dt : {3.0, 30.0, 3000.0}) {
      SCOPED_TRACE(std::string(nusselt) + ", dt = " + std::to_string(dt));
      ConvectionRun run(
          read_scene_text(fracture_scene(20, 4, 0.5, drop, nusselt, 100), "peclet.yaml"));
      ASSERT_NEAR(std::abs(run.state.fields.get(kFractureFlow).flux.at(0)), q, 1e-9 * q);
      double lowest = 0, highest = 0;
      for (int k = 0; k < 30; ++k) {
        run.run(dt, 1);
        for (const std::vector<double>* t : {&run.s().temperature, &run.s().fluid_temperature})
          for (const double v : *t) lowest = std::min(lowest, v), highest = std::max(highest, v);
      }
      std::printf("Nu %s, dt = %g s: temperatures in [%.3e, %.6f] degC; water at 10 m %.3f\n",
                  nusselt, dt, lowest, highest, run.fluid_at(10));
      EXPECT_GE(lowest, -1.0);
      EXPECT_LE(highest, 101.0);
      EXPECT_GT(highest, 50.0);  // the front is in the fracture
    }
  }
}

// Fractures with no block face on either side (the flow's own traces, which
// the block meshes do not follow) and a dead end (the branch at x = 5, which
// carries no flow): the water only advects and stores. Its front reaches the
// outlet and the water there tends to the inlet temperature; nothing reaches
// the rock; the water's balance (in = out + stored) holds to round-off.
TEST(ThermalFractureConvection, SegmentsWithoutWallsOrFlowOnlyAdvect) {
  ConvectionRun run(read_scene_text(R"(name: traces
physics: [flow, thermal]
materials:
  - {name: rock, density: 2760 kg/m^3, young_modulus: 50 GPa, poisson_ratio: 0.25}
blocks:
  - {name: a, vertices: [[0, 0], [10, 0], [10, 10], [0, 10]]}
flow:
  network:
    source: traces
    traces:
      - {from: [0, 5], to: [10, 5], aperture: 0.1 mm}
      - {from: [5, 2], to: [5, 8], aperture: 0.1 mm}
  conditions:
    - {boundary: left, pressure: 1 MPa}
    - {boundary: right, pressure: 0}
thermal:
  materials:
    - {name: rock, conductivity: 3 W/m/K, specific_heat: 900 J/kg/K}
  mesh: {element_size: 0.5 m}
  time_step: 100 s
  initial: {temperature: 10}
  convection:
    inlets: [{boundary: left, temperature: 50}]
time:
  end: 1 d
)",
                                    "traces.yaml"));
  run.run(100, 100);
  EXPECT_EQ(run.thermal->statistics()["fracture_fluid"]["segments_without_walls"], 4);
  const thermal::EnergyBalance& b = run.s().balance;
  EXPECT_EQ(b.fluid.exchanged, 0);
  EXPECT_NEAR(b.fluid.carried(), 0, 1e-12 * b.fluid.advected_in);
  EXPECT_NEAR(run.s().fluid_temperature.at(run.thermal->fluid()->grid().fluid_node_of_graph.at(
                  run.state.fields.get(kFractureGraph).boundary_nodes.at("right").at(0))),
              50, 1e-6);
  for (const double t : run.s().fluid_temperature) {
    EXPECT_GE(t, 10);
    EXPECT_LE(t, 50 + 1e-12);
  }
  for (const double t : run.s().temperature) EXPECT_NEAR(t, 10, 1e-9);
}

}  // namespace
}  // namespace fissure
