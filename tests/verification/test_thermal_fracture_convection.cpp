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

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "coupling/process_registry.h"
#include "flow/cubic_law/cubic_law_process.h"
#include "rockmass/fields/fracture_flow.h"
#include "rockmass/fields/fracture_temperature.h"
#include "rockmass/fracture_graph.h"
#include "thermal/conduction/thermal_process.h"

namespace fissure {
namespace {

constexpr double kLambda = 2.5, kRhoC = 2760.0 * 900.0, kFluidRhoC = 1000.0 * 4200.0;
constexpr double kFlux = 1e-5, kVelocity = 0.01;

/// Two blocks of rock above and below the fracture y = 0, x in [0, length],
/// `thickness` each; the water enters on the left at `inlet` (degC), the
/// rock starts at 0.
std::string fracture_scene(double length, double thickness, double element, double pressure_drop,
                           const std::string& nusselt, double inlet = 1) {
  return fmt::format(R"(name: lauwerier
physics: [flow, thermal]
materials:
  - {{name: rock, density: 2760 kg/m^3, young_modulus: 50 GPa, poisson_ratio: 0.25}}
blocks:
  - {{name: below, vertices: [[0, {t0}], [{l}, {t0}], [{l}, 0], [0, 0]]}}
  - {{name: above, vertices: [[0, 0], [{l}, 0], [{l}, {t}], [0, {t}]]}}
flow:
  fluid: {{density: 1000 kg/m^3, viscosity: 1e-3 Pa*s}}
  apertures: {{initial: 1 mm}}
  conditions:
    - {{boundary: left, pressure: {p} Pa}}
    - {{boundary: right, pressure: 0 Pa}}
thermal:
  materials:
    - {{name: rock, conductivity: 2.5 W/m/K, specific_heat: 900 J/kg/K}}
  mesh: {{element_size: {h} m}}
  time_step: 1e4 s
  initial: {{temperature: 0}}
  convection:
    nusselt: {nu}
    fluid: {{density: 1000 kg/m^3, specific_heat: 4200 J/kg/K, conductivity: 0.6 W/m/K}}
    inlets:
      - {{boundary: left, temperature: {inlet}}}
time:
  end: 1e6 s
)",
                     fmt::arg("l", length), fmt::arg("t", thickness), fmt::arg("t0", -thickness),
                     fmt::arg("h", element), fmt::arg("p", pressure_drop), fmt::arg("nu", nusselt),
                     fmt::arg("inlet", inlet));
}

/// The flow solved once at the start, then thermal steps only.
struct ConvectionRun {
  explicit ConvectionRun(Scene s)
      : scene(std::move(s)),
        state(RockMass::from_scene(scene)),
        flow(std::make_unique<flow::CubicLawProcess>(scene)),
        thermal(std::make_unique<thermal::ThermalProcess>(scene)) {
    flow->initialize(state);
    thermal->initialize(state);
  }
  void run(double dt, int steps) {
    for (int k = 0; k < steps; ++k) {
      ASSERT_EQ(thermal->advance(state, state.time, dt).status, StepReport::Status::Ok);
      state.time += dt;
    }
  }
  const thermal::ThermalState& s() const { return state.fields.get(thermal::kThermalState); }
  /// The water's temperature at x on the fracture y = 0 (linear between
  /// its nodes).
  double fluid_at(double x) const {
    const thermal::FluidGrid& g = thermal->fluid()->grid();
    for (const thermal::FluidPiece& p : g.pieces) {
      const double x0 = g.positions[p.from].x(), x1 = g.positions[p.to].x();
      if (std::min(x0, x1) <= x && x <= std::max(x0, x1))
        return s().fluid_temperature[p.from] +
               (x - x0) / (x1 - x0) * (s().fluid_temperature[p.to] - s().fluid_temperature[p.from]);
    }
    return std::nan("");
  }

  Scene scene;
  RockMass state;
  std::unique_ptr<flow::CubicLawProcess> flow;
  std::unique_ptr<thermal::ThermalProcess> thermal;
};

double lauwerier(double x, double t) {
  return std::erfc(x * std::sqrt(kLambda * kRhoC) /
                   (kFluidRhoC * kFlux * std::sqrt(t - x / kVelocity)));
}

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
    previous_worst = worst;
  }
}

}  // namespace
}  // namespace fissure
