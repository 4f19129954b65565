// verification.md (a): free fall. Newmark beta = 1/2, gamma = 1 integrates a
// constant acceleration exactly, so the discrete result equals g t^2 / 2 and
// g t to round-off (tolerance 1e-10 relative).
#include <gtest/gtest.h>

#include "mechanics/dda/dda_settings.h"
#include "tests/support/dda_scenes.h"
#include "tests/support/run_scene.h"

namespace fissure::testing {
namespace {

Scene free_fall_scene(double k01) {
  Scene s = base_scene(10e9, 30, 9.8);
  s.blocks.push_back(block("block", rectangle(1, 1)));
  s.monitors.push_back({"c", Vec2(0.5, 0.5), 0});
  // Shi's numbers: dt = 0.009035 s, 50 steps. g2 large enough that no step is cut.
  mechanics_controls(s).dda.max_time_step = 0.009035;
  mechanics_controls(s).dda.max_displacement_ratio = 0.5;
  mechanics_controls(s).dda.velocity_carry_over = k01;
  s.time.end_time = 50 * 0.009035;
  return s;
}

TEST(DdaFreeFall, ShiFiftyStepsExact) {
  const RunResult r = run_scene(free_fall_scene(1.0), "dda_free_fall");
  ASSERT_EQ(r.summary.status, "completed") << r.summary.message;
  EXPECT_EQ(r.summary.steps, 50);
  const double t = 50 * 0.009035, g = 9.8;
  const Block& b = r.state.blocks[0];
  EXPECT_NEAR(b.section.centroid.y() - 0.5, -0.5 * g * t * t, 1e-10 * 0.5 * g * t * t);
  EXPECT_NEAR(b.section.centroid.x(), 0.5, 1e-12);
  EXPECT_NEAR(b.velocity(1), -g * t, 1e-10 * g * t);
  // No strain, no stress, no rotation.
  EXPECT_LT(b.stress.norm(), 1e-6);
  EXPECT_LT(std::abs(b.rotation), 1e-14);
  // Reported through the monitor as well (0.999983 m, Shi's 3-D DDA: 1.0000 m).
  EXPECT_NEAR(r.summary.monitors["c"]["uy"].get<double>(), -0.999983, 5e-7);
}

TEST(DdaFreeFall, VelocityCarryOverRecursion) {
  // With k01 the start velocity of a step is k01 v, so v_n = k01 v_{n-1} + g dt.
  const double k01 = 0.5, g = 9.8, dt = 0.009035;
  const RunResult r = run_scene(free_fall_scene(k01), "dda_free_fall_k01");
  ASSERT_EQ(r.summary.status, "completed") << r.summary.message;
  double v = 0, y = 0;
  for (int n = 0; n < 50; ++n) {
    y -= dt * k01 * v + 0.5 * g * dt * dt;
    v = k01 * v + g * dt;
  }
  const Block& b = r.state.blocks[0];
  EXPECT_NEAR(b.velocity(1), -v, 1e-10 * v);
  EXPECT_NEAR(b.section.centroid.y() - 0.5, y, 1e-10 * std::abs(y));
}

}  // namespace
}  // namespace fissure::testing
