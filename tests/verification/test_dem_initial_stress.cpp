// A rock mass in equilibrium under its initial stress stays at rest in the
// explicit DEM (docs/dem.md section 3, "initial stress"): the contacts
// bonded at the start carry n . sigma . n and t . sigma . n of their
// blocks' initial stress. Four 1 m blocks inside a fixed frame, all under
// sxx = -1 MPa, syy = -2 MPa, sxy = -0.5 MPa, no gravity, no damping:
// nothing moves, and each block's average (Love-Weber) stress is the
// initial stress (its vertical joints carry 1 MPa and 0.5 MPa of shear, its
// horizontal ones 2 MPa and 0.5 MPa). Without the prestress the blocks
// would also stay (no load at all) but carry no stress; with a wrong
// closure for the law the blocks would ring (no damping).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "coupling/process_registry.h"
#include "tests/support/run_scene.h"

namespace fissure::testing {
namespace {

std::string confined_scene(const std::string& joint) {
  std::string s = R"(physics: [dem]
gravity: [0, 0]
materials:
  - {name: rock, density: 2500, young_modulus: 50 GPa, poisson_ratio: 0.25}
joints:
  - {name: joint, friction_angle: 30, )" +
                  joint + R"(}
blocks:
  - {name: left, vertices: [[-1, -1], [0, -1], [0, 3], [-1, 3]], fixed: true, initial_stress: [-1 MPa, -2 MPa, -0.5 MPa]}
  - {name: right, vertices: [[2, -1], [3, -1], [3, 3], [2, 3]], fixed: true, initial_stress: [-1 MPa, -2 MPa, -0.5 MPa]}
  - {name: bottom, vertices: [[0, -1], [2, -1], [2, 0], [0, 0]], fixed: true, initial_stress: [-1 MPa, -2 MPa, -0.5 MPa]}
  - {name: top, vertices: [[0, 2], [2, 2], [2, 3], [0, 3]], fixed: true, initial_stress: [-1 MPa, -2 MPa, -0.5 MPa]}
)";
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const std::string x0 = std::to_string(i), x1 = std::to_string(i + 1);
      const std::string y0 = std::to_string(j), y1 = std::to_string(j + 1);
      s += "  - {name: b" + x0 + y0 + ", vertices: [[" + x0 + ", " + y0 + "], [" + x1 + ", " + y0 +
           "], [" + x1 + ", " + y1 + "], [" + x0 + ", " + y1 +
           "]], initial_stress: [-1 MPa, -2 MPa, -0.5 MPa]}\n";
    }
  s += "dem: {rounding: 1 cm, damping: none}\ntime: {end: 1}\n";
  return s;
}

void expect_at_rest_under_the_initial_stress(const std::string& joint, const std::string& name) {
  const Scene scene = read_scene_text(confined_scene(joint), name + ".yaml");
  // Two updates of 100 cycles, undamped: an unbalanced contact would ring.
  Scene short_run = scene;
  short_run.time.max_steps = 2;
  const RunResult r = run_scene(short_run, name);
  for (std::size_t b = 4; b < r.state.blocks.size(); ++b) {
    const Block& block = r.state.blocks[b];
    for (std::size_t v = 0; v < block.polygon.vertices.size(); ++v)
      EXPECT_LT((block.polygon.vertices[v] - block.initial_vertices[v]).norm(), 1e-12)
          << block.name << " moved";
    // Each contact's point lies on the block's face (no overlap: the law
    // holds the closure), so the Love-Weber sum is the stress to round-off.
    EXPECT_NEAR(block.stress.x(), -1e6, 1e-3) << block.name;
    EXPECT_NEAR(block.stress.y(), -2e6, 1e-3) << block.name;
    EXPECT_NEAR(block.stress.z(), -0.5e6, 1e-3) << block.name;
  }
}

TEST(DemInitialStress, ConfinedBlocksStayAtRestOnLinearJoints) {
  expect_at_rest_under_the_initial_stress(
      "cohesion: 2 MPa, tensile_strength: 1 MPa, normal_stiffness: 10 GPa/m, "
      "shear_stiffness: 5 GPa/m",
      "dem_prestress_linear");
}

TEST(DemInitialStress, ConfinedBlocksStayAtRestOnBandisJoints) {
  expect_at_rest_under_the_initial_stress(
      "model: barton_bandis, jrc: 8, jcs: 100 MPa, lab_length: 0.1 m, initial_aperture: 0.5 mm",
      "dem_prestress_bandis");
}

}  // namespace
}  // namespace fissure::testing
