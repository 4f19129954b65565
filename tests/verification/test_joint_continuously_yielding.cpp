// verification.md (s), docs/joints.md 5.3: the continuously yielding joint
// against its ODEs. On a monotonic path at constant sigma_n (r = 0) the law
// is
//   d tau / du = k_s (1 - tau/tau_m),  du^p/du = tau/tau_m,
//   d u_dil / du = tan(psi) tau/tau_m,  psi = max(0, atan(tau/sigma_n) - phi),
//   tau_m = sigma_n tan(phi + (phi_m0 - phi) exp(-u^p / R)),
// which has no closed form; the reference integrates it with classical
// Runge-Kutta in 80,000 steps (its error, O(h^4), is below 1e-10 of the
// stress scale: doubling its step changes the result by less than that).
// The law steps it with forward Euler (the rates at the start of a step), so
// its error must fall as the step: the test measures the observed order
// log2(e(h) / e(h/2)) at three steps and requires it in [0.9, 1.1], and the
// error at each step below 1.5 x (the finest step's error scaled up by the
// step ratio), i.e. first order with a constant that does not grow.
//
// Measured (800 steps of 5 um): tau within 1.25e4 Pa of the reference
// (0.8 % of the 1.62 MPa peak), halving with the step (5.19e4, 2.53e4,
// 1.25e4 Pa at 200, 400, 800 steps); dilation 5.4, 2.6, 1.3 um.
//
// Mutations checked (each failed here): phi_m decayed with the total shear
// u instead of the plastic u^p (the error stops falling: 9.4e4, 1.01e5,
// 1.05e5 Pa); F without the division by (1 - r) (ReversalResetsR); the
// dilation angle without "- phi" (dilation off by 2.3 mm at every step).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "rockmass/joints/continuously_yielding.h"
#include "tests/support/joint_driver.h"

