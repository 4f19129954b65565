// rock_mass.initial_stress (docs/scene-reference.md section 5): every
// generated block starts with the in-situ stress, and a bad value names its
// line.
#include <gtest/gtest.h>

#include <string>

#include "core/base/errors.h"
#include "core/state/rock_mass.h"
#include "coupling/process_registry.h"

namespace fissure {
namespace {

std::string scene(const std::string& stress) {
  return R"(physics: [mechanics]
materials:
  - {name: granite, density: 2650 kg/m^3, young_modulus: 50 GPa, poisson_ratio: 0.25}
joints:
  - {name: joint, friction_angle: 30}
rock_mass:
  domain: [[0, 0], [4, 0], [4, 4], [0, 4]]
  joint_sets:
    - {name: a, dip: 30, spacing: 1 m}
    - {name: b, dip: 120, spacing: 1.5 m}
  fixed_blocks: {boundaries: [bottom]}
  initial_stress: )" +
         stress + R"(
mechanics:
  dda: {time_step: 1 ms}
time: {end: 0.01}
)";
}

TEST(rock_mass_initial_stress, EveryGeneratedBlockStartsWithIt) {
  const Scene s = read_scene_text(scene("[-10 MPa, -13 MPa, 2 MPa]"), "stress.yaml");
  const RockMass state = RockMass::from_scene(s);
  ASSERT_GT(state.blocks.size(), 10u);
  for (const Block& b : state.blocks) {
    EXPECT_EQ(b.stress, Eigen::Vector3d(-10e6, -13e6, 2e6)) << b.name;
  }
}

TEST(rock_mass_initial_stress, ABadValueNamesItsLine) {
  try {
    read_scene_text(scene("[-10 MPa, -13 MPa]"), "stress.yaml");
    ADD_FAILURE() << "accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(
        std::string(e.what()).find("stress.yaml:12:19: rock_mass.initial_stress: found a list "
                                   "of 2 values; expected a list of 3"),
        std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace fissure
