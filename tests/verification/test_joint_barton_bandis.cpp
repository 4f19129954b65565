// verification.md (q), (r), docs/joints.md 5.2: the Barton-Bandis joint
// against its closed forms. Each test's expected values are computed here
// from the published formulas (Barton and Choubey 1977, Barton and Bandis
// 1982, Bandis et al. 1983, Barton et al. 1985), not from the library's
// helpers. The strength curve and the normal closure are functions of the
// displacements, so the law meets them at any step to rounding: 1e-16 per
// operation over up to 1,200 accumulated steps (the shear displacement is
// a sum of steps) gives ~1e-13; the tolerance 1e-11 sits above that. The
// dilation is the one integral: its midpoint rule's error is bounded from
// the step (see DilationFollowsThe...).
//
// Mutations checked (each failed here): the JCS scale exponent -0.02 JRC_0
// instead of -0.03 JRC_0; the table's 0.85 at delta/delta_peak = 2 as 0.8;
// the peak displacement with exponent 0.5; the Bandis tangent
// k_ni (1 + sigma_n/(k_ni V_m)); the hydraulic aperture E^2/JRC^2; the
// dilation angle without the factor 0.5.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "rockmass/joints/barton_bandis.h"
#include "tests/support/joint_driver.h"

namespace fissure::testing {
namespace {

using joints::BartonBandis;
using joints::BartonBandisProperties;
using joints::JointIncrement;

constexpr double kDeg = std::numbers::pi / 180;
constexpr double kTol = 1e-11;

// A granite-like joint: JRC_0 10 and JCS_0 100 MPa on 100 mm samples, in
// the field on 1 m blocks; E_0 0.5 mm; k_ni and V_m from the regressions.
BartonBandisProperties properties() {
  BartonBandisProperties p;
  p.jrc = 10;
  p.jcs = 100e6;
  p.lab_length = 0.1;
  p.field_length = 1.0;
  p.residual_friction_angle = 28 * kDeg;
  p.initial_aperture = 0.5e-3;
  return p;
}

// The closed forms, written out.
double jrc_n(const BartonBandisProperties& p) {
  return p.jrc * std::pow(p.field_length / p.lab_length, -0.02 * p.jrc);
}
double jcs_n(const BartonBandisProperties& p) {
  return p.jcs * std::pow(p.field_length / p.lab_length, -0.03 * p.jrc);
}
double delta_peak(const BartonBandisProperties& p) {
  return p.field_length / 500 * std::pow(jrc_n(p) / p.field_length, 0.33);
}
/// i = JRC_n log10(JCS_n / sigma_n), in degrees (below the 70 degree cap here).
double roughness_degrees(const BartonBandisProperties& p, double sigma) {
  return jrc_n(p) * std::log10(jcs_n(p) / sigma);
}

TEST(JointBartonBandis, ScaleCorrectionsFollowBartonAndBandis) {
  const BartonBandisProperties p = properties();
  // (L_n / L_0)^(-0.02 JRC_0) = 10^-0.2 and (L_n / L_0)^(-0.03 JRC_0) = 10^-0.3.
  EXPECT_NEAR(joints::scaled_jrc(p.jrc, p.lab_length, p.field_length), 10 * std::pow(10, -0.2),
              kTol * 10);
  EXPECT_NEAR(joints::scaled_jcs(p.jcs, p.jrc, p.lab_length, p.field_length),
              100e6 * std::pow(10, -0.3), kTol * 100e6);
  EXPECT_NEAR(joints::peak_shear_displacement(jrc_n(p), p.field_length),
              0.002 * std::pow(jrc_n(p), 0.33), kTol * 1e-3);
  // No correction at the lab length.
  EXPECT_EQ(joints::scaled_jrc(p.jrc, 0.1, 0.1), p.jrc);
  EXPECT_EQ(joints::scaled_jcs(p.jcs, p.jrc, 0.1, 0.1), p.jcs);
  // Barton (1982): delta_peak is about 1 % of a 100 mm sample's length.
  EXPECT_NEAR(joints::peak_shear_displacement(p.jrc, 0.1) / 0.1, 0.01, 0.001);
}

TEST(JointBartonBandis, BandisRegressionsGiveTheFirstLoadingParameters) {
  const BartonBandis law(properties());
  // JCS_0 / E_0 = 100 MPa / 0.5 mm = 200 MPa/mm.
  const double kni = -7.15 + 1.75 * 10 + 0.02 * 200;                        // MPa/mm
  const double vm = -0.1032 - 0.0074 * 10 + 1.135 * std::pow(200, -0.251);  // mm
  EXPECT_NEAR(law.closure().initial_normal_stiffness, kni * 1e9, kTol * 1e10);
  EXPECT_NEAR(law.closure().max_closure, vm * 1e-3, kTol * 1e-4);
}

// Direct shear at sigma_n = 2 MPa in steps of delta_peak / 10 to 120
// delta_peak: the mobilized curve through the table's points, the peak at
// delta_peak, the residual beyond 100 delta_peak.
TEST(JointBartonBandis, MobilizedCurveHitsThePeakAndTheTablePoints) {
  const BartonBandisProperties p = properties();
  const BartonBandis law(p);
  const double sigma = 2e6, phi_r = p.residual_friction_angle;
  const double i = roughness_degrees(p, sigma) * kDeg, dp = delta_peak(p);
  // Barton et al. (1985): JRC_mob / JRC_peak at delta / delta_peak.
  const std::vector<std::pair<int, double>> table = {{3, 0},     {6, 0.75},   {10, 1},  {20, 0.85},
                                                     {40, 0.70}, {100, 0.50}, {1000, 0}};
  BartonBandis::State s = constant_stress_step(law, law.initial_state(), 0, sigma).state;
  int checked = 0;
  for (int k = 1; k <= 1200; ++k) {
    const auto step = constant_stress_step(law, s, dp / 10, sigma);
    s = step.state;
    const double tau = step.response.shear_stress;
    double ratio = 0;  // JRC_mob / JRC_peak
    if (k < 3) {
      ratio = -phi_r / i * (1 - k / 3.0);  // from -phi_r / i at 0 to 0 at 0.3
    } else if (k > 1000) {
      ratio = 0;  // residual
    } else {
      const auto row =
          std::find_if(table.begin(), table.end(), [k](const auto& r) { return r.first == k; });
      if (row == table.end()) continue;
      ratio = row->second;
    }
    const double expected = sigma * std::tan(ratio * i + phi_r);
    EXPECT_NEAR(tau, expected, kTol * sigma) << "delta / delta_peak = " << k / 10.0;
    ++checked;
    if (k == 10) {  // the peak: Barton and Choubey's JRC-JCS strength
      EXPECT_NEAR(tau, sigma * std::tan((roughness_degrees(p, sigma) + 28) * kDeg), kTol * sigma);
    }
  }
  EXPECT_EQ(checked, 2 + 7 + 200);
  EXPECT_NEAR(s.shear_stress, sigma * std::tan(phi_r), kTol * sigma);
}

// Dilation d = integral of tan(psi_mob) d delta with psi_mob = 0.5 JRC_mob
// log10(JCS_n/sigma_n) = 0.5 (JRC_mob/JRC_peak) i: linear in delta within a
// segment of the table, where the integral is [-ln cos psi] / (d psi/d delta).
// The law takes psi at each step's middle (the midpoint rule), whose error
// per step is at most h^3/24 max|f''| with f = tan(psi(delta)), f'' = 2
// beta^2 tan(psi) sec^2(psi), beta = d psi / d delta; summed over the steps
// that is the tolerance.
TEST(JointBartonBandis, DilationFollowsTheMobilizedDilationAngle) {
  const BartonBandisProperties p = properties();
  const BartonBandis law(p);
  const double sigma = 2e6, i = roughness_degrees(p, sigma) * kDeg, dp = delta_peak(p);
  const std::vector<double> x = {0.3, 0.6, 1, 2, 4, 10};
  const std::vector<double> ratio = {0, 0.75, 1, 0.85, 0.70, 0.50};
  const double h = dp / 10;
  double exact = 0, bound = 0;
  for (std::size_t k = 0; k + 1 < x.size(); ++k) {
    const double a = 0.5 * ratio[k] * i, b = 0.5 * ratio[k + 1] * i;
    const double length = (x[k + 1] - x[k]) * dp, beta = (b - a) / length;
    exact += (std::log(std::cos(a)) - std::log(std::cos(b))) / beta;
    const double psi = std::max(a, b);
    const double f2 = 2 * beta * beta * std::tan(psi) / (std::cos(psi) * std::cos(psi));
    bound += length / h * h * h * h / 24 * f2;
  }
  BartonBandis::State s = constant_stress_step(law, law.initial_state(), 0, sigma).state;
  for (int k = 1; k <= 100; ++k) {
    s = constant_stress_step(law, s, h, sigma).state;
    if (k == 3) {
      EXPECT_EQ(s.dilation, 0);  // no dilation before JRC_mob > 0
    }
  }
  EXPECT_GT(exact, 0.02 * dp);
  EXPECT_NEAR(s.dilation, exact, bound + kTol * exact);
  EXPECT_LT(bound, 1e-4 * exact);  // the check is sharp
}

// Normal loading to 20 MPa (below JCS_n) and unloading in 100 steps each:
// dV = sigma_n V_m / (k_ni V_m + sigma_n) on both, k_n = k_ni (1 +
// sigma_n / (k_ni V_m))^2 its derivative (checked against a central
// difference of the law itself, to the difference's O(eps^2) + rounding/eps
// error, 1e-6).
TEST(JointBartonBandis, BandisHyperbolaOnLoadingAndUnloading) {
  const BartonBandisProperties p = properties();
  const BartonBandis law(p);
  const double kni = law.closure().initial_normal_stiffness, vm = law.closure().max_closure;
  const double sigma_max = 20e6;
  const double closure_max = sigma_max * vm / (kni * vm + sigma_max);
  const double h = closure_max / 100;
  BartonBandis::State s = law.initial_state();
  std::vector<double> loading(101, 0.0);
  const auto check = [&](const joints::JointResponse& r, const BartonBandis::State& state) {
    const double closure = -state.normal_displacement, sigma = r.normal_stress;
    EXPECT_NEAR(sigma, kni * vm * closure / (vm - closure), kTol * sigma_max);
    EXPECT_NEAR(closure, sigma * vm / (kni * vm + sigma), kTol * vm);
    const double kn = kni * std::pow(1 + sigma / (kni * vm), 2);
    EXPECT_NEAR(r.normal_stiffness, kn, kTol * kn);
    const double eps = 1e-6 * closure;
    BartonBandis::State plus, minus;
    const double difference = (law.update(state, JointIncrement{-eps, 0, 1}, plus).normal_stress -
                               law.update(state, JointIncrement{eps, 0, 1}, minus).normal_stress) /
                              (2 * eps);
    EXPECT_NEAR(r.normal_stiffness, difference, 1e-6 * kn);
  };
  for (int k = 1; k <= 100; ++k) {
    BartonBandis::State next;
    const auto r = law.update(s, JointIncrement{-h, 0, 1}, next);
    s = next;
    check(r, s);
    loading[k] = r.normal_stress;
  }
  EXPECT_NEAR(loading[100], sigma_max, 1e-9 * sigma_max);
  for (int k = 99; k >= 1; --k) {
    BartonBandis::State next;
    const auto r = law.update(s, JointIncrement{h, 0, 1}, next);
    s = next;
    check(r, s);
    EXPECT_NEAR(r.normal_stress, loading[k], kTol * sigma_max) << "no hysteresis";
  }
  BartonBandis::State next;
  EXPECT_TRUE(law.update(s, JointIncrement{h * 1.5, 0, 1}, next).open);
}

TEST(JointBartonBandis, HydraulicApertureFromTheMechanicalOne) {
  // e = E^2 / JRC^2.5 in micrometres: 100 um at JRC 10 gives 31.62 um.
  EXPECT_NEAR(joints::hydraulic_aperture(100e-6, 10), 1e4 / std::pow(10, 2.5) * 1e-6, kTol * 1e-4);
  // Never above E (Barton et al. 1985: e <= E), and E for a smooth joint.
  EXPECT_EQ(joints::hydraulic_aperture(20e-6, 2), 20e-6);
  EXPECT_EQ(joints::hydraulic_aperture(20e-6, 0), 20e-6);

  // The law's mechanical aperture: E_0 less the closure at sigma_n.
  const BartonBandisProperties p = properties();
  const BartonBandis law(p);
  const double sigma = 5e6;
  const BartonBandis::State s = constant_stress_step(law, law.initial_state(), 0, sigma).state;
  const double kni = law.closure().initial_normal_stiffness, vm = law.closure().max_closure;
  const double E = p.initial_aperture - sigma * vm / (kni * vm + sigma);
  EXPECT_NEAR(law.mechanical_aperture(s), E, kTol * p.initial_aperture);
  // E = 0.41 mm at JRC_0 10 gives E^2/JRC^2.5 = 529 um > E: e = E. At
  // 0.1 mm (a joint closed to a fifth of that) the formula's 31.6 um.
  const double e_um = std::pow(E / 1e-6, 2) / std::pow(p.jrc, 2.5);
  EXPECT_GT(e_um * 1e-6, E);
  EXPECT_EQ(joints::hydraulic_aperture(law.mechanical_aperture(s), p.jrc),
            law.mechanical_aperture(s));
}

}  // namespace
}  // namespace fissure::testing
