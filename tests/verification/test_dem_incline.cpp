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
//    elastic slip (m g sin a / (k_s L) = 0.6 um).
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

/// Distance the block's centroid moved along the slope in `seconds`.
double slide(double friction_deg, double seconds, double local_damping = 0) {
  const double a = 30 * std::numbers::pi / 180;
  std::vector<DemBlock> blocks(2);
  blocks[0].polygon = turned({{-5, -1}, {5, -1}, {5, 0}, {-5, 0}}, a);
  blocks[0].fixed = true;
  blocks[1].polygon = turned({{-0.5, 0}, {0.5, 0}, {0.5, 0.5}, {-0.5, 0.5}}, a);
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
  DemSystem system(std::move(blocks), joint, settings);
  const int steps = static_cast<int>(std::lround(seconds / settings.time_step));
  for (int n = 0; n < steps; ++n) system.step();
  const Vec2 down_slope(-std::cos(a), -std::sin(a));
  return (system.blocks()[1].centroid - start).dot(down_slope);
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

}  // namespace
}  // namespace fissure::dem
