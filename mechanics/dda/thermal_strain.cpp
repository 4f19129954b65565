#include "mechanics/dda/thermal_strain.h"

#include <stdexcept>

#include "core/base/errors.h"
#include "rockmass/fields/block_temperature.h"

namespace fissure::dda {

Eigen::Vector3d thermal_strain_per_kelvin(const Material& m, PlaneMode plane) {
  const double free = plane == PlaneMode::Strain ? (1 + m.poisson_ratio) * m.thermal_expansion
                                                 : m.thermal_expansion;
  return Eigen::Vector3d(free, free, 0);
}

void ThermalStrain::begin_step(const RockMass& state, PlaneMode plane) {
  const std::vector<double>* change = state.fields.find(kBlockTemperatureChange);
  if (!change) {
    // No field (a mechanics-only scene, or before the thermal process wrote
    // it): nothing to apply, the system is the one without temperature.
    step_.clear();
    return;
  }
  const std::size_t n = state.blocks.size();
  FISSURE_CHECK(change->size() == n, std::logic_error,
                "the field '" << kBlockTemperatureChange.name << "' has " << change->size()
                              << " values for " << n << " blocks");
  target_ = *change;
  if (applied_.size() != n) applied_.assign(n, 0.0);
  step_.resize(n);
  for (std::size_t b = 0; b < n; ++b)
    step_[b] = (target_[b] - applied_[b]) *
               thermal_strain_per_kelvin(state.materials[state.blocks[b].material], plane);
}

}  // namespace fissure::dda
