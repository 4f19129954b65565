// Frozen contact states (DdaProcess::freeze_discrete_states, the iterated
// coupling's iteration.freeze_states_after; docs/dda.md section 2): while
// frozen, every step holds each contact in the state the last accepted step
// ended with, whatever the contact law asks, and takes one open-close
// iteration; thawed, the next step judges the contacts afresh.
// A block falls statically onto a base (g dt^2 / 2 per step, each step from
// rest) with its contacts frozen open before it lands: it passes through the
// base's surface, as an open contact exerts no force. Thawed, its contacts
// close in the next step and push it back out.
#include <gtest/gtest.h>

#include "mechanics/dda/dda_process.h"
#include "mechanics/dda/dda_settings.h"
#include "tests/support/dda_scenes.h"

namespace fissure::dda {
namespace {

constexpr double kG = 9.81, kDt = 1e-3;

long count_state(const DdaProcess& dda, ContactState state) {
  long n = 0;
  for (const DdaContact& c : dda.contacts()) n += c.state == state;
  return n;
}

TEST(FrozenContactStates, AFrozenOpenContactLetsTheBlockThroughUntilThawed) {
  const double fall_per_step = kG * kDt * kDt / 2;
  const double gap = 2.5 * fall_per_step;  // closes in the third step
  const Scene s = testing::block_above_base_scene(gap, kDt);
  RockMass state = RockMass::from_scene(s);
  DdaProcess dda(s);
  dda.initialize(state);

  double t = 0;
  auto step = [&] {
    ASSERT_EQ(dda.advance(state, t, kDt).status, StepReport::Status::Ok) << "t = " << t;
    t += kDt;
  };
  step();  // in the air: every contact open
  ASSERT_GE(dda.contacts().size(), 2u);
  ASSERT_EQ(count_state(dda, ContactState::Open), static_cast<long>(dda.contacts().size()));

  dda.freeze_discrete_states(true);
  const long iterations_before = dda.statistics()["open_close_iterations"].get<long>();
  for (int n = 0; n < 4; ++n) step();
  // Held open: the block's underside (at y = centroid - 0.25) went below the
  // base's surface y = 0, and each frozen step took one iteration.
  EXPECT_EQ(count_state(dda, ContactState::Open), static_cast<long>(dda.contacts().size()));
  const double underside = state.blocks[1].section.centroid.y() - 0.25;
  EXPECT_LT(underside, -fall_per_step);
  EXPECT_EQ(dda.statistics()["open_close_iterations"].get<long>() - iterations_before, 4);

  dda.freeze_discrete_states(false);
  step();
  // Judged afresh: the penetrating corners close and are pushed back.
  EXPECT_GE(count_state(dda, ContactState::Locked) + count_state(dda, ContactState::Sliding), 2);
  EXPECT_GT(state.blocks[1].section.centroid.y() - 0.25, underside);
}

}  // namespace
}  // namespace fissure::dda
