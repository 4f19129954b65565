// A DDA vertex-edge contact (theory.md 1.4-1.5): vertex `vertex` of block i
// against the edge of block j that starts at polygon vertex `edge` (the edge
// edge -> next(edge), material of j on its left). For the spring formulas the
// edge is walked backwards, P2 = next(edge), P3 = edge, so that block j lies
// to the right of P2 -> P3 and the signed distance d > 0 means separation.
#pragma once

#include <algorithm>
#include <compare>
#include <concepts>
#include <optional>
#include <type_traits>
#include <vector>

#include "core/state/rock_mass.h"
#include "mechanics/dda/block_kinematics.h"
#include "rockmass/fields/contacts.h"
#include "rockmass/joints/joint_law.h"

namespace fissure::dda {

/// Ordered by vertex (block, then polygon vertex), then edge: the order in
/// which detection lists contacts.
struct ContactKey {
  int block_i = -1, vertex = -1, block_j = -1, edge = -1;
  auto operator<=>(const ContactKey&) const = default;
};

struct DdaContact {
  ContactKey key;
  int joint = 0;

  // --- persistent state (carried from step to step) ---
  ContactState state = ContactState::Open;
  bool bonded = false;      ///< cohesion and tensile strength intact
  double normal_force = 0;  ///< compressive > 0 (N), last iterate
  /// Shear force as the spring's p_s ds along P2 -> P3 (N): the force on the
  /// vertex's block is -shear_force along the edge. It is the contact's
  /// memory (UDEC's incremental shear force): a stuck contact keeps carrying
  /// it from step to step, so a block under sustained load does not creep.
  double shear_force = 0;
  double shear_force_start = 0;  ///< shear force at the start of the step (F0)
  /// Force at which a stuck contact's shear spring is anchored in this step:
  /// F0, zero after closing, or the current sliding force after the slip
  /// reversed (so that the spring takes over the friction force, within the
  /// current Coulomb limit).
  double shear_anchor = 0;
  double slip_sign = 0;  ///< sliding: direction of the friction force's reaction
  /// The augmented Lagrangian multiplier of a closed contact (N, compression
  /// > 0; docs/dda.md section 11): its normal force is lambda - p_n d. Kept
  /// from step to step while closed, 0 when open and with the penalty method.
  double normal_multiplier = 0;
  /// The state of its joint's law (contact_laws.h) on a Barton-Bandis or
  /// continuously yielding joint, at the start of the step; none on a
  /// Coulomb joint.
  std::optional<joints::JointLaw::State> law;
  /// With a law: its friction coefficient in this step, the law's strength
  /// over sigma_n at the step's start (contact_laws.h).
  double law_friction = 0;

  // --- geometry of this step (start-of-step configuration) ---
  double length = 0;            ///< |P3 - P2|
  double tributary_length = 0;  ///< l_c: share of the joint length (cohesion, tension)
  double t_start = 0;           ///< projection P0 of P1 on P2 -> P3 at the start of the step
  Vector6 e = Vector6::Zero(), g = Vector6::Zero();  ///< d = gap0 + e.Di + g.Dj
  double gap0 = 0;
  Vector6 es = Vector6::Zero(), gs = Vector6::Zero();  ///< slip ds = es.Di + gs.Dj (from P0)
  Vector6 friction_i = Vector6::Zero();                ///< T_i(P1)^T t_hat
  Vector6 friction_j = Vector6::Zero();                ///< T_j(P0)^T t_hat
  /// The parts of d and ds that the step's prescribed motion of a driven
  /// block gives (a base following a ground motion): e.Di or g.Dj with D
  /// known, like a block's unknown part (dda_process.cpp).
  double prescribed_gap = 0, prescribed_slip = 0;
  /// Augmented Lagrangian: the gap and the slip a closed (stuck) contact is
  /// brought to in this step, those that end it with no relative velocity
  /// (open_close.h, set_contact_targets).
  double gap_target = 0, slip_target = 0;
  /// ... and how close it must come to them (m): the scene's tolerance, at
  /// most what keeps its force right to 2 % (set_contact_targets).
  double target_tolerance = 0;
  /// 1 + b / dt: the springs' stiffness in this step's system with their
  /// dashpots b k (vibration_damping.h); their forces in the contact law are
  /// the springs' alone.
  double spring_factor = 1;

  // --- last iterate ---
  double gap = 0;         ///< d
  double shear = 0;       ///< slip of this step ds
  int state_changes = 0;  ///< in this step's open-close iteration so far
};

/// The contact's friction coefficient in this step: its law's, else its
/// joint's tan(phi) (DdaParameters::friction_coefficients).
inline double friction_coefficient(const DdaContact& c,
                                   const std::vector<double>& joint_friction_coefficients) {
  return c.law ? c.law_friction : joint_friction_coefficients[c.joint];
}

/// Every field of a contact, for checkpoints (core/io/checkpoint.h): a
/// const DdaContact when writing, a DdaContact when reading. Of its law's
/// state only whether it has one: the process writes the states themselves
/// (joints::checkpoint_law_states), which are no columns of one kind.
template <class Archive, class Contact>
requires std::same_as<std::remove_const_t<Contact>, DdaContact>
void checkpoint_fields(Archive& e, Contact& c) {
  e("block_i", c.key.block_i);
  e("vertex", c.key.vertex);
  e("block_j", c.key.block_j);
  e("edge", c.key.edge);
  e("joint", c.joint);
  e("state", c.state);
  e("bonded", c.bonded);
  e("normal_force", c.normal_force);
  e("shear_force", c.shear_force);
  e("shear_force_start", c.shear_force_start);
  e("shear_anchor", c.shear_anchor);
  e("slip_sign", c.slip_sign);
  e("normal_multiplier", c.normal_multiplier);
  bool has_law = c.law.has_value();
  e("has_law", has_law);
  if constexpr (!std::is_const_v<Contact>) {
    if (has_law)
      c.law.emplace();  // a place for the state the process reads
    else
      c.law.reset();
  }
  e("law_friction", c.law_friction);
  e("length", c.length);
  e("tributary_length", c.tributary_length);
  e("t_start", c.t_start);
  e("e", c.e);
  e("g", c.g);
  e("gap0", c.gap0);
  e("es", c.es);
  e("gs", c.gs);
  e("prescribed_gap", c.prescribed_gap);
  e("prescribed_slip", c.prescribed_slip);
  e("friction_i", c.friction_i);
  e("friction_j", c.friction_j);
  e("spring_factor", c.spring_factor);
  e("gap", c.gap);
  e("shear", c.shear);
  e("state_changes", c.state_changes);
}

/// Whether a contact list is in key order, as detection gives it.
inline bool sorted_by_key(const std::vector<DdaContact>& contacts) {
  return std::is_sorted(contacts.begin(), contacts.end(),
                        [](const DdaContact& a, const DdaContact& b) { return a.key < b.key; });
}

}  // namespace fissure::dda
