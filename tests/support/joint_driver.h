// Drives one joint law of rockmass/joints/ as a direct shear test does:
// prescribed shear steps, with each step's normal displacement solved so
// that the normal stress after the step is what the test's boundary asks
// for (a constant normal stress, or a spring of constant normal stiffness).
// docs/joints.md section 5.
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

#include "rockmass/joints/joint_step.h"

namespace fissure::testing {

template <class Law>
struct JointStep {
  typename Law::State state;
  joints::JointResponse response;
  double normal_increment = 0;  ///< the du_n the boundary called for, m
};

/// One step of shear `shear` (m) from `before`, with the normal increment
/// x for which sigma_n(x) = target(x), to 1e-13 of the stress scale:
/// sigma_n falls as the walls open, so the root is bracketed from x = 0 in
/// the direction the tangent normal stiffness gives, then found by the
/// Illinois variant of regula falsi (exact in one update where the law is
/// linear in x, and safe across its corners: slip, opening). `target` is a
/// function of x (Pa) that does not fall as x grows.
template <class Law, class Target>
JointStep<Law> servo_step(const Law& law, const typename Law::State& before, double shear,
                          Target target, double length = 1) {
  JointStep<Law> s;
  const auto residual = [&](double x) {
    s.response = law.update(before, joints::JointIncrement{x, shear, length}, s.state);
    s.normal_increment = x;
    return s.response.normal_stress - target(x);
  };
  const double scale = std::max(std::abs(target(0.0)), 1.0), tolerance = 1e-13 * scale;
  double a = 0, ga = residual(a);
  if (std::abs(ga) <= tolerance) return s;
  // d sigma_n / dx = -k_n: the first step from the tangent (1 GPa/m when open).
  double step = ga / (s.response.normal_stiffness > 0 ? s.response.normal_stiffness : 1e9);
  double b = a + step, gb = residual(b);
  for (int n = 0; n < 100 && (ga > 0) == (gb > 0) && std::abs(gb) > tolerance; ++n) {
    a = b;
    ga = gb;
    step *= 2;
    b = a + step;
    gb = residual(b);
  }
  int side = 0;  // which end the last updates kept (Illinois: halve its value)
  for (int n = 0; n < 200 && std::abs(gb) > tolerance; ++n) {
    const double c = b - gb * (b - a) / (gb - ga), gc = residual(c);
    if ((gc > 0) == (gb > 0)) {
      b = c;
      gb = gc;
      if (side == -1) ga /= 2;
      side = -1;
    } else {
      a = b;
      ga = gb;
      b = c;
      gb = gc;
      side = 1;
    }
  }
  if (std::abs(gb) > tolerance || s.normal_increment != b) residual(b);
  if (std::abs(gb) > tolerance)
    throw std::runtime_error("servo_step: no normal displacement meets the target (residual " +
                             std::to_string(gb) + " Pa)");
  return s;
}

/// A step at the constant normal stress `sigma` (Pa).
template <class Law>
JointStep<Law> constant_stress_step(const Law& law, const typename Law::State& before, double shear,
                                    double sigma, double length = 1) {
  return servo_step(
      law, before, shear, [sigma](double) { return sigma; }, length);
}

}  // namespace fissure::testing
