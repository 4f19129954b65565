#include "mechanics/dda/open_close.h"

#include <algorithm>
#include <cmath>

namespace fissure::dda {

namespace {
// Relative band around the Coulomb limit in which a contact keeps its state.
constexpr double kFrictionBand = 1e-3;
// The share of its gap a closed augmented Lagrangian contact closes in a
// step (set_contact_targets): with g' = (1 - b) g + v dt / 2, v' = -2 b g / dt
// the gap obeys g'' = (1 - b) g' - b g, whose roots are smallest, a double
// 0.41, at b = 3 - 2 sqrt(2) (critical: no ringing, 0.41 of the gap left a step).
constexpr double kGapRelaxation = 0.17157287525381;
// The share of a contact's force its gap error may make in a step
// (set_contact_targets).
constexpr double kForceShare = 0.02;
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
  const double normal = c.normal_multiplier - k.normal * c.gap;  // compression > 0
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
    c.normal_multiplier = 0;
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
  double normal_force, shear_force, shear_anchor, slip_sign, normal_multiplier;
};

LawState law_state(const DdaContact& c) {
  return {c.state,        c.bonded,    c.normal_force,     c.shear_force,
          c.shear_anchor, c.slip_sign, c.normal_multiplier};
}

/// Force by which keeping `held` (the state of the last solve) violates the
/// contact law that asks for the state of `next`, both at the current gap and
/// slip: the tension a closed contact carries, the spring force an open one
/// does not exert, the shear above the Coulomb limit of a locked one, the
/// spring force of a sliding one's reversed slip.
double hold_error(const LawState& held, const DdaContact& next, const SpringConstants& k) {
  if (next.state == ContactState::Open) return std::max(0.0, k.normal * next.gap);  // lambda 0
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
  c.normal_force = c.state == ContactState::Open ? 0.0 : held.normal_multiplier - k.normal * c.gap;
  c.normal_multiplier = c.state == ContactState::Open ? 0.0 : held.normal_multiplier;
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

double largest_contact_error(const std::vector<DdaContact>& contacts) {
  double worst = 0;
  for (const DdaContact& c : contacts) {
    if (c.state == ContactState::Open || c.law) continue;
    // Both ways: a closed contact that carries lambda - p_n d > 0 across a
    // gap d > 0 holds blocks that have parted.
    // In units of the contact's tolerance; the gap's target is within half
    // of it of the penetration the tolerance allows.
    const double tol = c.target_tolerance;
    worst = std::max(worst, 2 * std::abs(c.gap - c.gap_target) / tol);
    if (c.state == ContactState::Locked)
      worst = std::max(worst, std::abs(c.shear - c.slip_target) / tol);
  }
  return worst;
}

void give_initial_stress_forces(std::vector<DdaContact>& contacts, const RockMass& state,
                                const std::vector<double>& friction_coefficients) {
  for (DdaContact& c : contacts) {
    if (c.state == ContactState::Open || c.law) continue;
    const Block& bi = state.blocks[c.key.block_i];
    const Block& bj = state.blocks[c.key.block_j];
    const Eigen::Vector3d s = 0.5 * (bi.stress + bj.stress);  // sxx, syy, sxy
    const Eigen::Matrix2d sigma = (Eigen::Matrix2d() << s(0), s(2), s(2), s(1)).finished();
    const Polygon& pj = bj.polygon;
    const Vec2 a = pj.vertices[c.key.edge], b = pj.vertices[pj.next(c.key.edge)];
    const Vec2 along = (a - b).normalized();   // P2 -> P3
    const Vec2 normal(-along.y(), along.x());  // outward of block j (a -> b counter-clockwise)
    const double n = std::max(0.0, -normal.dot(sigma * normal)) * c.tributary_length;
    const double limit = n * friction_coefficient(c, friction_coefficients);
    c.normal_multiplier = n;
    c.normal_force = n;
    c.shear_force = std::clamp(along.dot(sigma * normal) * c.tributary_length, -limit, limit);
    c.shear_anchor = c.shear_force_start = c.shear_force;
  }
}

void set_contact_targets(std::vector<DdaContact>& contacts, const RockMass& state,
                         double velocity_carry_over, double dt, double tolerance) {
  const double g = std::max(state.gravity.norm(), 1.0);
  const auto mass = [&](int b) {
    const Block& block = state.blocks[b];
    return block.fixed ? std::numeric_limits<double>::infinity()
                       : state.materials[block.material].density * block.initial_area;
  };
  for (DdaContact& c : contacts) {
    const Block& bi = state.blocks[c.key.block_i];
    const Block& bj = state.blocks[c.key.block_j];
    const double vn = velocity_carry_over * (c.e.dot(bi.velocity) + c.g.dot(bj.velocity));
    const double vs = velocity_carry_over * (c.es.dot(bi.velocity) + c.gs.dot(bj.velocity));
    // A gap off by d at the end of the step is an acceleration of the
    // lighter block off by 2 d / dt^2: its force m 2 d / dt^2 is held to
    // 2 % of what the contact carries (at least the block's weight).
    const double m = std::min(mass(c.key.block_i), mass(c.key.block_j));
    const double force = std::max(c.normal_force, m * g);
    c.target_tolerance = std::min(tolerance, kForceShare * force * dt * dt / (2 * m));
    c.gap_target = std::max((1 - kGapRelaxation) * c.gap0 + vn * dt / 2, -c.target_tolerance / 2);
    c.slip_target = vs * dt / 2;
  }
}

void update_multipliers(std::vector<DdaContact>& contacts, const SpringConstants& k,
                        const std::vector<double>& friction_coefficients,
                        const std::vector<JointProperties>& joints) {
  for (DdaContact& c : contacts) {
    if (c.state == ContactState::Open || c.law) continue;
    c.normal_multiplier -= k.normal * (c.gap - c.gap_target);
    if (c.state != ContactState::Locked) continue;
    const double limit = shear_strength(c, friction_coefficient(c, friction_coefficients),
                                        joints[c.joint].cohesion, c.normal_multiplier);
    c.shear_anchor =
        std::clamp(c.shear_anchor + k.shear * (c.shear - c.slip_target), -limit, limit);
  }
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
    if (c.state == ContactState::Open) c.normal_multiplier = 0;
    c.bonded = c.bonded && f->bonded;
    c.slip_sign = f->slip_sign;
  }
}

}  // namespace fissure::dda
