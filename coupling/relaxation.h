// Relaxation of the exchanged values between the passes of the iterated
// staggered scheme (theory.md 6.1): x^{k+1} = x^k + omega_k r^k with the
// residual r^k = x~^{k+1} - x^k (x~: what the pass produced from x^k).
// Fixed: omega_k = omega_0. Aitken (Irons and Tuck; Kuettler and Wall 2008):
// omega_k = -omega_{k-1} (r^{k-1})^T (r^k - r^{k-1}) / |r^k - r^{k-1}|^2,
// clipped to [0.05, 1]; it is the secant step of the fixed point, exact
// in one update for a scalar linear coupling. The residuals in omega are
// normalized, each by its field's tolerance (field_convergence.h): a field
// in Pa would otherwise decide omega for one in m.
#pragma once

#include <span>
#include <vector>

#include "core/scene/scene.h"

namespace fissure {

class Relaxation {
 public:
  explicit Relaxation(const CouplingSettings::Iteration& controls);

  /// A new coupling step: omega_0 again, no previous residual.
  void reset();

  /// x += omega r, with omega updated first from r and the previous
  /// residual (Aitken), each residual divided by its `scale` (its field's
  /// tolerance) so that no field's unit weighs on omega. x, r and scale
  /// have the same size.
  void relax(std::span<double> x, std::span<const double> r, std::span<const double> scale);

  double omega() const { return omega_; }

  static constexpr double kMinOmega = 0.05, kMaxOmega = 1;

 private:
  CouplingSettings::Iteration controls_;
  double omega_ = 1;
  std::vector<double> previous_;  ///< r^{k-1} / scale; empty before the first update
};

}  // namespace fissure
