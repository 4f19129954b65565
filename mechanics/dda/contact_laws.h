// The joint laws of the DDA's contacts (docs/dda.md section 9; docs/joints.md
// section 6). A contact on a joint whose model is Barton-Bandis or
// continuously yielding carries that law's state (JointLaw::State); the
// DDA's penalty springs carry the contact's forces, the law the history of
// its strength:
//  * at the start of a step the law's walls take the contact's stresses,
//    sigma_n = N / l and tau = F0 / l (l: stress_length(); a sliding
//    contact's tau is its strength, on the law's curve), and the step's
//    friction coefficient is the law's strength over sigma_n there
//    (JointLaw::friction_coefficient: tan phi_mob). It is explicit: fixed
//    through the step's open-close iteration, while the springs' forces are
//    implicit, so the strength lags the step's own mobilization by one step
//    (an error of first order in the step: d(tan phi_mob)/d delta times the
//    step's slip);
//  * once the step is accepted the law takes the step's change of gap and
//    its slip from that state (a pure update: a rejected try, a rollback of
//    the coupling, leaves the state as it was).
// The law's normal closure and stiffnesses are not used: the penalties are
// the springs. A Coulomb joint (no `model`, or `model: coulomb`) has no law
// here and keeps the per-joint tan phi, cohesion and tensile strength of
// DdaParameters, as before.
#pragma once

#include <optional>
#include <vector>

#include "core/scene/scene.h"
#include "mechanics/dda/dda_contact.h"
#include "rockmass/joints/joint_law.h"

namespace fissure::dda {

/// Per scene joint: its law where its contacts carry one (Barton-Bandis,
/// continuously yielding); none for a Coulomb joint.
using ContactLaws = std::vector<std::optional<joints::JointLaw>>;

ContactLaws contact_laws(const std::vector<JointProperties>& joints);

/// The joint length a contact's forces act on (m): its tributary length
/// (the share of an edge-to-edge overlap it stands for), or the whole edge
/// for a corner on a face, which has none. Also the contact's length for a
/// Barton-Bandis joint without a field length.
double stress_length(const DdaContact& c);

/// At the start of a step (after detection and prepare_contact): gives each
/// contact of a law joint its state where it has none of that law (a new
/// contact: the law's state at its gap, without stress or bond), puts the
/// state's walls at the contact's start-of-step stresses and sets the
/// contact's friction coefficient for the step; drops the state of a
/// contact of a Coulomb joint.
void begin_law_step(std::vector<DdaContact>& contacts, const ContactLaws& laws);

/// After an accepted step: each contact's law takes the step's change of
/// gap and slip.
void advance_law_states(std::vector<DdaContact>& contacts, const ContactLaws& laws);

}  // namespace fissure::dda
