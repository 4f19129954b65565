#include "rockmass/joints/continuously_yielding.h"

#include <algorithm>
#include <cmath>

#include "rockmass/joints/property_checks.h"

namespace fissure::joints {

namespace {
/// The stiffnesses are those at 1 % of the reference stress below it.
constexpr double kStressFloor = 0.01;
}  // namespace

ContinuouslyYielding::ContinuouslyYielding(const ContinuouslyYieldingProperties& properties)
    : p_(properties), floor_(kStressFloor) {
  const char* law = "continuously yielding";
  require_positive(law, "normal stiffness", p_.normal_stiffness);
  require_positive(law, "shear stiffness", p_.shear_stiffness);
  require(p_.normal_stiffness_exponent >= 0 && p_.normal_stiffness_exponent < 1, law,
          "normal stiffness exponent", "in [0, 1)", p_.normal_stiffness_exponent);
  require(p_.shear_stiffness_exponent >= 0 && p_.shear_stiffness_exponent < 1, law,
          "shear stiffness exponent", "in [0, 1)", p_.shear_stiffness_exponent);
  require_positive(law, "reference normal stress", p_.reference_normal_stress);
  require_acute(law, "friction angle", p_.friction_angle);
  require_acute(law, "initial friction angle", p_.initial_friction_angle);
  require(p_.initial_friction_angle >= p_.friction_angle, law, "initial friction angle",
          ">= the friction angle", p_.initial_friction_angle);
  require_positive(law, "roughness length", p_.roughness_length);
}

ContinuouslyYielding::State ContinuouslyYielding::initial_state() const {
  State s;
  s.bounding_friction_angle = p_.initial_friction_angle;
  return s;
}

double ContinuouslyYielding::normal_stress(double closure) const {
  if (closure <= 0) return 0;
  // In s = sigma_n / sigma_ref: ds/dc = K max(s, s_f)^e with K = k_n,ref /
  // sigma_ref, so s = K s_f^e c up to c_f = s_f^(1-e) / K, then
  // s^(1-e) = s_f^(1-e) + K (1 - e) (c - c_f).
  const double e = p_.normal_stiffness_exponent;
  const double K = p_.normal_stiffness / p_.reference_normal_stress;
  const double floor_power = std::pow(floor_, 1 - e);
  const double c_floor = floor_power / K;
  const double s = closure <= c_floor
                       ? K * std::pow(floor_, e) * closure
                       : std::pow(floor_power + K * (1 - e) * (closure - c_floor), 1 / (1 - e));
  return s * p_.reference_normal_stress;
}

double ContinuouslyYielding::closure(double normal_stress) const {
  if (normal_stress <= 0) return 0;
  // normal_stress() solved for the closure.
  const double e = p_.normal_stiffness_exponent;
  const double K = p_.normal_stiffness / p_.reference_normal_stress;
  const double s = normal_stress / p_.reference_normal_stress;
  if (s <= floor_) return s / (K * std::pow(floor_, e));
  const double floor_power = std::pow(floor_, 1 - e);
  return floor_power / K + (std::pow(s, 1 - e) - floor_power) / (K * (1 - e));
}

double ContinuouslyYielding::normal_stiffness(double normal_stress) const {
  const double s = std::max(normal_stress / p_.reference_normal_stress, floor_);
  return p_.normal_stiffness * std::pow(s, p_.normal_stiffness_exponent);
}

double ContinuouslyYielding::shear_stiffness(double normal_stress) const {
  const double s = std::max(normal_stress / p_.reference_normal_stress, floor_);
  return p_.shear_stiffness * std::pow(s, p_.shear_stiffness_exponent);
}

JointResponse ContinuouslyYielding::update(const State& before, const JointIncrement& step,
                                           State& after) const {
  after = before;
  after.normal_displacement += step.normal;
  after.shear_displacement += step.shear;
  JointResponse r;

  // 1. Shear, at the stresses of the start of the step: a joint that was
  // open carries no shear in the step it closes.
  const double sigma0 = before.normal_stress;
  if (sigma0 > 0 && step.shear != 0) {
    const double direction = step.shear > 0 ? 1 : -1;
    const double tau = before.shear_stress;
    const double phi_m = before.bounding_friction_angle;
    const double tau_m = direction * sigma0 * std::tan(phi_m);
    if (direction != before.loading_direction) {  // a reversal (or the first step)
      after.reversal_ratio = tau / tau_m;
      after.loading_direction = direction;
    }
    const double ratio = after.reversal_ratio;
    const double F = ratio < 1 ? std::min(1.0, (1 - tau / tau_m) / (1 - ratio)) : 0.0;
    const double plastic = (1 - F) * std::abs(step.shear);
    const double psi = std::max(0.0, std::atan(std::abs(tau) / sigma0) - p_.friction_angle);
    r.plastic_shear = plastic;
    r.dilation = std::tan(psi) * plastic;
    r.slipping = F <= 0;
    after.shear_stress = tau + F * shear_stiffness(sigma0) * step.shear;
    after.plastic_shear += plastic;
    after.dilation += r.dilation;
    after.bounding_friction_angle =
        p_.friction_angle + (phi_m - p_.friction_angle) * std::exp(-plastic / p_.roughness_length);
  }

  // 2. Normal: the stress of the closure after the step's dilation.
  const double closure = after.dilation - after.normal_displacement;
  if (closure <= 0) {
    after.normal_stress = after.shear_stress = 0;
    r.open = true;
    r.slipping = false;
    return r;
  }
  after.normal_stress = normal_stress(closure);
  r.normal_stress = after.normal_stress;
  r.shear_stress = after.shear_stress;
  r.normal_stiffness = normal_stiffness(after.normal_stress);
  r.shear_strength = after.normal_stress * std::tan(after.bounding_friction_angle);
  return r;
}

}  // namespace fissure::joints
