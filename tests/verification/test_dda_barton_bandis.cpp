// The DDA with a Barton-Bandis joint (docs/dda.md section 9): its contacts'
// friction is Barton's mobilized strength, tan(JRC_mob log10(JCS / sigma_n)
// + phi_r) at their normal stress and shear history (Barton and Choubey
// 1977; Barton 1982's mobilization), explicit in each step. Both scenes take
// the field length equal to the lab length (no scale correction): JRC, JCS
// and delta_peak = (L/500) (JRC/L)^0.33 are the lab's.
//  * A 2 x 0.2 m block on an incline (sigma_n = rho g h cos a; a flat block,
//    so that the overturning moment of the friction changes the two corner
//    contacts' sigma_n by only +-(h/b) tan a = 10 %, a second-order change
//    of their summed strength): in static steps it stops where the
//    mobilized friction angle reaches the slope when that is below the peak
//    friction angle, and slides on into the softening branch when the slope
//    is a degree above it.
//  * Dynamic, on a slope well above the peak: once the slip is past
//    100 delta_peak the joint is at its residual friction and the block
//    accelerates at g (sin a - cos a tan phi_r).
//  * Direct shear: a block under a constant normal load pushed sideways by
//    a slowly growing force (static steps); the largest shear force the
//    joint carries is sigma_n tan(JRC log10(JCS / sigma_n) + phi_r) times
//    the contact length.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "mechanics/dda/dda_process.h"
#include "rockmass/joints/joint_model.h"
#include "tests/support/dda_scenes.h"

