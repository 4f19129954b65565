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
}

void Relaxation::relax(std::span<double> x, std::span<const double> r,
                       std::span<const double> scale) {
  FISSURE_CHECK(x.size() == r.size() && r.size() == scale.size(), std::logic_error,
                "relaxation of " << x.size() << " values with " << r.size() << " residuals and "
                                 << scale.size() << " scales");
  std::vector<double> normalized(r.size());
  for (std::size_t i = 0; i < r.size(); ++i) normalized[i] = r[i] / scale[i];
  using Relax = CouplingSettings::Iteration::Relaxation;
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
