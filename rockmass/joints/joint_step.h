// What every joint law of rockmass/joints/ takes and gives for one step
// (docs/joints.md section 1): the relative displacement of the two walls in
// the step, and the stresses and slip after it. A law is a small class with
// its properties, its per-contact State (plain data with checkpoint_fields,
// so that a process checkpoints it to the bit) and
//   JointResponse update(const State& before, const JointIncrement& step, State& after) const;
// a pure function of (properties, state, increment): a process can try a
// step, reject it and try another from the same state (the DDA's open-close
// iteration, a rolled-back coupling step).
//
// Signs: opening and normal displacement positive; normal stress
// compression positive; shear stress with the sign of the shear
// displacement that loads it.
#pragma once

#include <concepts>
#include <type_traits>

namespace fissure::joints {

/// One step of the walls' relative displacement.
struct JointIncrement {
  double normal = 0;  ///< du_n, m, opening positive
  double shear = 0;   ///< du_s, m, along the joint's tangent
  /// The contact's length, m: the field length of a law with a scale effect
  /// (Barton-Bandis) when the scene gives none. Stresses are per unit area;
  /// the caller turns them into forces.
  double length = 0;
};

/// What every law keeps of a contact's walls (the base of each law's
/// State): where they are, and the stresses between them.
struct JointWalls {
  double normal_displacement = 0;  ///< u_n, m, opening + (0: sigma_n = 0)
  double shear_displacement = 0;   ///< u_s, m
  double dilation = 0;             ///< u_dil, m: the opening caused by slip so far
  double normal_stress = 0;        ///< Pa, compression +
  double shear_stress = 0;         ///< Pa
};

/// The walls' fields of a law's State, for its checkpoint_fields
/// (core/io/checkpoint.h): const when written, not when read.
template <class Archive, class Walls>
requires std::derived_from<std::remove_const_t<Walls>, JointWalls>
void checkpoint_walls(Archive& e, Walls& w) {
  e("normal_displacement", w.normal_displacement);
  e("shear_displacement", w.shear_displacement);
  e("dilation", w.dilation);
  e("normal_stress", w.normal_stress);
  e("shear_stress", w.shear_stress);
}

/// The joint after one step.
struct JointResponse {
  double normal_stress = 0;  ///< sigma_n, Pa, compression positive (0 when open)
  double shear_stress = 0;   ///< tau, Pa (0 when open)
  double plastic_shear = 0;  ///< |du_s^p| of the step, m (>= 0)
  double dilation = 0;       ///< du_n^dil of the step, m: the opening caused by slip
  bool slipping = false;     ///< at its shear strength in this step (each law says which)
  bool open = false;         ///< the walls are apart: no stress
  /// Tangent normal stiffness d sigma_n / d(closure) at the new state, Pa/m
  /// (for an implicit method such as the DDA); 0 when open.
  double normal_stiffness = 0;
  /// The shear stress at which the joint slips at the new state, Pa (its
  /// current strength: cohesion lost or not, mobilized roughness, bounding
  /// strength).
  double shear_strength = 0;
};

}  // namespace fissure::joints
