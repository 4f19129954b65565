// The continuously yielding joint of Cundall and Hart (1984), as UDEC has it
// (Itasca's UDEC manual, "Continuously yielding joint model"; Lemos's
// implementation): docs/joints.md section 4.
//
// Normal: the stiffness grows with the normal stress, no tension,
//   d sigma_n = k_n d(closure),  k_n = a_n sigma_n^e_n
// written k_n = k_n,ref (sigma_n / sigma_ref)^e_n with the stress floored
// at 0.01 sigma_ref (a joint that touches has a stiffness); this is
// integrated exactly, so sigma_n is a function of the closure (loading and
// unloading on one curve).
// Shear, with tau_m = sigma_n tan(phi_m) sign(du_s) the bounding strength:
//   d tau = F k_s du_s,  F = (1 - tau/tau_m) / (1 - r),  F <= 1
//   du_s^p = (1 - F) |du_s|
//   phi_m = phi + (phi_m0 - phi) exp(-u_s^p / R)
// r = 0 at the start and r = tau/tau_m (in the new direction) at every
// reversal, so that F = 1 just after it; k_s = k_s,ref (sigma_n /
// sigma_ref)^e_s likewise. Dilation: du_dil = tan(psi) du_s^p with
// psi = atan(|tau| / sigma_n) - phi, and 0 where that is negative.
//
// The step is explicit (forward Euler, first order in the step, as UDEC's):
// F, k_s, psi and tau_m are those at the start of the step; phi_m follows
// the step's plastic shear exactly (the exponential).
#pragma once

#include <concepts>
#include <type_traits>

#include "rockmass/joints/joint_step.h"

namespace fissure::joints {

struct ContinuouslyYieldingProperties {
  double normal_stiffness = 0;           ///< k_n,ref at sigma_ref, Pa/m (> 0)
  double normal_stiffness_exponent = 0;  ///< e_n, in [0, 1)
  double shear_stiffness = 0;            ///< k_s,ref at sigma_ref, Pa/m (> 0)
  double shear_stiffness_exponent = 0;   ///< e_s, in [0, 1)
  double reference_normal_stress = 1e6;  ///< sigma_ref, Pa (> 0)
  double friction_angle = 0;             ///< phi, rad: the friction phi_m decays to
  double initial_friction_angle = 0;     ///< phi_m0, rad, in [phi, 90 deg)
  double roughness_length = 0;           ///< R, m (> 0)
};

class ContinuouslyYielding {
 public:
  /// Per contact: the walls (JointWalls) and the law's own history.
  struct State : JointWalls {
    double plastic_shear = 0;            ///< u_s^p, m
    double bounding_friction_angle = 0;  ///< phi_m, rad (phi_m0 in initial_state())
    double reversal_ratio = 0;           ///< r
    double loading_direction = 0;        ///< sign of the last shear step (0: none yet)
  };

  /// Throws std::invalid_argument for properties out of range.
  explicit ContinuouslyYielding(const ContinuouslyYieldingProperties& properties);

  const ContinuouslyYieldingProperties& properties() const { return p_; }
  /// At rest, phi_m = phi_m0.
  State initial_state() const;
  JointResponse update(const State& before, const JointIncrement& step, State& after) const;

  /// sigma_n (Pa) at the closure (m) on the exact normal curve; 0 for closure <= 0.
  double normal_stress(double closure) const;
  /// Its inverse: the closure (m) at sigma_n (Pa); 0 for sigma_n <= 0.
  double closure(double normal_stress) const;
  /// k_n (Pa/m) at sigma_n.
  double normal_stiffness(double normal_stress) const;
  /// k_s (Pa/m) at sigma_n.
  double shear_stiffness(double normal_stress) const;

 private:
  ContinuouslyYieldingProperties p_;
  double floor_ = 0;  ///< sigma_floor / sigma_ref
};

template <class Archive, class State>
requires std::same_as<std::remove_const_t<State>, ContinuouslyYielding::State>
void checkpoint_fields(Archive& e, State& s) {
  checkpoint_walls(e, s);
  e("plastic_shear", s.plastic_shear);
  e("bounding_friction_angle", s.bounding_friction_angle);
  e("reversal_ratio", s.reversal_ratio);
  e("loading_direction", s.loading_direction);
}

}  // namespace fissure::joints
