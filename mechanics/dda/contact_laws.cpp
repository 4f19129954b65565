#include "mechanics/dda/contact_laws.h"

#include <algorithm>

#include "rockmass/joints/joint_model.h"

namespace fissure::dda {

ContactLaws contact_laws(const std::vector<JointProperties>& joints) {
  ContactLaws laws;
  laws.reserve(joints.size());
  for (const JointProperties& j : joints) {
    const joints::JointModel model = joints::joint_model(j);
    if (joints::kind_of(model) == joints::JointModelKind::Coulomb)
      laws.emplace_back();
    else
      laws.emplace_back(std::in_place, model);
  }
  return laws;
}

double stress_length(const DdaContact& c) {
  return c.tributary_length > 0 ? c.tributary_length : c.length;
}

void begin_law_step(std::vector<DdaContact>& contacts, const ContactLaws& laws) {
  for (DdaContact& c : contacts) {
    const std::optional<joints::JointLaw>& law = laws[c.joint];
    if (!law) {
      c.law.reset();
      continue;
    }
    // A contact carried over from an edge of another joint (its vertex
    // passed a corner) starts afresh, as a new one.
    if (!c.law || c.law->index() != static_cast<std::size_t>(law->kind()))
      c.law = law->state_at(c.gap0, false);
    const double l = stress_length(c);
    const double normal_stress = std::max(c.normal_force, 0.0) / l;
    c.law_friction = law->friction_coefficient(*c.law, normal_stress, l);
    // A sliding contact slides at its strength: its walls are on the law's
    // curve, so that the law counts its whole slip as mobilization. Its
    // force F0 lags a strength that the last step's slip has moved, and the
    // law would spend the difference on an elastic shear of its own (Barton's
    // K_s), which the DDA's shear spring already is.
    const double shear_stress = c.state == ContactState::Open ? 0.0
                                : c.state == ContactState::Locked
                                    ? c.shear_force_start / l
                                    : c.slip_sign * c.law_friction * normal_stress;
    std::visit(
        [&](auto& s) {
          joints::JointWalls& walls = s;
          walls.normal_stress = normal_stress;
          walls.shear_stress = shear_stress;
        },
        *c.law);
  }
}

void advance_law_states(std::vector<DdaContact>& contacts, const ContactLaws& laws) {
  for (DdaContact& c : contacts) {
    if (!c.law) continue;
    joints::JointLaw::State after;
    laws[c.joint]->update(*c.law, {c.gap - c.gap0, c.shear, stress_length(c)}, after);
    c.law = std::move(after);
  }
}

}  // namespace fissure::dda
