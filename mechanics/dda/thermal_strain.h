// Thermal strain of the blocks (theory.md 4.3): the mechanics' reader of the
// shared field "block_thermal_strain" (rockmass/fields/block_thermal_strain.h).
//
// A block whose free (stress-free) linear thermal strain is e = alpha_T dT
// (the thermal process owns alpha_T: thermal.materials[].thermal_expansion)
// has the initial strain
//   eps* = e (1, 1, 0)            in plane stress,
//   eps* = (1 + nu) e (1, 1, 0)   in plane strain, with the plane-strain E
// (the out-of-plane strain is held at zero: its stress -E e is what raises
// the in-plane free strain by 1 + nu; nu is the mechanics' own material
// property). DDA's unknowns and stresses are increments over a step, so a
// step applies only the change of eps* since the last step: F += S E d_eps*
// on the block's strain rows, and the stress update is
// sigma += E (d_eps - d_eps*). What has been applied, per block, is the DDA's
// inner state (checkpointed): the field may change between the steps of the
// mechanics (a sub-cycled thermal process) and the mechanics catches up in
// its next step.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/state/rock_mass.h"
#include "mechanics/dda/dda_settings.h"

namespace fissure::dda {

/// The in-plane initial strain (xx, yy, xy) of a block of `material` whose
/// isotropic free linear strain is `free_strain` (theory.md 4.3), in the
/// plane mode.
Eigen::Vector3d in_plane_thermal_strain(double free_strain, const Material& material,
                                        PlaneMode plane);

class ThermalStrain {
 public:
  /// At the start of a step: every block's thermal strain increment, from the
  /// state's free thermal strain (none without the field). Throws
  /// std::logic_error when the field does not have one value per block.
  void begin_step(const RockMass& state, PlaneMode plane);
  /// Whether the step has a thermal strain field (otherwise every term is absent,
  /// not zero: a scene without heat runs to the same bits as before).
  bool active() const { return !step_.empty(); }
  /// The step's thermal strain increment of `block` (zero without a field).
  Eigen::Vector3d step_strain(int block) const {
    return step_.empty() ? Eigen::Vector3d::Zero() : step_[block];
  }
  /// After an accepted step: the free thermal strain the step applied.
  void commit() {
    if (!step_.empty()) applied_ = target_;
  }
  /// Per block, the free thermal strain alpha_T dT applied so far (empty
  /// before the field first appears).
  const std::vector<double>& applied() const { return applied_; }

  /// The inner state (core/io/checkpoint.h).
  /// Stored only once a thermal strain field was seen: the checkpoints of
  /// scenes without heat stay as they were.
  template <class Self, class Archive>
  static void checkpoint(Self& self, Archive& a) {
    constexpr const char* key = "applied_thermal_strain";
    if constexpr (Archive::reading) {
      self.applied_.clear();
      if (!a.has(key)) return;
    } else if (self.applied_.empty()) {
      return;
    }
    a(key, self.applied_);
  }

 private:
  std::vector<double> applied_, target_;
  std::vector<Eigen::Vector3d> step_;
};

}  // namespace fissure::dda
