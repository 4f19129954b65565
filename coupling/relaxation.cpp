#include "coupling/relaxation.h"

#include <algorithm>

#include "core/base/errors.h"

namespace fissure {

Relaxation::Relaxation(const CouplingSettings::Iteration& controls) : controls_(controls) {
  reset();
}

void Relaxation::reset() {
  omega_ = controls_.omega;
  previous_.clear();
  previous_output_.resize(0);
  residual_changes_.clear();
  output_changes_.clear();
}

void Relaxation::relax(std::span<double> x, std::span<const double> r,
                       std::span<const double> scale) {
  FISSURE_CHECK(x.size() == r.size() && r.size() == scale.size(), std::logic_error,
                "relaxation of " << x.size() << " values with " << r.size() << " residuals and "
                                 << scale.size() << " scales");
  std::vector<double> normalized(r.size());
  for (std::size_t i = 0; i < r.size(); ++i) normalized[i] = r[i] / scale[i];
  using Relax = CouplingSettings::Iteration::Relaxation;
  if (controls_.relaxation == Relax::QuasiNewton) {
    quasi_newton(x, r, normalized);
    previous_ = std::move(normalized);
    return;
  }
  if (controls_.relaxation == Relax::Aitken && previous_.size() == r.size()) {
    double numerator = 0, denominator = 0;
    for (std::size_t i = 0; i < r.size(); ++i) {
      const double d = normalized[i] - previous_[i];
      numerator += previous_[i] * d;
      denominator += d * d;
    }
    // Equal residuals leave nothing to learn: omega stays.
    if (denominator > 0)
      omega_ = std::clamp(-omega_ * numerator / denominator, kMinOmega, kMaxOmega);
  }
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += omega_ * r[i];
  previous_ = std::move(normalized);
}

}  // namespace fissure

namespace fissure {

void Relaxation::quasi_newton(std::span<double> x, std::span<const double> r,
                              const std::vector<double>& normalized) {
  const auto n = static_cast<Eigen::Index>(x.size());
  const Eigen::Map<const Eigen::VectorXd> rn(normalized.data(), n);
  Eigen::VectorXd output(n);  // x~ = x + r, what the pass produced
  for (Eigen::Index i = 0; i < n; ++i) output(i) = x[i] + r[i];
  if (previous_output_.size() == n && previous_.size() == x.size()) {
    residual_changes_.push_back(rn - Eigen::Map<const Eigen::VectorXd>(previous_.data(), n));
    output_changes_.push_back(output - previous_output_);
    if (residual_changes_.size() > kMostColumns) {
      residual_changes_.erase(residual_changes_.begin());
      output_changes_.erase(output_changes_.begin());
    }
  }
  previous_output_ = output;
  if (residual_changes_.empty()) {  // nothing learnt yet: a relaxed pass
    for (Eigen::Index i = 0; i < n; ++i) x[i] += omega_ * r[i];
    return;
  }
  const auto k = static_cast<Eigen::Index>(residual_changes_.size());
  Eigen::MatrixXd v(n, k), w(n, k);
  for (Eigen::Index j = 0; j < k; ++j) {
    v.col(j) = residual_changes_[j];
    w.col(j) = output_changes_[j];
  }
  // Columns that repeat others (a pass that taught nothing new) are left
  // out by the rank-revealing factorization.
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(v);
  const Eigen::VectorXd c = qr.solve(-rn);
  const Eigen::VectorXd next = output + w * c;
  for (Eigen::Index i = 0; i < n; ++i) x[i] = next(i);
}

}  // namespace fissure
