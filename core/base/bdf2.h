// The variable-step BDF2 coefficients, written once for every process that
// integrates in time with it (the flow's transient integrator, the thermal
// process, the continuum). With the step ratio w = dt_n / dt_{n-1}, the
// two-step backward differentiation formula on the nonuniform grid
// t_{n-1}, t_n, t_{n+1} = t_n + dt_n is
//   a0 y_{n+1} - a1 y_n + a2 y_{n-1} = dt_n f(t_{n+1}, y_{n+1}),
//   a0 = (1 + 2w) / (1 + w),  a1 = 1 + w,  a2 = w^2 / (1 + w)
// (Hairer, Norsett & Wanner, Solving ODEs I, 2nd ed., III.5, variable-step
// BDF; Becker 1998, "A second order backward difference method with
// variable steps for a parabolic problem", BIT 38). a0 - a1 + a2 = 0: a
// constant is a solution of y' = 0. w = 1 gives the fixed-step 3/2, 2, 1/2.
#pragma once

namespace fissure {

struct Bdf2Coefficients {
  double a0 = 1, a1 = 1, a2 = 0;  ///< the default: backward Euler (the first step)
};

/// The coefficients for the step ratio w = dt_n / dt_{n-1} > 0.
constexpr Bdf2Coefficients bdf2_coefficients(double w) {
  return {(1 + 2 * w) / (1 + w), 1 + w, w * w / (1 + w)};
}

}  // namespace fissure