namespace fissure::testing {
namespace {

using joints::ContinuouslyYielding;
using joints::ContinuouslyYieldingProperties;
using joints::JointIncrement;

constexpr double kDeg = std::numbers::pi / 180;

ContinuouslyYieldingProperties properties() {
  ContinuouslyYieldingProperties p;
  p.normal_stiffness = 20e9;  // Pa/m at 1 MPa
  p.normal_stiffness_exponent = 0.5;
  p.shear_stiffness = 10e9;
  p.shear_stiffness_exponent = 0.3;
  p.reference_normal_stress = 1e6;
  p.friction_angle = 30 * kDeg;
  p.initial_friction_angle = 45 * kDeg;
  p.roughness_length = 0.5e-3;
  return p;
}

constexpr double kSigma = 2e6;   // the test's constant normal stress
constexpr double kTotal = 4e-3;  // shear to 4 mm (the peak near 0.3 mm)

/// The reference: (tau, u^p, u_dil) along u, classical RK4 with r = r0
/// fixed, starting from tau0 (u^p = u_dil = 0 at u = 0; direction +1).
struct Reference {
  std::vector<double> tau, dilation;  ///< at u = k * kTotal / n
};
Reference integrate(const ContinuouslyYieldingProperties& p, double ks, int n, double tau0 = 0,
                    double phi_m0 = -1, double r0 = 0, double direction = 1,
                    double total = kTotal) {
  using Y = std::array<double, 3>;  // tau, u^p, u_dil
  const double phi = p.friction_angle;
  const double start = phi_m0 < 0 ? p.initial_friction_angle : phi_m0;
  const auto rate = [&](const Y& y) {
    const double tau_m =
        direction * kSigma * std::tan(phi + (start - phi) * std::exp(-y[1] / p.roughness_length));
    const double F = (1 - y[0] / tau_m) / (1 - r0);
    const double psi = std::max(0.0, std::atan(std::abs(y[0]) / kSigma) - phi);
    return Y{F * ks * direction, 1 - F, std::tan(psi) * (1 - F)};
  };
  const double h = total / n;
  Y y{tau0, 0, 0};
  Reference out;
  out.tau.push_back(y[0]);
  out.dilation.push_back(y[2]);
  for (int k = 0; k < n; ++k) {
    const auto add = [](const Y& a, const Y& b, double f) {
      return Y{a[0] + f * b[0], a[1] + f * b[1], a[2] + f * b[2]};
    };
    const Y k1 = rate(y), k2 = rate(add(y, k1, h / 2)), k3 = rate(add(y, k2, h / 2)),
            k4 = rate(add(y, k3, h));
    for (int j = 0; j < 3; ++j) y[j] += h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
    out.tau.push_back(y[0]);
    out.dilation.push_back(y[2]);
  }
  return out;
}

/// The law's path at constant sigma_n in n steps: the largest errors of tau
/// and of the dilation against `ref` (sampled every n_ref / n of its points).
std::pair<double, double> errors(const ContinuouslyYielding& law, int n, const Reference& ref) {
  ContinuouslyYielding::State s = constant_stress_step(law, law.initial_state(), 0, kSigma).state;
  const double d0 = s.dilation;
  const int stride = static_cast<int>(ref.tau.size() - 1) / n;
  double e_tau = 0, e_dil = 0;
  for (int k = 1; k <= n; ++k) {
    s = constant_stress_step(law, s, kTotal / n, kSigma).state;
    e_tau = std::max(e_tau, std::abs(s.shear_stress - ref.tau[k * stride]));
    e_dil = std::max(e_dil, std::abs(s.dilation - d0 - ref.dilation[k * stride]));
  }
  return {e_tau, e_dil};
}

TEST(JointContinuouslyYielding, MonotonicShearConvergesAtFirstOrderToTheOde) {
  const ContinuouslyYieldingProperties p = properties();
  const ContinuouslyYielding law(p);
  const double ks = p.shear_stiffness * std::pow(kSigma / p.reference_normal_stress, 0.3);
  ASSERT_DOUBLE_EQ(law.shear_stiffness(kSigma), ks);
  const Reference ref = integrate(p, ks, 80000), half = integrate(p, ks, 40000);
  // The reference's own error: below 1e-10 of tau_m.
  const double tau_scale = kSigma * std::tan(p.initial_friction_angle);
  for (std::size_t k = 0; k < half.tau.size(); ++k)
    ASSERT_NEAR(half.tau[k], ref.tau[2 * k], 1e-10 * tau_scale);
  // The path peaks and softens towards sigma_n tan(phi).
  const double peak = *std::max_element(ref.tau.begin(), ref.tau.end());
  EXPECT_GT(peak, 1.2 * kSigma * std::tan(p.friction_angle));
  EXPECT_LT(std::abs(ref.tau.back() - kSigma * std::tan(p.friction_angle)),
            0.05 * kSigma * std::tan(p.friction_angle));

  const std::array<int, 3> steps = {200, 400, 800};  // 20, 10 and 5 um
  std::array<std::pair<double, double>, 3> e;
  for (int k = 0; k < 3; ++k) e[k] = errors(law, steps[k], ref);
  for (int k = 0; k < 3; ++k)
    RecordProperty("tau_error_" + std::to_string(steps[k]) + "_steps", std::to_string(e[k].first));
  for (int k = 0; k + 1 < 3; ++k) {
    const double order_tau = std::log2(e[k].first / e[k + 1].first);
    const double order_dilation = std::log2(e[k].second / e[k + 1].second);
    EXPECT_GT(order_tau, 0.9) << steps[k];
    EXPECT_LT(order_tau, 1.1) << steps[k];
    EXPECT_GT(order_dilation, 0.9) << steps[k];
    EXPECT_LT(order_dilation, 1.1) << steps[k];
  }
  for (int k = 0; k < 3; ++k)
    EXPECT_LT(e[k].first, 1.5 * e[2].first * steps[2] / steps[k]) << steps[k];
  // Small in absolute terms too: at 5 um steps, under 1 % of the peak.
  EXPECT_LT(e[2].first, 0.01 * peak);
  std::printf("CY tau error: %.4g Pa (200 steps), %.4g (400), %.4g (800); peak %.4g Pa\n",
              e[0].first, e[1].first, e[2].first, peak);
  std::printf("CY dilation error: %.4g m, %.4g, %.4g\n", e[0].second, e[1].second, e[2].second);
}

// A reversal resets r to tau / tau_m (in the new direction): the first
// reversed step is elastic (F = 1, no plastic shear), and the reversed path
// follows the ODE with that r (measured: within 2.5e-4 tau_m at 0.2 um
// steps). The same ODE with r = 0 (no reset) lies 36 % of tau_m away, far
// outside the tolerance.
TEST(JointContinuouslyYielding, ReversalResetsR) {
  const ContinuouslyYieldingProperties p = properties();
  const ContinuouslyYielding law(p);
  const double ks = law.shear_stiffness(kSigma);
  ContinuouslyYielding::State s = constant_stress_step(law, law.initial_state(), 0, kSigma).state;
  const int n = 1000;
  const double h = 0.2e-3 / n;  // forward 0.2 mm, before the peak
  for (int k = 0; k < n; ++k) s = constant_stress_step(law, s, h, kSigma).state;
  const double tau0 = s.shear_stress, phi_m0 = s.bounding_friction_angle;
  ASSERT_GT(tau0, 0);

  // The first reversed step: F = 1.
  const auto first = constant_stress_step(law, s, -h, kSigma);
  const double r = tau0 / (-kSigma * std::tan(phi_m0));
  EXPECT_NEAR(first.state.reversal_ratio, r, 1e-12 * std::abs(r));
  EXPECT_EQ(first.response.plastic_shear, 0);
  EXPECT_NEAR(first.state.shear_stress, tau0 - ks * h, 1e-9 * tau0);

  // Then 0.6 mm backwards against the ODE with r (step 0.2 um: the Euler
  // error ~1e-3 of tau_m at this step, per the first-order constant above).
  const double back = 0.6e-3;
  const Reference with_r = integrate(p, ks, 6000, tau0, phi_m0, r, -1, back);
  const Reference without = integrate(p, ks, 6000, tau0, phi_m0, 0, -1, back);
  const double tau_m = kSigma * std::tan(phi_m0);
  const int m = 3000;
  ContinuouslyYielding::State b = s;
  double error = 0, apart = 0;
  for (int k = 1; k <= m; ++k) {
    b = constant_stress_step(law, b, -back / m, kSigma).state;
    error = std::max(error, std::abs(b.shear_stress - with_r.tau[2 * k]));
    apart = std::max(apart, std::abs(with_r.tau[2 * k] - without.tau[2 * k]));
  }
  std::printf("CY reversal: error %.3g of tau_m, r = 0 lies %.3g of tau_m away\n", error / tau_m,
              apart / tau_m);
  EXPECT_LT(error, 0.005 * tau_m);
  EXPECT_GT(apart, 10 * 0.005 * tau_m);
  EXPECT_LT(b.shear_stress, 0);  // it has sheared the other way
}

// The normal law k_n = k_n,ref (sigma_n / sigma_ref)^e_n integrated exactly:
// its tangent is that stiffness (a central difference of the law, to its
// O(eps^2) + rounding/eps error, 1e-6), one curve for loading and unloading,
// no tension.
TEST(JointContinuouslyYielding, NormalStiffnessGrowsWithTheStressWithoutTension) {
  const ContinuouslyYieldingProperties p = properties();
  const ContinuouslyYielding law(p);
  ContinuouslyYielding::State s = law.initial_state();
  const double h = 4.7e-6;  // the floor's corner, 5 um, inside a step
  std::vector<double> loading;
  for (int k = 1; k <= 100; ++k) {
    ContinuouslyYielding::State next;
    const auto r = law.update(s, JointIncrement{-h, 0, 1}, next);
    s = next;
    loading.push_back(r.normal_stress);
    const double expected =
        p.normal_stiffness *
        std::pow(std::max(r.normal_stress / p.reference_normal_stress, 0.01), 0.5);
    EXPECT_NEAR(r.normal_stiffness, expected, 1e-12 * expected);
    const double eps = 1e-6 * k * h;
    ContinuouslyYielding::State a, b;
    const double difference = (law.update(s, JointIncrement{-eps, 0, 1}, a).normal_stress -
                               law.update(s, JointIncrement{eps, 0, 1}, b).normal_stress) /
                              (2 * eps);
    EXPECT_NEAR(difference, expected, 1e-6 * expected) << k;
  }
  EXPECT_GT(loading.back(), 10e6);
  for (int k = 98; k >= 0; --k) {
    ContinuouslyYielding::State next;
    const auto r = law.update(s, JointIncrement{h, 0, 1}, next);
    s = next;
    EXPECT_NEAR(r.normal_stress, loading[k], 1e-11 * loading.back());
  }
  ContinuouslyYielding::State next;
  const auto r = law.update(s, JointIncrement{2 * h, 0, 1}, next);
  EXPECT_TRUE(r.open);
  EXPECT_EQ(r.normal_stress, 0);
}

}  // namespace
}  // namespace fissure::testing
