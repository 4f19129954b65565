// A rigid block on an incline with the explicit DEM cycle (mechanics/dem/
// dem_system.h; the 3DEC verification set's first problem): a 1 m x 0.5 m
// block (2,500 kg/m^3) on a fixed plane inclined at 30 degrees, Coulomb
// joint k_n = k_s = 10 GPa/m, no damping, dt = 1e-4 s (a seventh of the
// critical step of the block on its contact springs).
//  * friction 20 degrees: it slides with g (sin a - cos a tan phi) = 1.813
//    m/s^2, 0.2266 m in 0.5 s. The contact springs first take the block's
//    weight and ring (about 450 Hz, undamped), so the friction force and the
//    acceleration oscillate about their means; the displacement's share of
//    that ringing is about mu g cos a / omega^2 = 4e-7 m, 2e-6 of the
//    distance: asserted within 1e-4 of the closed form;
//  * friction 35 degrees, with local damping: it stays, within the springs'
//    elastic slip (m g sin a / (k_s L) = 0.6 um);
//  * toppling (friction 45 degrees): a block whose base / height is below
//    tan a turns over its downhill corner, a squat one stays.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mechanics/dem/dem_system.h"

namespace fissure::dem {
namespace {

constexpr double kG = 9.81, kDensity = 2500;

Polygon turned(std::vector<Vec2> points, double angle) {
  const Eigen::Matrix2d r{{std::cos(angle), -std::sin(angle)}, {std::sin(angle), std::cos(angle)}};
  for (Vec2& p : points) p = r * p;
  return Polygon(points);
}

struct Outcome {
  double slide;     ///< m, the centroid's move down the slope
  double rotation;  ///< rad, the block's turn (counter-clockwise +)
};

/// A `width` x `height` block on the 30-degree incline for `seconds`.
Outcome on_incline(double friction_deg, double seconds, double local_damping = 0,
                   double width = 1.0, double height = 0.5) {
  const double a = 30 * std::numbers::pi / 180;
  std::vector<DemBlock> blocks(2);
  blocks[0].polygon = turned({{-5, -1}, {5, -1}, {5, 0}, {-5, 0}}, a);
  blocks[0].fixed = true;
  const double w = 0.5 * width;
  blocks[1].polygon = turned({{-w, 0}, {w, 0}, {w, height}, {-w, height}}, a);
  for (DemBlock& b : blocks) {
    const SectionProperties s = section_properties(b.polygon);
    b.centroid = s.centroid;
    b.body = rigid_body(s, kDensity);
  }
  joints::CoulombProperties joint;
  joint.normal_stiffness = joint.shear_stiffness = 10e9;
  joint.friction_angle = friction_deg * std::numbers::pi / 180;
  DemSettings settings;
  settings.rounding = 0.01;
  settings.margin = 0.01;
  settings.time_step = 1e-4;
  settings.gravity = Vec2(0, -kG);
  settings.damping.local = local_damping;
  const Vec2 start = blocks[1].centroid;
  DemSystem system(std::move(blocks), {joints::JointLaw(joint)}, settings);
  const int steps = static_cast<int>(std::lround(seconds / settings.time_step));
  for (int n = 0; n < steps; ++n) system.step();
  const Vec2 down_slope(-std::cos(a), -std::sin(a));
  const Polygon& p = system.blocks()[1].polygon;
  const Vec2 bottom = p.vertices[1] - p.vertices[0];
  return {(system.blocks()[1].centroid - start).dot(down_slope),
          std::atan2(bottom.y(), bottom.x()) - a};
}

double slide(double friction_deg, double seconds, double local_damping = 0) {
  return on_incline(friction_deg, seconds, local_damping).slide;
}

TEST(DemIncline, ABlockSlidesAsCoulombFrictionAllows) {
  const double a = 30 * std::numbers::pi / 180, phi = 20 * std::numbers::pi / 180, t = 0.5;
  const double exact = 0.5 * kG * (std::sin(a) - std::cos(a) * std::tan(phi)) * t * t;
  const double s = slide(20, t);
  std::printf("sliding: %.9f m against %.9f m (%.2e relative)\n", s, exact, s / exact - 1);
  EXPECT_NEAR(s, exact, 1e-4 * exact);
}

TEST(DemIncline, ABlockStaysWhenFrictionHoldsIt) {
  // Undamped, the block set down without contact stress rings on its
  // springs between no and twice its weight's normal force, and slips a
  // little at each swing (0.37 mm in 0.5 s); with local damping (0.8, as a
  // static analysis) it settles within the springs' elastic slip.
  const double undamped = slide(35, 0.5), damped = slide(35, 0.5, 0.8);
  std::printf("sticking: %.3e m undamped, %.3e m with local damping\n", undamped, damped);
  EXPECT_LT(std::abs(damped), 1e-5);
}

TEST(DemIncline, ASlenderBlockTopplesAndASquatOneDoesNot) {
  // Friction 45 degrees holds both against sliding; the block topples when
  // its base / height is below tan 30 = 0.577 (its weight's line leaves the
  // base's downhill corner): 0.2 / 1.0 turns about that corner (counter-clockwise
  // here: downhill is to the left) by more than 0.2 rad in 0.5 s; 0.8 / 1.0 stays upright within
  // its springs' rocking (under 1e-3 rad), damped.
  const Outcome slender = on_incline(45, 0.5, 0, 0.2, 1.0);
  const Outcome squat = on_incline(45, 0.5, 0.8, 0.8, 1.0);
  std::printf("toppling: %.4f rad (slender), %.2e rad (squat)\n", slender.rotation, squat.rotation);
  EXPECT_GT(slender.rotation, 0.2);
  EXPECT_LT(std::abs(squat.rotation), 1e-3);
  // Near the threshold (1 s): 0.55 / 1.0 goes over (undamped), 0.60 / 1.0
  // stands (damped: undamped, set down without contact stress, it rocks by
  // up to 1e-2 rad); the rounded corners move the pivot in by a few mm.
  const Outcome over = on_incline(45, 1.0, 0, 0.55, 1.0);
  const Outcome back = on_incline(45, 1.0, 0.8, 0.60, 1.0);
  std::printf("near tan a: %.4f rad (0.55), %.2e rad (0.60)\n", over.rotation, back.rotation);
  EXPECT_GT(over.rotation, 0.1);
  EXPECT_LT(std::abs(back.rotation), 1e-3);
}

}  // namespace
}  // namespace fissure::dem
