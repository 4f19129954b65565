// Static-friction stability (foundation issue, "Stability stress test"; issue
// 22, "Static friction at every time step"), reduced sweep; the full 50-case
// sweep is benchmarks/dda_stability.
//  * A block on a 22.6 deg slope with friction 30 deg moves less than 1e-4 m
//    in 2 s and ends with both its contacts closed, for every dt in
//    {1e-4, 1e-3, 1e-2} s and penalty in {1, 10, 100, 1000} x E and
//    automatic (15 cheap cases), and at the small steps with the softest and
//    the stiffest penalty: dt = 1e-5 s over 2 s, dt = 1e-6 s over 0.2 s
//    (200,000 steps). Without the vibration damping of docs/dda.md section 4
//    the block's elastic vibration rang on at these steps and it walked down
//    the slope: 1.4-31 mm in 2 s, contacts open at the end in 8 of 10 cases.
//  * A 10 x 10 staggered brick wall (bricks 1.0 x 0.5 m, friction 30 deg,
//    fixed base, gravity from t = 0) stands: its top brick moves less than
//    1 mm in 1 s. Here dt = 1e-2 and 1e-3 s with 5 E and the automatic
//    penalty over 1 s, dt = 1e-4 s over 0.2 s, the stiffest case (500 E,
//    dt = 1e-2 s) over its first 0.02 s, where the impact transient makes the
//    open-close iteration hardest (the full 1 s takes ~40 s and runs in the
//    benchmark), and the small steps over their first 300 and 500 steps
//    (1000 E at dt = 1e-5 s, 1 E at 1e-6 s). What the top brick does move is the wall's elastic
//    settlement (rho g H^2 / 2E ~ 3e-5 m).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>

#include "mechanics/dda/dda_settings.h"
#include "tests/support/dda_scenes.h"
#include "tests/support/run_scene.h"

namespace fissure::testing {
namespace {

std::string name(double dt, double factor) {
  const std::string p = factor == 0 ? "auto" : std::to_string(static_cast<int>(factor)) + "E";
  return "dt" + std::to_string(static_cast<int>(std::round(-std::log10(dt)))) + "_" + p;
}

double displacement(const RunResult& r, const char* monitor) {
  const auto& m = r.summary.monitors[monitor];
  return std::hypot(m["ux"].get<double>(), m["uy"].get<double>());
}

class SlopeStability : public ::testing::TestWithParam<std::tuple<double, double>> {};

class SmallStepSlopeStability
    : public ::testing::TestWithParam<std::tuple<double, double, double>> {};

void expect_block_stays(double dt, double factor, double duration) {
  Scene s = incline_scene(22.6, 30, dt, factor * 10e9, duration);
  if (factor == 0) mechanics_controls(s).dda.penalty.reset();
  const RunResult r = run_scene(s, "stability_slope_" + name(dt, factor));
  ASSERT_EQ(r.summary.status, "completed") << r.summary.message;
  EXPECT_LT(displacement(r, "block"), 1e-4);
  // Both base corners still carry the block.
  EXPECT_EQ(r.summary.processes["mechanics"]["contacts"]["open"].get<long>(), 0);
}

TEST_P(SlopeStability, StickingBlockStays) {
  const auto [dt, factor] = GetParam();
  expect_block_stays(dt, factor, 2.0);
}

INSTANTIATE_TEST_SUITE_P(Sweep, SlopeStability,
                         ::testing::Combine(::testing::Values(1e-4, 1e-3, 1e-2),
                                            ::testing::Values(1.0, 10.0, 100.0, 1000.0, 0.0)));

TEST_P(SmallStepSlopeStability, StickingBlockStays) {
  const auto [dt, factor, duration] = GetParam();
  expect_block_stays(dt, factor, duration);
}

INSTANTIATE_TEST_SUITE_P(Reduced, SmallStepSlopeStability,
                         ::testing::Values(std::make_tuple(1e-5, 1.0, 2.0),
                                           std::make_tuple(1e-5, 1000.0, 2.0),
                                           std::make_tuple(1e-6, 1.0, 0.2),
                                           std::make_tuple(1e-6, 1000.0, 0.2)));

class WallStability : public ::testing::TestWithParam<std::tuple<double, double, double>> {};

TEST_P(WallStability, BrickWallStands) {
  const auto [dt, factor, duration] = GetParam();
  Scene s = brick_wall_scene(10, 10, 1.0, 0.5, 30, dt, factor * 10e9, duration);
  if (factor == 0) mechanics_controls(s).dda.penalty.reset();
  const RunResult r = run_scene(s, "stability_wall_" + name(dt, factor));
  ASSERT_EQ(r.summary.status, "completed") << r.summary.message;
  EXPECT_LT(displacement(r, "top"), 1e-3);
  // Every brick stays where it was built (the settlement is elastic).
  for (std::size_t b = 1; b < r.state.blocks.size(); ++b) {
    const Vec2 moved =
        r.state.blocks[b].section.centroid - section_properties(s.blocks[b].polygon).centroid;
    EXPECT_LT(moved.norm(), 1e-3) << s.blocks[b].name;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Reduced, WallStability,
    ::testing::Values(std::make_tuple(1e-2, 5.0, 1.0), std::make_tuple(1e-2, 0.0, 1.0),
                      std::make_tuple(1e-3, 5.0, 1.0), std::make_tuple(1e-3, 0.0, 1.0),
                      std::make_tuple(1e-4, 5.0, 0.2), std::make_tuple(1e-2, 500.0, 0.02),
                      std::make_tuple(1e-5, 1000.0, 0.003), std::make_tuple(1e-6, 1.0, 0.0005)));

TEST(WallSettling, LongWallSettlesStaticallyWithoutStepCuts) {
  // A 10 x 40 wall (405 bricks) settling from rest in static mode (k01 = 0)
  // at dt = 1 ms: contacts that chatter between two states are held
  // (open_close.h) instead of rejecting the step. Without the hold the
  // first 30 steps needed 2 cuts to 0.3 dt (and a 1,000-brick wall never got
  // back to 1 ms: docs/performance.md#dda_scaling).
  constexpr int kSteps = 30;
  Scene s = brick_wall_scene(10, 40, 1.0, 0.5, 30, 1e-3, 0, 1.0);
  mechanics_controls(s).dda.penalty.reset();
  mechanics_controls(s).dda.velocity_carry_over = 0;
  s.time.max_steps = kSteps;
  const RunResult r = run_scene(s, "stability_long_wall_static");
  const auto& m = r.summary.processes["mechanics"];
  EXPECT_EQ(m["steps"].get<long>(), kSteps);
  EXPECT_EQ(m["time_step_cuts"]["open_close"].get<long>(), 0);
  EXPECT_NEAR(r.summary.simulated_time, kSteps * 1e-3, 1e-12);
  EXPECT_GT(m["held_contacts"].get<long>(), 0);  // the hold did the work
  EXPECT_LT(displacement(r, "top"), 1e-3);
}

}  // namespace
}  // namespace fissure::testing
