// verification.md (p), docs/joints.md 5.1: the Coulomb slip joint in direct
// shear, against the closed forms of its piecewise linear law. The step is
// a return mapping that solves slip and dilation together, so the closed
// forms hold at the end of any step (not only of steps that land on the
// corners): what remains is rounding, some 1e-16 of the stress and
// displacement scales per step over 10^2 - 10^3 steps, and the servo's 1e-13
// on the normal stress. The tolerances, 1e-11 of the scales, sit above that
// and far below any modelling difference (a cohesion kept after failure is
// 0.5 MPa, a dilation left unlimited 1e-4 m).
//
// Mutations checked (each made in coulomb_slip.cpp, each failed here):
//  * cohesion kept after the first failure: DirectShear... and TensionCutOff...;
//  * dilation not stopped at u_cs: DirectShear...;
//  * the slip solved without the dilation's stress (k_s alone in the
//    return mapping), or tau set from the normal stress before the
//    dilation: DirectShear... and ConstantNormalStiffness...;
//  * the bond kept when the joint opens in tension: TensionCutOff....
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rockmass/joints/coulomb_slip.h"
#include "tests/support/joint_driver.h"

namespace fissure::testing {
namespace {

using joints::CoulombProperties;
using joints::CoulombSlip;
using joints::JointIncrement;

constexpr double kDeg = std::numbers::pi / 180;
constexpr double kStressTol = 1e-11;  // relative to the stress scale
constexpr double kLengthTol = 1e-11;  // relative to the displacement scale

CoulombProperties properties() {
  CoulombProperties p;
  p.normal_stiffness = 10e9;  // Pa/m
  p.shear_stiffness = 5e9;
  p.friction_angle = 30 * kDeg;
  p.cohesion = 0.5e6;
  p.tensile_strength = 0.2e6;
  p.dilation_angle = 10 * kDeg;
  p.zero_dilation_displacement = 2e-3;
  return p;
}

/// The joint brought to the normal stress `sigma` without shear.
CoulombSlip::State preloaded(const CoulombSlip& law, double sigma) {
  return constant_stress_step(law, law.initial_state(), 0, sigma).state;
}

TEST(JointCoulomb, DirectShearAtConstantNormalStressGivesPeakResidualAndDilation) {
  const CoulombProperties p = properties();
  const CoulombSlip law(p);
  const double sigma = 2e6;
  const double tan_phi = std::tan(p.friction_angle), tan_psi = std::tan(p.dilation_angle);
  const double peak = p.cohesion + sigma * tan_phi, residual = sigma * tan_phi;
  const double u_yield = peak / p.shear_stiffness;  // 0.33 mm
  const double u_cs = p.zero_dilation_displacement;
  CoulombSlip::State s = preloaded(law, sigma);
  const double u_n0 = s.normal_displacement;

  // 300 steps of 0.02 mm to 6 mm: 16 elastic, the 17th fails, and u_cs is
  // crossed at a step's end.
  const double h = 2e-5;
  bool failed = false;
  for (int k = 1; k <= 300; ++k) {
    const auto step = constant_stress_step(law, s, h, sigma);
    s = step.state;
    const double u = k * h;
    ASSERT_NEAR(step.response.normal_stress, sigma, kStressTol * sigma);
    if (u < u_yield) {
      // Elastic: slope k_s, cohesion intact, no dilation.
      EXPECT_NEAR(step.response.shear_stress, p.shear_stiffness * u, kStressTol * peak) << u;
      EXPECT_TRUE(s.intact);
      EXPECT_FALSE(step.response.slipping);
      EXPECT_EQ(s.dilation, 0);
      EXPECT_NEAR(step.response.shear_strength, peak, kStressTol * peak);
      continue;
    }
    // Past the peak: residual strength, cohesion lost for good.
    failed = true;
    EXPECT_TRUE(step.response.slipping) << u;
    EXPECT_FALSE(s.intact);
    EXPECT_NEAR(step.response.shear_stress, residual, kStressTol * peak) << u;
    // Plastic slip: all of u but the elastic share of the residual stress;
    // dilation tan(psi) per unit of it while |u_s| < u_cs, then flat.
    const double slip = u - residual / p.shear_stiffness;
    EXPECT_NEAR(s.plastic_shear, slip, kLengthTol * u_cs) << u;
    const double dilation = tan_psi * (std::min(u, u_cs) - residual / p.shear_stiffness);
    EXPECT_NEAR(s.dilation, dilation, kLengthTol * u_cs) << u;
    // The walls open by the dilation at constant normal stress.
    EXPECT_NEAR(s.normal_displacement - u_n0, dilation, kLengthTol * u_cs) << u;
  }
  EXPECT_TRUE(failed);
  EXPECT_GT(s.dilation, 0);
}

TEST(JointCoulomb, TensionCutOffOpensTheJointAndLosesTheBond) {
  CoulombProperties p = properties();
  p.tensile_strength = 0.205e6;
  const CoulombSlip law(p);
  const double kn = p.normal_stiffness;
  CoulombSlip::State s = law.initial_state();
  // Pull in steps of 1 um: sigma_n = -k_n u_n = -10 kPa per step until the
  // tension exceeds T = 0.205 MPa (the 21st step; T between two steps, so
  // that rounding cannot move it).
  const double h = 1e-6;
  int opened_at = 0;
  for (int k = 1; k <= 30 && !opened_at; ++k) {
    CoulombSlip::State next;
    const auto r = law.update(s, JointIncrement{h, 0, 1}, next);
    s = next;
    if (kn * k * h > p.tensile_strength) {
      opened_at = k;
      EXPECT_TRUE(r.open);
      EXPECT_EQ(r.normal_stress, 0);
      EXPECT_EQ(r.shear_stress, 0);
      EXPECT_FALSE(s.intact);
    } else {
      EXPECT_FALSE(r.open) << k;
      EXPECT_NEAR(r.normal_stress, -kn * k * h, kStressTol * p.tensile_strength);
      EXPECT_TRUE(s.intact);
    }
  }
  EXPECT_EQ(opened_at, 21);

  // Closed again under compression, then pulled: the bond is gone, so the
  // joint opens at the first tension and slides at sigma_n tan(phi) alone.
  const double sigma = 1e6;
  s = constant_stress_step(law, s, 0, sigma).state;
  EXPECT_FALSE(s.intact);
  CoulombSlip::State pulled;
  const auto r = law.update(s, JointIncrement{sigma / kn + 1e-9, 0, 1}, pulled);
  EXPECT_TRUE(r.open);
  const auto sheared = constant_stress_step(law, s, 1e-3, sigma);
  EXPECT_TRUE(sheared.response.slipping);
  EXPECT_NEAR(sheared.response.shear_stress, sigma * std::tan(p.friction_angle),
              kStressTol * sigma);
}

// Constant normal stiffness K (the surroundings of a joint in a rock mass):
// sigma_n = sigma_0 + K w with w the walls' normal displacement. Slipping,
// tau = sigma_n tan(phi) and the dilation d = tan(psi) p raise sigma_n by
// K_eff d, K_eff = K k_n / (K + k_n) (the joint's own spring in series), and
// u_s = tau / k_s + p gives, past u_y = sigma_0 tan(phi) / k_s,
//   p = (u_s - u_y) / (1 + K_eff tan(psi) tan(phi) / k_s).
TEST(JointCoulomb, ConstantNormalStiffnessFollowsTheFrictionLine) {
  CoulombProperties p = properties();
  p.cohesion = 0;
  p.tensile_strength = 0;
  p.zero_dilation_displacement = 0;  // no limit
  p.dilation_angle = 15 * kDeg;
  const CoulombSlip law(p);
  const double sigma0 = 2e6, K = 4e9;
  const double tan_phi = std::tan(p.friction_angle), tan_psi = std::tan(p.dilation_angle);
  const double K_eff = K * p.normal_stiffness / (K + p.normal_stiffness);
  const double u_yield = sigma0 * tan_phi / p.shear_stiffness;
  CoulombSlip::State s = preloaded(law, sigma0);
  const double u_n0 = s.normal_displacement;

  const double h = 3e-5;
  int slipping_steps = 0;
  for (int k = 1; k <= 200; ++k) {
    const double w0 = s.normal_displacement - u_n0;
    const auto step = servo_step(law, s, h, [&](double x) { return sigma0 + K * (w0 + x); });
    s = step.state;
    const double u = k * h;
    const double sigma = step.response.normal_stress, tau = step.response.shear_stress;
    // The boundary: sigma_n - sigma_0 = K w, at every step.
    EXPECT_NEAR(sigma - sigma0, K * (s.normal_displacement - u_n0), kStressTol * sigma0);
    if (u < u_yield) {
      EXPECT_NEAR(tau, p.shear_stiffness * u, kStressTol * sigma0);
      EXPECT_NEAR(sigma, sigma0, kStressTol * sigma0);
      continue;
    }
    ++slipping_steps;
    // On the friction line, exactly.
    EXPECT_NEAR(tau, sigma * tan_phi, kStressTol * sigma0) << u;
    const double slip = (u - u_yield) / (1 + K_eff * tan_psi * tan_phi / p.shear_stiffness);
    EXPECT_NEAR(s.plastic_shear, slip, kLengthTol * u) << u;
    EXPECT_NEAR(sigma, sigma0 + K_eff * tan_psi * slip, kStressTol * sigma0) << u;
  }
  EXPECT_GT(slipping_steps, 150);
  EXPECT_GT(s.normal_stress, 1.5 * sigma0);  // the test measures a real rise
}

}  // namespace
}  // namespace fissure::testing
