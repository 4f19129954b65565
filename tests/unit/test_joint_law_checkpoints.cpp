// Each joint law's per-contact state goes through a checkpoint to the bit
// (checkpoint_fields, core/io/checkpoint.h): a path interrupted by a save and
// a restore ends where the uninterrupted one does, every field equal.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <vector>

#include "core/io/memory_checkpoint.h"
#include "rockmass/joints/barton_bandis.h"
#include "rockmass/joints/continuously_yielding.h"
#include "rockmass/joints/coulomb_slip.h"

namespace fissure::joints {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

/// A cyclic path: closing, then shear back and forth with some opening.
std::vector<JointIncrement> path() {
  std::vector<JointIncrement> steps;
  for (int k = 0; k < 20; ++k) steps.push_back({-2e-6, 0, 0.5});
  for (int k = 0; k < 200; ++k)
    steps.push_back({1e-8 * std::sin(0.1 * k), 2e-5 * std::cos(0.05 * k), 0.5});
  return steps;
}

/// The fields a checkpoint holds, in its order (the archive's interface).
struct FieldValues {
  std::vector<double> values;
  template <class T>
  void operator()(const char*, T& value) {
    values.push_back(static_cast<double>(value));
  }
};
template <class State>
std::vector<double> fields(State s) {
  FieldValues f;
  checkpoint_fields(f, s);
  return f.values;
}

template <class Law>
void expect_restarts_to_the_bit(const Law& law) {
  using State = typename Law::State;
  const std::vector<JointIncrement> steps = path();
  State straight = law.initial_state(), next;
  std::vector<State> list;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    law.update(straight, steps[k], next);
    straight = next;
    if (k == 120) list.push_back(straight);  // saved here
  }
  MemoryCheckpoint saved;
  CheckpointWriter writer = saved.writer();
  writer.list("contacts", list, [](auto& e, auto& s) { checkpoint_fields(e, s); });
  std::vector<State> restored;
  CheckpointReader reader = saved.reader();
  reader.list("contacts", restored, [](auto& e, auto& s) { checkpoint_fields(e, s); });
  ASSERT_EQ(restored.size(), 1u);
  State resumed = restored[0];
  for (std::size_t k = 121; k < steps.size(); ++k) {
    law.update(resumed, steps[k], next);
    resumed = next;
  }
  // Every field, bit for bit.
  const std::vector<double> a = fields(straight), b = fields(resumed);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0);
  EXPECT_NE(a, fields(law.initial_state()));  // the path went somewhere
}

TEST(joint_law_checkpoints, CoulombSlipRestartsToTheBit) {
  CoulombProperties p;
  p.normal_stiffness = 10e9;
  p.shear_stiffness = 5e9;
  p.friction_angle = 30 * kDeg;
  p.cohesion = 0.1e6;
  p.dilation_angle = 5 * kDeg;
  p.zero_dilation_displacement = 1e-3;
  expect_restarts_to_the_bit(CoulombSlip(p));
}

TEST(joint_law_checkpoints, BartonBandisRestartsToTheBit) {
  BartonBandisProperties p;
  p.jrc = 10;
  p.jcs = 100e6;
  p.lab_length = 0.1;
  p.residual_friction_angle = 28 * kDeg;
  p.initial_aperture = 0.5e-3;
  expect_restarts_to_the_bit(BartonBandis(p));  // field length from the steps
}

TEST(joint_law_checkpoints, ContinuouslyYieldingRestartsToTheBit) {
  ContinuouslyYieldingProperties p;
  p.normal_stiffness = 20e9;
  p.normal_stiffness_exponent = 0.5;
  p.shear_stiffness = 10e9;
  p.friction_angle = 30 * kDeg;
  p.initial_friction_angle = 40 * kDeg;
  p.roughness_length = 1e-3;
  expect_restarts_to_the_bit(ContinuouslyYielding(p));
}

}  // namespace
}  // namespace fissure::joints
