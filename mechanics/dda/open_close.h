// Open-close iteration: after each solve every contact is re-classified from
// its computed gap d and slip ds (theory.md 1.5):
//  * normal: closed while in compression; open in tension (a bonded contact
//    only once the tension exceeds its tensile strength), closed again when it
//    penetrates;
//  * shear: a stuck (locked) contact carries the trial force F = F0 + p_s ds
//    (F0: its shear force at the start of the step, ds: the slip of this step)
//    and starts to slide when |F| exceeds the Coulomb limit N tan(phi) + c l_c,
//    in the direction of F, with force sign(F) x limit; a contact that closes
//    is judged the same way (it sticks only when p_s ds is within the limit;
//    Shi let it enter stuck whatever its force, which made packed rock masses
//    chatter, docs/dda.md 2); a sliding contact
//    sticks again when its slip reverses (Shi). The pure return-mapping rule
//    (stick whenever |F| is within the limit) is more consistent but cycles
//    between stick and slip far more often in a vibrating wall (measured:
//    twice the iterations, ten times the step cuts), so Shi's hysteresis is
//    kept for the slip -> stick decision.
// Sliding or opening in tension breaks a bond (c = sigma_t = 0 afterwards).
// Changes smaller than `force_tolerance` (a 1e-6 fraction of the step's force
// scale), or within +-0.1 % of the Coulomb limit, are not changes: unloaded
// contacts (the vertical joints of a wall) and contacts resting exactly at the
// limit otherwise flip between states without end.
// A contact that has already changed state `kMaxStateChanges` times in this
// step is *held* when the state of the last solve violates the contact law by
// less than `hold_tolerance` (a force): it keeps that state (its forces follow
// that state's law at the current iterate) and is judged afresh in the next
// step. Without this a single contact chattering between two states (a
// 2-cycle) rejects the whole step, and in assemblies of thousands of contacts
// some contact always does: a 1,000-brick wall settling from rest was cut to
// dt ~ 5e-5 s and never got back to 1 ms. Abaqus handles chattering contacts
// the same way (it fixes their status after repeated changes).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/state/rock_mass.h"
#include "mechanics/dda/contact_springs.h"
#include "mechanics/dda/dda_contact.h"

namespace fissure::dda {

/// Changes of state a contact may make in one step before it is held.
constexpr int kMaxStateChanges = 3;

struct OpenCloseResult {
  int state_changes = 0;  ///< contacts that changed state in this iterate
  int held = 0;           ///< contacts that would have changed but are held
};

/// Updates gap, slip, forces and states of all contacts from the solution x
/// (six unknowns per free block, `slots` give the rows), each with its
/// friction coefficient (friction_coefficient(): its law's or its joint's).
OpenCloseResult update_contact_states(std::vector<DdaContact>& contacts,
                                      const std::vector<ContactSlots>& slots,
                                      const Eigen::VectorXd& x, const SpringConstants& k,
                                      double force_tolerance, double hold_tolerance,
                                      const std::vector<double>& friction_coefficients,
                                      const RockMass& state);

/// Sets each contact that `frozen` lists (by key; both sorted by key) to the
/// state it has there and marks every contact as held whatever its law asks
/// (the iterated coupling's frozen states, Process::freeze_discrete_states):
/// with an infinite hold tolerance the open-close iteration then ends after
/// one solve. A contact stuck in both keeps its anchor, the start-of-step
/// force of this step.
void freeze_states(std::vector<DdaContact>& contacts, const std::vector<DdaContact>& frozen);

/// Augmented Lagrangian contacts (docs/dda.md section 11; Bao, Zhao and
/// Tian 2014 for DDA, after Simo and Laursen 1992): the largest distance
/// |d - d*| of a closed contact's gap from its target (set_contact_targets;
/// both ways: a contact whose multiplier bridges a gap holds blocks that
/// have parted) and |ds - ds*| of a stuck one's slip, over the contacts on
/// joints without a law (a law's closure is the joint's own deformation,
/// not a penalty error).
/// In units of each contact's tolerance (set_contact_targets): at most 1
/// when every contact is within it.
double largest_contact_error(const std::vector<DdaContact>& contacts);

/// The forces the blocks' initial stresses put on their closed contacts at
/// the start of a run with augmented Lagrangian contacts: the multiplier
/// N = -n.sigma.n l_c and the shear force t.sigma.n l_c (within the Coulomb
/// limit), sigma the mean of the two blocks' stresses, n the edge's normal,
/// l_c the contact's tributary length. A rock mass given an in-situ stress
/// (rock_mass.initial_stress) then starts in equilibrium but where an
/// excavation left a wall free; with penalty springs its contacts start at
/// zero force and every block first expands into its neighbours.
void give_initial_stress_forces(std::vector<DdaContact>& contacts, const RockMass& state,
                                const std::vector<double>& friction_coefficients);

/// Where the augmented Lagrangian brings each contact in a step of length
/// dt. Newmark (beta = 1/2, gamma = 1) ends a step at v1 = 2 d / dt - v0: a
/// contact held at d = 0 reverses the relative velocity v0 it started with,
/// and a block at rest on a slope rings from step to step, its normal forces
/// swinging by a quarter and its contacts sliding (it walked 0.2 mm in 2 s).
/// So a contact is brought to the gap and slip at which its relative
/// velocity ends at zero, gap0 + vn0 dt / 2 and vs0 dt / 2, with vn0, vs0
/// the rates of its gap and slip at the start (the blocks' carried-over
/// velocities through e, g and es, gs): an inelastic contact, as the
/// penalty springs' dashpots make it. The gap's target also closes 0.17 of
/// the gap (critically damped, open_close.cpp). Each contact's tolerance
/// (DdaContact::target_tolerance) is `tolerance`, at most 0.02 F dt^2 / 2m,
/// which holds its force F to 2 % (m the lighter free block, F at least its
/// weight); the gap's target is never deeper than half of it, and
/// largest_contact_error counts |d - d*| twice, so that a step within
/// tolerance penetrates by less than it.
void set_contact_targets(std::vector<DdaContact>& contacts, const RockMass& state,
                         double velocity_carry_over, double dt, double tolerance);

/// The multipliers' update (Uzawa): each closed contact (without a law)
/// moves its multiplier by lambda <- lambda - p_n (d - d*) and each stuck
/// one its anchor by F_a <- F_a + p_s (ds - ds*), d* and ds* its targets
/// (set_contact_targets), with the step's spring constants `k`; solved
/// again, the springs then carry only what is left of the error. An anchor
/// is kept within the contact's Coulomb limit at its new normal force
/// (shear_strength).
void update_multipliers(std::vector<DdaContact>& contacts, const SpringConstants& k,
                        const std::vector<double>& friction_coefficients,
                        const std::vector<JointProperties>& joints);

/// Coulomb limit of the shear force: N tan(phi) + c l_c (cohesion while bonded).
double shear_strength(const DdaContact& c, double friction_coefficient, double cohesion,
                      double normal_force);

}  // namespace fissure::dda
