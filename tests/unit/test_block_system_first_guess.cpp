// First guess of the DDA block system (mechanics/dda/block_system.cpp): before
// a step's first solve, the increment holds the motion the step is expected
// to make, which the iterative back ends start from. Dynamic analysis: free
// motion with the carried velocity, dt k01 v. Static analysis (k01 = 0):
// the last step's increment scaled to this dt, dt v / 2, since the block
// keeps v = 2 d / dt of its last step.
#include <gtest/gtest.h>

#include "mechanics/dda/block_kinematics.h"
#include "mechanics/dda/block_system.h"
#include "mechanics/dda/dda_parameters.h"
#include "mechanics/dda/dda_settings.h"
#include "mechanics/dda/step_update.h"
#include "tests/support/dda_scenes.h"

namespace fissure::dda {
namespace {

constexpr double kG = 9.81;

/// One free 1 x 0.5 m block in the air (no contacts) under gravity.
struct FreeBlock {
  Scene scene;
  RockMass state;
  DdaParameters parameters;
  BlockLoads loads;

  explicit FreeBlock(double k01) : scene(testing::base_scene(10e9, 30, kG)) {
    scene.blocks.push_back(testing::block("block", testing::rectangle(1, 0.5)));
    mechanics_controls(scene).dda.velocity_carry_over = k01;
    state = RockMass::from_scene(scene);
    parameters = DdaParameters::from_scene(scene);
  }
};

TEST(BlockSystemFirstGuess, DynamicStepStartsFromFreeMotion) {
  FreeBlock b(0.8);
  b.state.blocks[0].velocity << 0.3, -1.2, 0.05, 1e-6, -2e-6, 3e-6;
  BlockSystem system(b.parameters, b.state);
  const double dt = 2e-3;
  system.begin_step(b.state, b.loads, {}, {}, dt, dt);
  const Vector6 expected = dt * 0.8 * b.state.blocks[0].velocity;
  EXPECT_LT((system.increment(0) - expected).norm(), 1e-15 * expected.norm());
}

TEST(BlockSystemFirstGuess, StaticStepRepeatsTheLastIncrementScaledToThisStep) {
  FreeBlock b(0);
  BlockSystem system(b.parameters, b.state);
  // From rest there is nothing to repeat: the guess is zero.
  const double dt = 1e-3;
  system.begin_step(b.state, b.loads, {}, {}, dt, dt);
  EXPECT_EQ(system.increment(0).norm(), 0.0);

  // A static step of free fall moves the block by g dt^2 / 2 (inertia 2 M /
  // dt^2 against the weight M g), whatever it did before.
  system.assemble_and_solve({}, {b.parameters.normal_penalty, b.parameters.shear_penalty});
  const Vector6 d = system.increment(0);
  EXPECT_NEAR(d(1), -kG * dt * dt / 2, 1e-9 * kG * dt * dt);
  update_block(b.state.blocks[0], d, dt, 0,
               elastic_matrix(b.state.materials[0], b.parameters.plane), true);

  // The next step, half as long, starts from the last increment scaled by
  // dt2 / dt ...
  const double dt2 = dt / 2;
  system.begin_step(b.state, b.loads, {}, {}, dt + dt2, dt2);
  const Vector6 guess = system.increment(0);
  EXPECT_LT((guess - d * (dt2 / dt)).norm(), 1e-12 * d.norm());
  // ... and its solution, g dt2^2 / 2, is what the guess scaled linearly
  // towards (free fall in a static step goes with dt^2, a creep with dt).
  system.assemble_and_solve({}, {b.parameters.normal_penalty, b.parameters.shear_penalty});
  EXPECT_NEAR(system.increment(0)(1), -kG * dt2 * dt2 / 2, 1e-9 * kG * dt2 * dt2);
}

}  // namespace
}  // namespace fissure::dda
