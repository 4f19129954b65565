// The explicit DEM's motion law for a rigid block
// (mechanics/dem/rigid_block_motion.h) against closed forms:
//  * free fall and a constant moment: central differences from the
//    half-step start are exact for a constant acceleration (the positions
//    are sums of an arithmetic series), to round-off; taking v^0 for the
//    velocity before the first step instead, the block falls g dt t / 2
//    further, which the test also shows;
//  * a mass on a spring: second order in dt (the phase error of central
//    differences is (omega dt)^2 / 24 per radian), stable up to the
//    critical step 2 sqrt(m / k) and unstable beyond it;
//  * Cundall's local damping: a load on a spring settles at P / k, where
//    the undamped motion swings between 0 and 2 P / k.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "mechanics/dem/rigid_block_motion.h"

namespace fissure::dem {
namespace {

constexpr double kDensity = 2000;  // kg/m^3

/// A 2 m x 1 m block.
RigidBody brick() {
  return rigid_body(section_properties(Polygon({{0, 0}, {2, 0}, {2, 1}, {0, 1}})), kDensity);
}

TEST(DemRigidMotion, MassAndInertiaOfARectangle) {
  const RigidBody b = brick();
  EXPECT_DOUBLE_EQ(b.mass, kDensity * 2);
  EXPECT_NEAR(b.inertia, kDensity * 2 * (4.0 + 1.0) / 12,
              1e-9 * b.inertia);  // rho a b (a^2 + b^2) / 12
}

TEST(DemRigidMotion, AMoveTurnsAboutTheCentroidExactly) {
  Polygon p({{0, 0}, {2, 0}, {2, 1}, {0, 1}});
  Vec2 centroid = section_properties(p).centroid;
  // A thousand turns of pi/1000 and a shift: half a turn, the block's area
  // and its centroid's place kept (a linearized rotation would have grown it
  // by (1 + (pi/1000)^2)^1000, 1 %).
  const double pi = std::numbers::pi;
  for (int k = 0; k < 1000; ++k) move_rigidly(p, centroid, Motion(1e-3, 0, pi / 1000));
  const SectionProperties after = section_properties(p);
  EXPECT_NEAR(after.area, 2.0, 1e-12);
  EXPECT_NEAR((after.centroid - centroid).norm(), 0, 1e-12);
  EXPECT_NEAR((centroid - Vec2(2.0, 0.5)).norm(), 0, 1e-12);
  EXPECT_NEAR((p.vertices[0] - Vec2(3, 1)).norm(), 0, 1e-12);  // (0, 0) turned by pi, shifted
}

TEST(DemRigidMotion, FreeFallAndASteadyMomentAreExactFromTheHalfStepStart) {
  const RigidBody b = brick();
  const Vec2 g(0, -9.81);
  const BlockLoad moment{Vec2::Zero(), 50.0};
  const double dt = 1e-3;
  const int n = 1000;
  const double t = n * dt;
  for (bool half_start : {true, false}) {
    Motion v(1.5, 0, 0);
    if (half_start) v = velocity_before_first_step(v, b, moment, g, dt);
    Motion x = Motion::Zero();
    for (int k = 0; k < n; ++k) x += advance(v, b, moment, g, dt, {});
    const double y_exact = 0.5 * g.y() * t * t,
                 theta_exact = 0.5 * moment.moment / b.inertia * t * t;
    if (half_start) {
      EXPECT_NEAR(x.x(), 1.5 * t, 1e-12);
      EXPECT_NEAR(x.y(), y_exact, 1e-12 * std::abs(y_exact));
      EXPECT_NEAR(x.z(), theta_exact, 1e-12 * theta_exact);
    } else {  // an O(dt) offset: half a step's velocity change over the whole time
      EXPECT_NEAR(x.y() - y_exact, 0.5 * g.y() * dt * t, 1e-9);
    }
  }
}

/// A block on a horizontal spring k from x0 at rest, n steps of dt; returns
/// the positions.
std::vector<double> oscillate(double k, double x0, double dt, int n, double load = 0,
                              DampingControls damping = {}) {
  const RigidBody b = brick();
  auto spring = [&](double x) { return BlockLoad{Vec2(load - k * x, 0), 0}; };
  double x = x0;
  Motion v = velocity_before_first_step(Motion::Zero(), b, spring(x), Vec2::Zero(), dt);
  std::vector<double> path;
  for (int i = 0; i < n; ++i) {
    x += advance(v, b, spring(x), Vec2::Zero(), dt, damping).x();
    path.push_back(x);
  }
  return path;
}

TEST(DemRigidMotion, ASpringOscillatesToSecondOrderUpToTheCriticalStep) {
  const RigidBody b = brick();
  const double k = 1e9, x0 = 1e-3;
  const double omega = std::sqrt(k / b.mass), period = 2 * std::numbers::pi / omega;
  // Largest error over 10 periods for 50, 100, 200 steps a period: the
  // phase error, order 2.
  std::vector<double> errors;
  for (int per_period : {50, 100, 200}) {
    const double dt = period / per_period;
    const std::vector<double> x = oscillate(k, x0, dt, 10 * per_period);
    double worst = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
      worst = std::max(worst, std::abs(x[i] - x0 * std::cos(omega * dt * (i + 1))));
    errors.push_back(worst);
  }
  for (std::size_t i = 0; i + 1 < errors.size(); ++i) {
    const double order = std::log2(errors[i] / errors[i + 1]);
    std::printf("spring: largest error %.3e -> %.3e m, order %.4f\n", errors[i], errors[i + 1],
                order);
    EXPECT_GT(order, 1.9) << errors[i] << " -> " << errors[i + 1];
    EXPECT_LT(order, 2.1) << errors[i] << " -> " << errors[i + 1];
  }
  // Stable just below the critical step (from rest the discrete solution is
  // x0 cos(n theta), cos theta = 1 - (omega dt)^2 / 2: amplitude x0),
  // unstable just above.
  const double critical = critical_time_step(b.mass, k);
  EXPECT_NEAR(critical, 2 / omega, 1e-12 * critical);
  double largest = 0;
  for (double x : oscillate(k, x0, 0.99 * critical, 2000)) largest = std::max(largest, std::abs(x));
  EXPECT_LT(largest, (1 + 1e-9) * x0);
  largest = 0;
  for (double x : oscillate(k, x0, 1.01 * critical, 2000)) largest = std::max(largest, std::abs(x));
  EXPECT_GT(largest, 1e3 * x0);
}

TEST(DemRigidMotion, LocalDampingSettlesALoadOnASpring) {
  const RigidBody b = brick();
  const double k = 1e9, load = 1e6;  // static displacement 1 mm
  const double dt = 0.1 * critical_time_step(b.mass, k);
  const std::vector<double> undamped = oscillate(k, 0, dt, 400, load);
  EXPECT_GT(*std::max_element(undamped.begin(), undamped.end()), 1.9 * load / k);
  const std::vector<double> damped = oscillate(k, 0, dt, 400, load, {0.8, 0});
  EXPECT_NEAR(damped.back(), load / k, 1e-8 * load / k);
}

}  // namespace
}  // namespace fissure::dem
