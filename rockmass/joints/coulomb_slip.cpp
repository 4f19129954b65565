#include "rockmass/joints/coulomb_slip.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "rockmass/joints/property_checks.h"

namespace fissure::joints {

CoulombSlip::CoulombSlip(const CoulombProperties& properties) : p_(properties) {
  const char* law = "Coulomb slip";
  require_positive(law, "normal stiffness", p_.normal_stiffness);
  require_positive(law, "shear stiffness", p_.shear_stiffness);
  require_acute(law, "friction angle", p_.friction_angle);
  require_acute(law, "dilation angle", p_.dilation_angle);
  require_non_negative(law, "cohesion", p_.cohesion);
  require_non_negative(law, "tensile strength", p_.tensile_strength);
  require_non_negative(law, "zero-dilation shear displacement", p_.zero_dilation_displacement);
  tan_phi_ = std::tan(p_.friction_angle);
  tan_psi_ = std::tan(p_.dilation_angle);
}

JointResponse CoulombSlip::update(const State& before, const JointIncrement& step,
                                  State& after) const {
  after = before;
  after.normal_displacement += step.normal;
  after.shear_displacement += step.shear;
  const double kn = p_.normal_stiffness, ks = p_.shear_stiffness;
  JointResponse r;

  // 1. The normal spring at this step's displacement, before its dilation,
  // and the elastic shear trial.
  const double sigma = -kn * (after.normal_displacement - after.dilation);
  const double trial = before.shear_stress + ks * step.shear;
  const auto stick = [&](double cohesion) {
    after.normal_stress = r.normal_stress = sigma;
    after.shear_stress = r.shear_stress = trial;
    r.normal_stiffness = kn;
    r.shear_strength = cohesion + std::max(sigma, 0.0) * tan_phi_;
    return r;
  };
  const auto open = [&] {
    after.normal_stress = after.shear_stress = 0;
    r.open = true;
    return r;
  };

  // 2. An intact joint holds up to its tensile strength and cohesion.
  if (after.intact && sigma >= -p_.tensile_strength &&
      std::abs(trial) <= p_.cohesion + std::max(sigma, 0.0) * tan_phi_)
    return stick(p_.cohesion);
  // Otherwise it has failed (or had): cohesion and tension are lost for
  // good (UDEC's residual strength).
  after.intact = false;
  if (sigma >= 0 && std::abs(trial) <= sigma * tan_phi_) return stick(0);

  // 3. Slip, with dilation only for the share of the step with |u_s| <
  // u_cs (exact for a step of one sign that slips throughout).
  double share = 1;
  if (p_.zero_dilation_displacement > 0 && step.shear != 0)
    share = std::clamp((p_.zero_dilation_displacement - std::abs(before.shear_displacement)) /
                           std::abs(step.shear),
                       0.0, 1.0);
  const double t = share * tan_psi_;
  // Return mapping with the dilation's stress: sigma_n = sigma + k_n t p,
  // |tau| = |trial| - k_s p = sigma_n tan(phi), solved for the slip p.
  const double slip = (std::abs(trial) - sigma * tan_phi_) / (ks + kn * t * tan_phi_);
  const double dilation = t * slip;
  // The walls stay in contact while the slip's dilation exceeds their
  // opening (continuous in the step: sigma_n -> 0 as the two balance).
  if (sigma + kn * dilation <= 0) return open();
  after.dilation += dilation;
  after.plastic_shear += slip;
  after.normal_stress = sigma + kn * dilation;
  after.shear_stress = std::copysign(after.normal_stress * tan_phi_, trial);
  r.normal_stress = after.normal_stress;
  r.shear_stress = after.shear_stress;
  r.plastic_shear = slip;
  r.dilation = dilation;
  r.slipping = true;
  r.normal_stiffness = kn;
  r.shear_strength = after.normal_stress * tan_phi_;
  return r;
}

}  // namespace fissure::joints
