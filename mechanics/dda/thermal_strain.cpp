#include "mechanics/dda/thermal_strain.h"

#include <stdexcept>

#include "core/base/errors.h"
#include "rockmass/fields/block_thermal_strain.h"

namespace fissure::dda {

Eigen::Vector3d in_plane_thermal_strain(double free_strain, const Material& m, PlaneMode plane) {
  const double in_plane =
      plane == PlaneMode::Strain ? (1 + m.poisson_ratio) * free_strain : free_strain;
  return Eigen::Vector3d(in_plane, in_plane, 0);
}

void ThermalStrain::begin_step(const RockMass& state, PlaneMode plane) {
  const std::vector<double>* free = state.fields.find(kBlockThermalStrain);
  if (!free) {
    // No field (a mechanics-only scene, or before the thermal process wrote
    // it): nothing to apply, the system is the one without temperature.
    step_.clear();
    return;
  }
  const std::size_t n = state.blocks.size();
  FISSURE_CHECK(free->size() == n, std::logic_error,
                "the field '" << kBlockThermalStrain.name << "' has " << free->size()
                              << " values for " << n << " blocks");
  target_ = *free;
  if (applied_.size() != n) applied_.assign(n, 0.0);
  step_.resize(n);
  for (std::size_t b = 0; b < n; ++b)
    step_[b] = in_plane_thermal_strain(target_[b] - applied_[b],
                                       state.materials[state.blocks[b].material], plane);
}

}  // namespace fissure::dda
