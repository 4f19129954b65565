// Coulomb slip with cohesion, tension cut-off and dilation (docs/joints.md
// section 2; UDEC's joint area contact Coulomb slip model, Itasca's UDEC
// manual, "Constitutive models for joints"):
//   sigma_n = -k_n (u_n - u_dil)            linear normal spring, compression +
//   d tau   =  k_s du_s                     while |tau| < c + sigma_n tan(phi)
//   |tau|   =  sigma_n tan(phi)             once slipping (c and T lost at
//                                           the first failure: residual)
//   open when -sigma_n > T (T = 0 after the first failure): sigma_n = tau = 0
//   du_dil  =  tan(psi) |du_s^p|            while slipping and |u_s| < u_cs
// (a slipping joint stays in contact while its dilation exceeds the opening
// of its walls).
// The step is a return mapping: the plastic slip and the dilation it causes
// are solved together, so the stress point of a slipping joint lies on
// |tau| = sigma_n tan(phi) also when the dilation raises sigma_n (constant
// normal stiffness), exactly for any step (the law is piecewise linear).
#pragma once

#include <concepts>
#include <type_traits>

#include "rockmass/joints/joint_step.h"

namespace fissure::joints {

struct CoulombProperties {
  double normal_stiffness = 0;  ///< k_n, Pa/m (> 0)
  double shear_stiffness = 0;   ///< k_s, Pa/m (> 0)
  double friction_angle = 0;    ///< phi, rad, in [0, pi/2)
  double cohesion = 0;          ///< c, Pa (>= 0), until the first failure
  double tensile_strength = 0;  ///< T, Pa (>= 0), until the first failure
  double dilation_angle = 0;    ///< psi, rad, in [0, pi/2)
  /// u_cs, m: no dilation once |u_s| >= u_cs; 0 = no limit (as the flow's
  /// hm.dilation_limit).
  double zero_dilation_displacement = 0;
};

class CoulombSlip {
 public:
  /// Per contact: the walls (JointWalls) and the law's own history.
  struct State : JointWalls {
    double plastic_shear = 0;  ///< sum of |du_s^p|, m
    bool intact = true;        ///< cohesion and tensile strength not yet lost (a new bond)
  };

  /// Throws std::invalid_argument for properties out of range.
  explicit CoulombSlip(const CoulombProperties& properties);

  const CoulombProperties& properties() const { return p_; }
  /// A bonded joint at rest: no displacement, no stress, cohesion intact.
  State initial_state() const { return State{}; }
  JointResponse update(const State& before, const JointIncrement& step, State& after) const;

 private:
  CoulombProperties p_;
  double tan_phi_ = 0, tan_psi_ = 0;
};

/// Every field of the state, for checkpoints (core/io/checkpoint.h).
template <class Archive, class State>
requires std::same_as<std::remove_const_t<State>, CoulombSlip::State>
void checkpoint_fields(Archive& e, State& s) {
  checkpoint_walls(e, s);
  e("plastic_shear", s.plastic_shear);
  e("intact", s.intact);
}

}  // namespace fissure::joints
