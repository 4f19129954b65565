// The fracture-convection set-up of verification.md (i), Lauwerier's
// single fracture, built in code for the tests and the benchmarks: water
// entering a straight fracture between two rock blocks, the real flow
// process solved once at the start, then thermal steps only.
#pragma once

#include <memory>
#include <string>

#include "core/scene/scene.h"
#include "core/state/rock_mass.h"
#include "flow/cubic_law/cubic_law_process.h"
#include "thermal/conduction/thermal_process.h"

namespace fissure::testing {

/// The rock and the water of (i): lambda_r, rho_r c_r, rho_f c_f; the flux
/// and velocity of a 1 mm fracture with 120 Pa/m.
constexpr double kLauwerierLambda = 2.5, kLauwerierRockRhoC = 2760.0 * 900.0,
                 kLauwerierFluidRhoC = 1000.0 * 4200.0;
constexpr double kLauwerierFlux = 1e-5, kLauwerierVelocity = 0.01;

/// Two blocks of rock above and below the fracture y = 0, x in [0, length],
/// `thickness` each; the water enters on the left at `inlet` (degC), the
/// rock starts at 0.
std::string fracture_scene(double length, double thickness, double element, double pressure_drop,
                           const std::string& nusselt, double inlet = 1);

/// Lauwerier's water temperature at x and t (theta_f, with the water's
/// storage: t - x / v).
double lauwerier(double x, double t);

/// The flow solved once at the start, then thermal steps only.
struct ConvectionRun {
  explicit ConvectionRun(Scene s);
  /// `steps` thermal steps of dt (each must be accepted).
  void run(double dt, int steps);
  const thermal::ThermalState& s() const;
  /// The water's temperature at x on the fracture y = 0 (linear between
  /// its nodes); NaN off it.
  double fluid_at(double x) const;

  Scene scene;
  RockMass state;
  std::unique_ptr<flow::CubicLawProcess> flow;
  std::unique_ptr<thermal::ThermalProcess> thermal;
};

}  // namespace fissure::testing
