// The rule of the adaptive thermal step (thermal/conduction/
// temperature_step_control.h, docs/thermal.md 3.1): off accepts every step;
// a rejected step is retried scaled to 0.9 of the limit (always shorter);
// the next step grows by at most 2x and never beyond thermal.time_step, and
// shrinks before a step would be rejected. Exact values (the rule is a few
// multiplications; 1e-15 relative for round-off).
#include <gtest/gtest.h>

#include "thermal/conduction/temperature_step_control.h"

namespace fissure::thermal {
namespace {

TEST(temperature_step_control, OffAcceptsEveryStep) {
  const TemperatureStepControl off{0, 100};
  EXPECT_FALSE(off.enabled());
  EXPECT_TRUE(off.accepts(1e9));
}

TEST(temperature_step_control, RejectsAboveTheLimitAndScalesTheRetry) {
  const TemperatureStepControl c{2, 100};
  EXPECT_TRUE(c.accepts(2));
  EXPECT_FALSE(c.accepts(2 * (1 + 1e-15)));
  EXPECT_NEAR(c.retry_step(10, 4), 10 * 0.9 * 2 / 4, 1e-15 * 10);
  EXPECT_LT(c.retry_step(10, 2 * (1 + 1e-15)), 10);
}

TEST(temperature_step_control, GrowsAtMostTwiceAndUpToTheTimeStep) {
  const TemperatureStepControl c{2, 100};
  EXPECT_EQ(c.next_step(10, 0), 20);                                  // no change at all: the cap
  EXPECT_EQ(c.next_step(10, 0.1), 20);                                // far below: the cap
  EXPECT_EQ(c.next_step(80, 0.1), 100);                               // never beyond time_step
  EXPECT_NEAR(c.next_step(10, 1.2), 10 * 0.9 * 2 / 1.2, 1e-15 * 10);  // 1.5x
  EXPECT_LT(c.next_step(10, 1.95), 10);                               // near the limit: shrinks
}

}  // namespace
}  // namespace fissure::thermal
