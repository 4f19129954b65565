// A DEM contact's kinematics and loads (mechanics/dem/contact_kinematics.h):
//  * a block moving away along the normal opens the contact by v dt, one
//    sliding along t shears it by v dt; a rotation about block i's centroid
//    moves C by omega x r;
//  * the two loads are equal and opposite, and for a rigid-body rotation of
//    both blocks together (no relative motion) there is no increment;
//  * the moments: a normal force at a point offset along t from the
//    centroid turns the block by F times the offset.
#include <gtest/gtest.h>

#include "mechanics/dem/contact_kinematics.h"

namespace fissure::dem {
namespace {

const Vec2 kPoint(1, 0), kNormal(0, -1);  // C on i's underside, j below
const Vec2 kCi(1, 0.5), kCj(3, -0.5);

TEST(DemContactKinematics, OpeningShearAndRotationIncrements) {
  const double dt = 1e-3;
  // j falls away from i at 2 m/s: opening 2 dt.
  DisplacementIncrement d =
      relative_displacement(kPoint, kNormal, Motion::Zero(), kCi, Motion(0, -2, 0), kCj, dt);
  EXPECT_NEAR(d.normal, 2 * dt, 1e-15);
  EXPECT_NEAR(d.shear, 0, 1e-15);
  // t = n turned by +90 deg = (1, 0): j moving in +x shears by +v dt.
  d = relative_displacement(kPoint, kNormal, Motion::Zero(), kCi, Motion(3, 0, 0), kCj, dt);
  EXPECT_NEAR(d.shear, 3 * dt, 1e-15);
  // i turning by omega about its centroid moves C (0.5 below it) by
  // omega x (0, -0.5) = (0.5 omega, 0): j shears by -0.5 omega dt against it.
  d = relative_displacement(kPoint, kNormal, Motion(0, 0, 4), kCi, Motion::Zero(), kCj, dt);
  EXPECT_NEAR(d.shear, -0.5 * 4 * dt, 1e-15);
  EXPECT_NEAR(d.normal, 0, 1e-15);
  // Both blocks turning together as one rigid body: no relative
  // motion at C (v_j = v_i + omega x (x_j - x_i)).
  const double w = 0.7;
  const Vec2 vi(0.2, -0.1);
  const Vec2 r = kCj - kCi;
  const Motion mi(vi.x(), vi.y(), w), mj(vi.x() - w * r.y(), vi.y() + w * r.x(), w);
  d = relative_displacement(kPoint, kNormal, mi, kCi, mj, kCj, dt);
  EXPECT_NEAR(d.normal, 0, 1e-15);
  EXPECT_NEAR(d.shear, 0, 1e-15);
}

TEST(DemContactKinematics, LoadsAreEqualAndOppositeWithTheirMoments) {
  const double sigma = 2e6, tau = 5e5, length = 0.5;
  const BlockLoad i = load_on_i(kPoint, kNormal, sigma, tau, length, kCi);
  const BlockLoad j = load_on_j(kPoint, kNormal, sigma, tau, length, kCj);
  // Compression pushes i up (away from j), tau t = +x on i.
  EXPECT_NEAR((i.force - Vec2(tau * length, sigma * length)).norm(), 0, 1e-9);
  EXPECT_NEAR((i.force + j.force).norm(), 0, 1e-9);
  // Moments about each centroid: r x F.
  EXPECT_NEAR(i.moment, (kPoint - kCi).x() * i.force.y() - (kPoint - kCi).y() * i.force.x(), 1e-9);
  EXPECT_NEAR(i.moment, 0.5 * tau * length, 1e-9);  // r = (0, -0.5), F_x = tau L
  EXPECT_NEAR(j.moment, (kPoint - kCj).x() * j.force.y() - (kPoint - kCj).y() * j.force.x(), 1e-9);
}

}  // namespace
}  // namespace fissure::dem
