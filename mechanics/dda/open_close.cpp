#include "mechanics/dda/open_close.h"

#include <algorithm>
#include <cmath>

namespace fissure::dda {

namespace {
// Relative band around the Coulomb limit in which a contact keeps its state.
constexpr double kFrictionBand = 1e-3;
}  // namespace

double shear_strength(const DdaContact& c, double friction_coefficient, double cohesion,
                      double normal_force) {
  return std::max(normal_force, 0.0) * friction_coefficient +
         (c.bonded ? cohesion * c.tributary_length : 0.0);
}

namespace {

/// Return mapping of one contact at its current gap and slip: the state, the
/// forces and the history its constitutive law calls for (the rules above).
void classify(DdaContact& c, const JointProperties& joint, double mu, const SpringConstants& k,
              double tol) {
  const double normal = -k.normal * c.gap;  // compression > 0
  const ContactState before = c.state;

  // 1. Normal: open or closed.
  bool closed = before != ContactState::Open;
  if (!closed) {
    closed = normal > tol;
  } else if (c.bonded && normal < 0) {
    if (-normal > joint.tensile_strength * c.tributary_length + tol) {
      closed = false;
      c.bonded = false;
    }
  } else if (normal < -tol) {
    closed = false;
    c.bonded = false;
  }

  // 2. Shear: return mapping on the trial force.
  if (!closed) {
    c.state = ContactState::Open;
    c.normal_force = 0;
    c.shear_force = 0;
    c.shear_anchor = 0;
    return;
  }
  c.normal_force = normal;
  const double limit = shear_strength(c, mu, joint.cohesion, normal);
  const double trial = c.shear_anchor + k.shear * c.shear;
  // A sliding contact sticks again only when its slip reverses (Shi); a
  // stuck one, or one that closes in this iterate, slides when its trial
  // force exceeds the limit (return mapping). Both with a band of 0.1 % of
  // the limit. A closing contact entered stuck whatever its trial force
  // (Shi): then its shear spring, anchored at zero, carried p_s ds, often
  // far above the limit, until the next iterate let it slide; that detour
  // through a wrong state is what made packed rock masses chatter (issue 22:
  // 77 of 363 steps cut settling a jointed slope, 5 of 48 now).
  const double band = kFrictionBand * limit + tol;
  const bool slides = before == ContactState::Sliding ? k.shear * c.shear * c.slip_sign >= -band
                                                      : std::abs(trial) > limit + band;
  if (!slides) {
    // Sticking again after sliding: the spring takes over the current
    // friction force (within today's limit, not the start force's).
    if (before == ContactState::Sliding) c.shear_anchor = c.slip_sign * limit;
    c.state = ContactState::Locked;
    c.shear_force = before == ContactState::Locked ? trial : c.shear_anchor;
  } else {
    if (before != ContactState::Sliding) c.slip_sign = trial > 0 ? 1 : -1;
    c.state = ContactState::Sliding;
    c.bonded = false;
    c.shear_force = c.slip_sign * shear_strength(c, mu, joint.cohesion, normal);
  }
}

/// What the contact law updates in a contact: a hold puts it back.
struct LawState {
  ContactState state;
  bool bonded;
  double normal_force, shear_force, shear_anchor, slip_sign;
};

LawState law_state(const DdaContact& c) {
  return {c.state, c.bonded, c.normal_force, c.shear_force, c.shear_anchor, c.slip_sign};
}

/// Force by which keeping `held` (the state of the last solve) violates the
/// contact law that asks for the state of `next`, both at the current gap and
/// slip: the tension a closed contact carries, the spring force an open one
/// does not exert, the shear above the Coulomb limit of a locked one, the
/// spring force of a sliding one's reversed slip.
double hold_error(const LawState& held, const DdaContact& next, const SpringConstants& k) {
  if (next.state == ContactState::Open) return std::max(0.0, k.normal * next.gap);
  if (held.state == ContactState::Open) return next.normal_force;
  if (held.state == ContactState::Locked)
    return std::abs(held.shear_anchor + k.shear * next.shear) - std::abs(next.shear_force);
  if (next.state == ContactState::Locked) return k.shear * std::abs(next.shear);
  return std::abs(next.shear_force - held.shear_force);  // slip direction reversed
}

/// Puts the held state back, with its law's forces at the current iterate
/// (which is what the last solve applied).
void hold(DdaContact& c, const LawState& held, const JointProperties& joint, double mu,
          const SpringConstants& k) {
  c.state = held.state;
  c.bonded = held.bonded;
  c.shear_anchor = held.shear_anchor;
  c.slip_sign = held.slip_sign;
  c.normal_force = c.state == ContactState::Open ? 0.0 : -k.normal * c.gap;
  c.shear_force = c.state == ContactState::Open ? 0.0
                  : c.state == ContactState::Locked
                      ? c.shear_anchor + k.shear * c.shear
                      : c.slip_sign * shear_strength(c, mu, joint.cohesion, c.normal_force);
}

}  // namespace

OpenCloseResult update_contact_states(std::vector<DdaContact>& contacts,
                                      const std::vector<ContactSlots>& slots,
                                      const Eigen::VectorXd& x, const SpringConstants& k,
                                      double force_tolerance, double hold_tolerance,
                                      const std::vector<double>& friction_coefficients,
                                      const RockMass& state) {
  OpenCloseResult result;
  for (std::size_t n = 0; n < contacts.size(); ++n) {
    DdaContact& c = contacts[n];
    const ContactSlots& s = slots[n];
    const JointProperties& joint = state.joints[c.joint];
    const double mu = friction_coefficient(c, friction_coefficients);
    const auto dot = [&](const Vector6& a, int dof) {
      return dof >= 0 ? a.dot(x.segment<6>(6 * dof)) : 0.0;
    };
    c.gap = c.gap0 + c.prescribed_gap + dot(c.e, s.dof_i) + dot(c.g, s.dof_j);
    c.shear = c.prescribed_slip + dot(c.es, s.dof_i) + dot(c.gs, s.dof_j);
    const LawState before = law_state(c);
    classify(c, joint, mu, k, force_tolerance);
    const bool changed = c.state != before.state ||
                         (c.state == ContactState::Sliding && c.slip_sign != before.slip_sign);
    if (!changed) continue;
    if (c.state_changes >= kMaxStateChanges && hold_error(before, c, k) <= hold_tolerance) {
      hold(c, before, joint, mu, k);
      ++result.held;
    } else {
      ++c.state_changes;
      ++result.state_changes;
    }
  }
  return result;
}

void freeze_states(std::vector<DdaContact>& contacts, const std::vector<DdaContact>& frozen) {
  auto f = frozen.begin();
  for (DdaContact& c : contacts) {
    c.state_changes = kMaxStateChanges;
    f = std::lower_bound(f, frozen.end(), c.key,
                         [](const DdaContact& a, const ContactKey& k) { return a.key < k; });
    if (f == frozen.end() || f->key != c.key) continue;
    if (c.state != ContactState::Locked || f->state != ContactState::Locked)
      c.shear_anchor = f->state == ContactState::Locked ? f->shear_anchor : 0.0;
    c.state = f->state;
    c.bonded = c.bonded && f->bonded;
    c.slip_sign = f->slip_sign;
  }
}

}  // namespace fissure::dda