namespace fissure::testing {
namespace {

constexpr double kDeg = std::numbers::pi / 180;
constexpr double kG = 9.81, kDensity = 2700;

joints::BartonBandisProperties barton_bandis(double jrc, double jcs, double residual_deg) {
  joints::BartonBandisProperties p;
  p.jrc = jrc;
  p.jcs = jcs;
  p.lab_length = p.field_length = 0.1;
  p.residual_friction_angle = residual_deg * kDeg;
  p.initial_aperture = 0.5e-3;
  return p;
}

void use_law(Scene& s, const joints::BartonBandisProperties& p) {
  s.joints[0].friction_angle = p.residual_friction_angle;
  s.joints[0].model.set(joints::kJointModel, joints::JointModel{p});
}

/// Barton's peak friction angle (rad) at sigma_n (below the 70 degree cap).
double peak_friction(const joints::BartonBandisProperties& p, double sigma) {
  return p.jrc * std::log10(p.jcs / sigma) * kDeg + p.residual_friction_angle;
}

double peak_displacement(const joints::BartonBandisProperties& p) {
  return p.field_length / 500 * std::pow(p.jrc / p.field_length, 0.33);
}

// The incline: JRC 5, JCS 50 MPa, phi_r 25 degrees; the block 2 x 0.2 m.
constexpr double kWidth = 2.0, kHeight = 0.2;
const joints::BartonBandisProperties kInclineJoint = barton_bandis(5, 50e6, 25);

double incline_stress(double slope) {
  return kDensity * kG * kHeight * std::cos(slope);
}

/// The block's centroid path down the slope, one entry per accepted step
/// (t, slip, velocity along the slope).
struct Path {
  std::vector<double> t, slip, velocity;
};

Path slide_on_incline(double slope_deg, double dt, double velocity_carry_over, double end_time) {
  Scene s = incline_scene(slope_deg, 25, dt, 5e9, end_time, kWidth, kHeight);
  use_law(s, kInclineJoint);
  mechanics_controls(s).dda.velocity_carry_over = velocity_carry_over;
  RockMass state = RockMass::from_scene(s);
  dda::DdaProcess dda(s);
  dda.initialize(state);
  const double a = slope_deg * kDeg;
  const Vec2 down(-std::cos(a), -std::sin(a));
  const Vec2 start = state.blocks[1].section.centroid;
  Path path;
  double t = 0;
  while (t < end_time - 1e-12) {
    const double step = std::min(dda.proposed_dt(state), end_time - t);
    if (dda.advance(state, t, step).status != StepReport::Status::Ok) continue;
    t += step;
    path.t.push_back(t);
    path.slip.push_back((state.blocks[1].section.centroid - start).dot(down));
    path.velocity.push_back(state.blocks[1].velocity.head<2>().dot(down));
  }
  return path;
}

TEST(DdaBartonBandisIncline, SlidesOnlyWhenTheSlopeExceedsThePeakFrictionAngle) {
  // The peak friction angle is 45.6 degrees at the slopes' sigma_n (3.7 kPa):
  // slopes a degree either side of it. Static steps of 10 ms: each moves a
  // sliding block g (sin a - cos a tan phi_mob) dt^2 / 2, from rest.
  const double below = 44.6, above = 46.7, dt = 0.01;
  const double peak_below = peak_friction(kInclineJoint, incline_stress(below * kDeg)) / kDeg;
  const double peak_above = peak_friction(kInclineJoint, incline_stress(above * kDeg)) / kDeg;
  ASSERT_NEAR(below, peak_below - 1, 0.05);
  ASSERT_NEAR(above, peak_above + 1, 0.05);
  const double delta_peak = peak_displacement(kInclineJoint);

  const Path stays = slide_on_incline(below, dt, 0, 5.0);
  const Path slides = slide_on_incline(above, dt, 0, 5.0);
  // Below the peak the slip mobilizes the roughness until phi_mob = a, at
  // delta / delta_peak = x* (0.921: on the table's segment 0.6 -> 1 of
  // JRC_mob / JRC_peak 0.75 -> 1), and stops there. Before that, the first
  // step: the block set down on the joint has no normal force at its start,
  // so no strength (phi_mob = 0 at rest) and no mobilization in it (the
  // law's explicit step, docs/dda.md section 9): it slides g sin a dt^2 / 2.
  const double i = peak_below * kDeg - kInclineJoint.residual_friction_angle;
  const double ratio = (below * kDeg - kInclineJoint.residual_friction_angle) / i;
  const double x_star = 0.6 + 0.4 * (ratio - 0.75) / 0.25;
  const double first_step = kG * std::sin(below * kDeg) * dt * dt / 2;
  const double mobilized = (stays.slip.back() - first_step) / delta_peak;
  const double last_second = stays.slip.back() - stays.slip[stays.slip.size() - 101];
  std::printf(
      "below the peak: slip %.5e m, first step %.5e m, then %.5f delta_peak against "
      "x* = %.5f; last second %.2e m\n",
      stays.slip.back(), first_step, mobilized, x_star, last_second);
  std::printf("above the peak: slip %.4e m = %.2f delta_peak\n", slides.slip.back(),
              slides.slip.back() / delta_peak);
  // Within 0.005: the corner contacts' normal stresses differ by +-10 %
  // (the friction's overturning moment), which moves the stop by ~0.002
  // (second order), and the last creeping step overshoots x* by less.
  EXPECT_NEAR(mobilized, x_star, 0.005);
  EXPECT_EQ(last_second, 0);
  EXPECT_GT(slides.slip.back(), 5 * delta_peak);
}

TEST(DdaBartonBandisIncline, SlidesAtTheResidualFrictionPastTheSoftening) {
  // 55 degrees (the peak friction 45.8): dynamic steps of 1 ms. From the
  // step at which the slip passes 100 delta_peak (7.3 cm; phi_mob = phi_r
  // beyond it) the block moves by v1 tau + A tau^2 / 2 with
  // A = g (sin a - cos a tan phi_r), tau the time since.
  const double slope = 55 * kDeg;
  const Path path = slide_on_incline(55, 1e-3, 1, 0.8);
  const double delta_peak = peak_displacement(kInclineJoint);
  std::size_t k1 = 0;
  while (k1 < path.slip.size() && path.slip[k1] < 100 * delta_peak) ++k1;
  ASSERT_LT(k1 + 100, path.slip.size()) << "the block did not get past the softening";
  const double acceleration =
      kG * (std::sin(slope) - std::cos(slope) * std::tan(kInclineJoint.residual_friction_angle));
  double worst = 0;
  for (std::size_t k = k1; k < path.slip.size(); ++k) {
    const double tau = path.t[k] - path.t[k1];
    const double moved = path.slip[k] - path.slip[k1] - path.velocity[k1] * tau;
    worst = std::max(worst, std::abs(moved - acceleration * tau * tau / 2));
  }
  const double tau = path.t.back() - path.t[k1];
  const double scale = acceleration * tau * tau / 2;
  std::printf("residual slide: %.4f s from slip %.4f m, error %.3e m of %.4f m (%.2e)\n", tau,
              path.slip[k1], worst, scale, worst / scale);
  // Newmark (beta = 1/2, gamma = 1) integrates a constant acceleration
  // exactly and the friction is constant: within 1e-6 of the distance, below
  // the penalty springs' own displacement m g / p = 2e-6 m (which shifts the
  // path, not its increments).
  EXPECT_LT(worst, 1e-6 * scale);
}

/// The largest shear force (N/m) a Barton-Bandis joint carries under a
/// block pushed by a force growing from 0 to `factor` x `peak` in `ramp`
/// seconds (static steps of dt), and the block's slip (m).
struct ShearTest {
  double largest = 0, slip = 0;
};

ShearTest direct_shear(const joints::BartonBandisProperties& joint, double width, double height,
                       double normal_load, double push, double ramp, double dt) {
  Scene s = base_scene(10e9, 30, 0);
  use_law(s, joint);
  s.blocks.push_back(block("base", rectangle(6, 0.5, 0, Vec2(0, -0.5)), true));
  s.blocks.push_back(block("block", rectangle(width, height, 0, Vec2(1, 0))));
  PointLoad normal;
  normal.block = 1;
  normal.point = Vec2(1 + width / 2, height / 2);
  normal.force = Vec2(0, -normal_load);
  PointLoad shear;  // at the middle of the block's base: no moment on the joint
  shear.block = 1;
  shear.point = Vec2(1 + width / 2, 0);
  shear.force = Vec2(push, 0);
  shear.history = {{0, 0}, {ramp, 1}};
  s.point_loads = {normal, shear};
  mechanics_controls(s).dda.max_time_step = dt;
  mechanics_controls(s).dda.velocity_carry_over = 0;
  s.time.end_time = ramp;

  RockMass state = RockMass::from_scene(s);
  dda::DdaProcess dda(s);
  dda.initialize(state);
  ShearTest result;
  double t = 0;
  while (t < ramp - 1e-12) {
    const double step = std::min(dda.proposed_dt(state), ramp - t);
    if (dda.advance(state, t, step).status != StepReport::Status::Ok) continue;
    t += step;
    double force = 0;
    for (const dda::DdaContact& c : dda.contacts()) force += c.shear_force;
    result.largest = std::max(result.largest, std::abs(force));
  }
  result.slip = state.blocks[1].section.centroid.x() - (1 + width / 2);
  return result;
}

TEST(DdaBartonBandisDirectShear, PeakShearForceIsBartonsPeakStrength) {
  // A 1 x 0.2 m block on a fixed 6 x 0.5 m base, no gravity; a normal load of
  // 1 MN/m at its centroid (sigma_n = 1 MPa on its 1 m base) and a
  // horizontal force growing from 0 to 1.5 times the peak strength, static
  // steps of 1 ms. JRC 10, JCS 100 MPa, phi_r 30 degrees: i = 20 degrees,
  // the peak friction angle 50 degrees, delta_peak 0.91 mm.
  const joints::BartonBandisProperties joint = barton_bandis(10, 100e6, 30);
  const double width = 1.0, height = 0.2, normal_load = 1e6, dt = 1e-3;
  const double sigma = normal_load / width, phi_peak = peak_friction(joint, sigma);
  const double peak = sigma * std::tan(phi_peak) * width;
  const double mass = kDensity * width * height, delta_peak = peak_displacement(joint);
  // The strength is the law's at the start of each step, so the largest
  // force is the curve sampled at the steps' mobilized displacements: it
  // misses the peak by at most the curve's slope there (0.25 i per 0.4
  // delta_peak, times N sec^2 phi) times one step's advance, which a force
  // at most one ramp increment dF above the strength gives in a static
  // step, dF dt^2 / (2 m).
  const double slope = normal_load / std::pow(std::cos(phi_peak), 2) *
                       (0.25 * (phi_peak - joint.residual_friction_angle) / 0.4);
  for (const double ramp : {1.0, 4.0}) {
    const double increment = 1.5 * peak * dt / ramp;
    const double bound = slope * increment * dt * dt / (2 * mass) / delta_peak;
    const ShearTest r = direct_shear(joint, width, height, normal_load, 1.5 * peak, ramp, dt);
    std::printf(
        "direct shear, ramp %.0f s: peak %.6e N/m against %.6e N/m (%.2e; bound %.2e), "
        "slip %.3e m\n",
        ramp, r.largest, peak, r.largest / peak - 1, bound / peak, r.slip);
    EXPECT_GT(r.slip, 5 * delta_peak);  // it went past the peak
    EXPECT_NEAR(r.largest, peak, bound) << "ramp " << ramp << " s";
  }
}

}  // namespace
}  // namespace fissure::testing
