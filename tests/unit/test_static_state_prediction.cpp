// Predicted start states of a static DDA step (mechanics/dda/dda_process.cpp,
// docs/dda.md section 2): with k01 = 0 the open-close iteration starts from
// the states an update at the first guess (the last step's increment) gives.
// A block that falls statically onto a base moves g dt^2 / 2 per step (each
// step starts at rest); in the step in which that motion closes the gap, the
// prediction closes the contacts before the first solve, so that step, like
// every other, takes one open-close iteration. Starting from the last
// step's states (open) the block would fall through in the first solve and
// need a second iteration.
#include <gtest/gtest.h>

#include "mechanics/dda/dda_process.h"
#include "mechanics/dda/dda_settings.h"
#include "tests/support/dda_scenes.h"

namespace fissure::dda {
namespace {

constexpr double kG = 9.81, kDt = 1e-3;

TEST(StaticStatePrediction, ABlockLandsInOneOpenCloseIteration) {
  const double fall_per_step = kG * kDt * kDt / 2;
  const double gap = 2.5 * fall_per_step;  // closes in the third step
  const Scene s = testing::block_above_base_scene(gap, kDt);
  RockMass state = RockMass::from_scene(s);
  DdaProcess dda(s);
  dda.initialize(state);

  const int steps = 6;
  double t = 0;
  for (int n = 0; n < steps; ++n) {
    ASSERT_EQ(dda.advance(state, t, kDt).status, StepReport::Status::Ok) << "step " << n;
    t += kDt;
  }
  const nlohmann::json stats = dda.statistics();
  // It landed: both bottom corners are in contact and closed.
  EXPECT_EQ(stats["contacts"]["open"].get<long>(), 0);
  EXPECT_GE(stats["contacts"]["locked"].get<long>(), 2);
  // One iteration per step, the landing step included.
  EXPECT_EQ(stats["open_close_iterations"].get<long>(), steps);
  // Before landing the block fell g dt^2 / 2 per step.
  const double y = state.blocks[1].section.centroid.y();
  EXPECT_LT(y, 0.25 + gap - 2 * fall_per_step);
}

}  // namespace
}  // namespace fissure::dda
