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

/// Coulomb limit of the shear force: N tan(phi) + c l_c (cohesion while bonded).
double shear_strength(const DdaContact& c, double friction_coefficient, double cohesion,
                      double normal_force);

}  // namespace fissure::dda
