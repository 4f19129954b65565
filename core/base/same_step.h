// When two step sizes are the same step for a factorization. The
// coordinator lands on output frames and coupling intervals with a step
// t_frame - t, a difference of times that carry the round-off of every step
// added into them: 1.5e-12 of dt after 1,400 steps of configs/continuum_mandel.yaml,
// up to about n eps t / dt after n steps in the worst case. A process whose
// matrix depends on dt (the thermal process, the continuum) keeps its factor
// for such a step and takes the step with the factor's dt; every later term
// (loads, energy balances) uses that dt, so the balances stay exact. The
// step then ends at most 1e-9 of a step's change away from the asked end,
// far below the solvers' tolerances (1e-10 of the solution) and the
// discretization error. Comparing with ==, the Mandel run factorized 41
// times instead of twice (issue 41).
#pragma once

#include <cmath>

namespace fissure {

/// The largest relative difference of two step sizes (or of two matrix
/// coefficients a0 / dt) that are the same step.
constexpr double kSameStepTolerance = 1e-9;

/// Whether the factor made for `held` serves a step of `asked`.
inline bool same_step(double held, double asked) {
  return std::abs(asked - held) <= kSameStepTolerance * std::abs(asked);
}

}  // namespace fissure
