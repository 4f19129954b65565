// Heat crosses the joints of a rock mass that has settled before the
// coupled run (coupling.initial_equilibrium), as it crosses those of the
// same rock mass without mechanics. The blocks, cut by two joint sets, are
// confined by fixed blocks on every side under an in-situ stress, so every
// joint stays closed: the heat from a heater must then spread
// exactly as in the thermal-only run (the same meshes, made on the blocks
// as cut; the same joint conductance). Before the meshes were made on the
// blocks as cut, the settled blocks' faces, moved apart by round-off, did
// not pair up, no heat crossed any joint, and the heated blocks reached
// hundreds of degrees (the heated drift, docs/thermal.md section 10).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "coupling/process_registry.h"
#include "tests/support/run_scene.h"
#include "tests/support/thermal_runs.h"
#include "thermal/conduction/thermal_state.h"

namespace fissure::testing {
namespace {

std::string scene(bool with_mechanics) {
  std::string s =
      std::string("physics: ") + (with_mechanics ? "[mechanics, thermal]" : "[thermal]") + R"(
gravity: [0, -9.81]
materials:
  - {name: granite, density: 2650 kg/m^3, young_modulus: 50 GPa, poisson_ratio: 0.25}
joints:
  - {name: joint, friction_angle: 35}
rock_mass:
  domain: [[0, 0], [10, 0], [10, 10], [0, 10]]
  seed: 2
  joint_sets:
    - {name: a, dip: 70, spacing: 1.5 m, spacing_spread: 0.2 m}
    - {name: b, dip: 160, spacing: 1.5 m, spacing_spread: 0.2 m}
  fixed_blocks: {boundaries: [bottom, left, right, top]}
  initial_stress: [-3 MPa, -4 MPa, 0]
thermal:
  materials:
    - {name: granite, conductivity: 3 W/m/K, heat_capacity: 2.4 MJ/m^3/K, thermal_expansion: 8e-6 1/K}
  mesh: {element_size: 0.5 m}
  time_step: 5 d
  initial: {temperature: 15}
  joints: {conductance: 200 W/m^2/K}
  conditions:
    - {boundary: exterior, temperature: 15}
  sources:
    - {name: heater, point: [5.1, 4.9], power: 400 W/m}
time: {end: 60 d}
output: {interval: 30 d, hdf5: false}
)";
  if (with_mechanics)
    s += R"(mechanics:
  dda: {time_step: 5 ms, velocity_carry_over: 0}
coupling:
  order: [thermal, mechanics]
  intervals: {mechanics: 20 d}
  quasi_static: {processes: [mechanics], max_speed: 1e-4 m/s, max_steps: 30}
  initial_equilibrium: {processes: [mechanics], max_speed: 1e-5 m/s, max_time: 5 s}
)";
  return s;
}

TEST(ThermalSettledJoints, HeatCrossesTheJointsOfASettledRockMass) {
  const RunResult thm = run_scene(read_scene_text(scene(true), "settled.yaml"), "settled");
  ASSERT_EQ(thm.summary.status, "completed") << thm.summary.message;
  const RunResult th = run_scene(read_scene_text(scene(false), "alone.yaml"), "alone");
  ASSERT_EQ(th.summary.status, "completed") << th.summary.message;
  const thermal::ThermalState* a = &thermal_state(thm);
  const thermal::ThermalState* b = &thermal_state(th);
  ASSERT_EQ(a->temperature.size(), b->temperature.size()) << "the same meshes";
  double largest_rise = 0, largest_difference = 0;
  for (std::size_t i = 0; i < a->temperature.size(); ++i) {
    largest_rise = std::max(largest_rise, b->temperature[i] - 15);
    largest_difference =
        std::max(largest_difference, std::abs(a->temperature[i] - b->temperature[i]));
  }
  EXPECT_GT(largest_rise, 5) << "the heaters warm the rock";
  // The same linear systems while every joint is closed: round-off.
  EXPECT_LT(largest_difference, 1e-9 * largest_rise);
}

}  // namespace
}  // namespace fissure::testing
