#include "tests/support/convection_runs.h"

#include <gtest/gtest.h>

#include <fmt/format.h>
#include <algorithm>
#include <cmath>

#include "thermal/convection/fracture_fluid_grid.h"

namespace fissure::testing {

std::string fracture_scene(double length, double thickness, double element, double pressure_drop,
                           const std::string& nusselt, double inlet) {
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

double lauwerier(double x, double t) {
  return std::erfc(x * std::sqrt(kLauwerierLambda * kLauwerierRockRhoC) /
                   (kLauwerierFluidRhoC * kLauwerierFlux * std::sqrt(t - x / kLauwerierVelocity)));
}

ConvectionRun::ConvectionRun(Scene s)
    : scene(std::move(s)),
      state(RockMass::from_scene(scene)),
      flow(std::make_unique<flow::CubicLawProcess>(scene)),
      thermal(std::make_unique<thermal::ThermalProcess>(scene)) {
  flow->initialize(state);
  thermal->initialize(state);
}

void ConvectionRun::run(double dt, int steps) {
  for (int k = 0; k < steps; ++k) {
    ASSERT_EQ(thermal->advance(state, state.time, dt).status, StepReport::Status::Ok);
    state.time += dt;
  }
}

const thermal::ThermalState& ConvectionRun::s() const {
  return thermal->inner_state();
}

double ConvectionRun::fluid_at(double x) const {
  const thermal::FluidGrid& g = thermal->fluid()->grid();
  for (const thermal::FluidPiece& p : g.pieces) {
    const double x0 = g.positions[p.from].x(), x1 = g.positions[p.to].x();
    if (std::min(x0, x1) <= x && x <= std::max(x0, x1))
      return s().fluid_temperature[p.from] +
             (x - x0) / (x1 - x0) * (s().fluid_temperature[p.to] - s().fluid_temperature[p.from]);
  }
  return std::nan("");
}

}  // namespace fissure::testing
