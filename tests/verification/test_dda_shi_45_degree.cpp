// verification.md (c): Shi's frictionless block on a 45 degree plane.
// dt = 0.0080812 s, 100 steps: the block slides with g / sqrt(2) along the
// plane, so the vertical and horizontal distances are g t^2 / 4 = 1.599992 m.
// Sliding at constant acceleration is integrated exactly by Newmark
// (beta = 1/2, gamma = 1); what remains is the settling of the penalty spring
// (m g cos 45 / p_n ~ 1e-6 m), far inside the 5e-4 tolerance.
#include <gtest/gtest.h>

#include "mechanics/dda/dda_settings.h"
#include "tests/support/dda_scenes.h"
#include "tests/support/run_scene.h"

namespace fissure::testing {
namespace {

TEST(DdaShi45, FrictionlessPlane) {
  const double dt = 0.0080812, g = 9.8;
  Scene s = incline_scene(45, 0, dt, 5e9, 100 * dt);
  s.gravity = Vec2(0, -g);
  mechanics_controls(s).dda.max_displacement_ratio = 0.02;  // no step is cut
  const RunResult r = run_scene(s, "dda_shi_45");
  ASSERT_EQ(r.summary.status, "completed") << r.summary.message;
  EXPECT_EQ(r.summary.steps, 100);
  const double t = 100 * dt, exact = g * t * t / 4;  // 1.599992 m
  const auto& m = r.summary.monitors["block"];
  EXPECT_NEAR(-m["uy"].get<double>(), exact, 5e-4 * exact);
  EXPECT_NEAR(-m["ux"].get<double>(), exact, 5e-4 * exact);
}

}  // namespace
}  // namespace fissure::testing
