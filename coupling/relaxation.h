// Relaxation of the exchanged values between the passes of the iterated
// staggered scheme (theory.md 6.1): x^{k+1} = x^k + omega_k r^k with the
// residual r^k = x~^{k+1} - x^k (x~: what the pass produced from x^k).
// Fixed: omega_k = omega_0. Aitken (Irons and Tuck; Kuettler and Wall 2008):
// omega_k = -omega_{k-1} (r^{k-1})^T (r^k - r^{k-1}) / |r^k - r^{k-1}|^2,
// clipped to [0.05, 1]; it is the secant step of the fixed point, exact
// in one update for a scalar linear coupling. The residuals in omega are
// normalized, each by its field's tolerance (field_convergence.h): a field
// in Pa would otherwise decide omega for one in m.
// Quasi-Newton (IQN-ILS, Degroote, Bathe and Vierendeels 2009): the
// Jacobian of the pass, learnt from the step's earlier passes as the
// differences of their residuals V and outputs W, x^{k+1} = x~^k + W c with
// c the least-squares solution of V c = -r^k (residuals normalized as
// Aitken's). For a linear coupling it is GMRES on the interface: where
// many modes contract at different rates (a block region tied to a
// continuum, docs/architecture.md 5), one omega cannot serve them all.
#pragma once

#include <Eigen/Dense>
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
  /// The passes quasi-Newton learns from (the latest).
  static constexpr std::size_t kMostColumns = 200;

 private:
  void quasi_newton(std::span<double> x, std::span<const double> r,
                    const std::vector<double>& normalized);

  CouplingSettings::Iteration controls_;
  double omega_ = 1;
  std::vector<double> previous_;  ///< r^{k-1} / scale; empty before the first update
  /// Quasi-Newton: the previous output x~^{k-1}, and the differences of the
  /// normalized residuals (V) and of the outputs (W), one column per pass.
  Eigen::VectorXd previous_output_;
  std::vector<Eigen::VectorXd> residual_changes_, output_changes_;
};

}  // namespace fissure
