// Bad values of a DEM scene are refused where the scene says them
// (docs/scene-reference.md section 14, docs/dem.md section 6): a Coulomb
// joint without stiffnesses (the DEM has no penalty of its own), a
// rounding longer than a block's edge, a time step above the critical one,
// a damping coefficient out of range (local or Rayleigh's, or the two
// together), fixed points (the DEM holds whole
// blocks), and `mechanics` beside `dem` (two writers of the same fields).
#include <gtest/gtest.h>

#include <string>

#include "coupling/process_registry.h"
#include "tests/support/bad_scene_checks.h"

namespace fissure::testing {
namespace {

const std::string kDemScene = R"(physics: [dem]
materials:
  - {name: granite, density: 2650 kg/m^3, young_modulus: 50 GPa, poisson_ratio: 0.25}
joints:
  - name: bedding
    friction_angle: 30
    normal_stiffness: 10 GPa/m
    shear_stiffness: 5 GPa/m
blocks:
  - {name: base, vertices: [[0, 0], [10, 0], [10, 1], [0, 1]], fixed: true}
  - {name: top, vertices: [[4, 1], [6, 1], [6, 2], [4, 2]]}
dem:
  rounding: 10 mm
time:
  end: 1
)";

TEST(dem_bad_input, TheValidSceneStarts) {
  EXPECT_EQ(start_error(kDemScene), "");
}

TEST(dem_bad_input, ACoulombJointWithoutStiffnessIsRefusedAtTheJoint) {
  const std::string y =
      replace(kDemScene, "    normal_stiffness: 10 GPa/m\n    shear_stiffness: 5 GPa/m\n", "");
  expect_error(errors(y), at(y, "name: bedding"), "joints[0]",
               {"has no normal_stiffness and shear_stiffness", "the DEM's contacts"});
}

TEST(dem_bad_input, ValuesOutOfRange) {
  std::string y = replace(kDemScene, "  rounding: 10 mm\n", "  rounding: -1 mm\n");
  expect_error(errors(y), at(y, "-1 mm"), "dem.rounding", {"found '-1 mm'", "> 0"});
  y = replace(kDemScene, "  rounding: 10 mm\n", "  damping: {local: 1.2}\n");
  expect_error(errors(y), at(y, "1.2"), "dem.damping.local", {"found '1.2'", "[0, 1)"});
  y = replace(kDemScene, "  rounding: 10 mm\n", "  damping: strong\n");
  expect_error(errors(y), at(y, "strong"), "dem.damping", {"found 'strong'", "'none'"});
  y = replace(kDemScene, "  rounding: 10 mm\n", "  safety_factor: 2\n");
  expect_error(errors(y), at(y, "2\n"), "dem.safety_factor", {"found '2'", "(0, 1]"});
  y = replace(kDemScene, "  rounding: 10 mm\n", "  solve_ratio: 0\n");
  expect_error(errors(y), at(y, "0\ntime"), "dem.solve_ratio", {"found '0'", "(0, 1)"});
  y = replace(kDemScene, "  rounding: 10 mm\n", "  zone_size: 0 m\n");
  expect_error(errors(y), at(y, "0 m"), "dem.zone_size", {"found '0 m'", "> 0"});
  // Density scaling changes the motion: only in a solve to a ratio.
  y = replace(kDemScene, "  rounding: 10 mm\n", "  density_scaling: true\n");
  expect_error(errors(y), at(y, "true\ntime"), "dem.density_scaling", {"without dem.solve_ratio"});
  y = replace(kDemScene, "  rounding: 10 mm\n",
              "  solve_ratio: 1e-5\n  time_step: 10 us\n  density_scaling: true\n");
  expect_error(errors(y), at(y, "true\ntime"), "dem.density_scaling", {"time_step: auto"});
}

TEST(dem_bad_input, RayleighDampingOutOfRangeOrMixedIsRefusedAtItsKey) {
  const auto with = [](const std::string& damping) {
    return replace(kDemScene, "  rounding: 10 mm\n", "  damping: " + damping + "\n");
  };
  EXPECT_EQ(start_error(with("{rayleigh: {fraction: 0.05, frequency: 10 Hz}}")), "");
  EXPECT_EQ(start_error(with("{rayleigh: {mass: 2, stiffness: 1e-4}}")), "");
  std::string y = with("{rayleigh: {fraction: -0.05, frequency: 10 Hz}}");
  expect_error(errors(y), at(y, "-0.05"), "dem.damping.rayleigh.fraction",
               {"found '-0.05'", "(0, 1)"});
  y = with("{rayleigh: {fraction: 0.05, frequency: -10 Hz}}");
  expect_error(errors(y), at(y, "-10 Hz"), "dem.damping.rayleigh.frequency",
               {"found '-10 Hz'", "> 0"});
  y = with("{rayleigh: {mass: -2, stiffness: 1e-4}}");
  expect_error(errors(y), at(y, "-2"), "dem.damping.rayleigh.mass", {"found '-2'", ">= 0"});
  y = with("{rayleigh: {mass: 2, stiffness: -1e-4}}");
  expect_error(errors(y), at(y, "-1e-4"), "dem.damping.rayleigh.stiffness",
               {"found '-1e-4'", ">= 0"});
  y = with("{rayleigh: {fraction: 0.05}}");
  expect_error(errors(y), at(y, "{fraction"), "dem.damping.rayleigh.frequency",
               {"key is missing", "frequency > 0"});
  y = with("{rayleigh: {fraction: 0.05, frequency: 10 Hz, mass: 2}}");
  expect_error(errors(y), at(y, "{fraction"), "dem.damping.rayleigh", {"one form"});
  y = with("{local: 0.8, rayleigh: {mass: 2, stiffness: 1e-4}}");
  expect_error(errors(y), at(y, "{mass"), "dem.damping.rayleigh", {"beside local damping"});
}

// Refused when the processes are made, with the key's location.
TEST(dem_bad_input, ARoundingLongerThanAnEdgeNamesTheBlockAndTheEdge) {
  const std::string y = replace(kDemScene, "  rounding: 10 mm\n", "  rounding: 1.5 m\n");
  const std::string message = start_error(y);
  expect_contains(message, at(y, "1.5 m") + ": dem.rounding: found 1.5 m");
  expect_contains(message, "block 'base'");
}

TEST(dem_bad_input, ATimeStepAboveTheCriticalOneIsRefusedAtItsKey) {
  // The 2 x 1 m block of 2650 kg/m^3 on two contacts of 1 m (k_n 10 GPa/m):
  // 2 sqrt(m / (k L)) = 2 sqrt(5300 / 1e10) = 4.6e-5 s.
  const std::string y = replace(kDemScene, "  rounding: 10 mm\n", "  time_step: 1 ms\n");
  const std::string message = start_error(y);
  expect_contains(message, at(y, "1 ms") + ": dem.time_step: found 0.001 s, above the critical");
  // ... and one below it runs.
  EXPECT_EQ(start_error(replace(kDemScene, "  rounding: 10 mm\n", "  time_step: 10 us\n")), "");
}

TEST(dem_bad_input, FixedPointsAreRefused) {
  const std::string y =
      replace(kDemScene, "dem:\n", "fixed_points:\n  - {point: [5, 1.5]}\ndem:\n");
  expect_contains(start_error(y), "fixed_points: found 1; the DEM holds whole blocks");
}

TEST(dem_bad_input, TheDdaAndTheDemTogetherAreRefused) {
  const std::string y = replace(replace(kDemScene, "physics: [dem]", "physics: [mechanics, dem]"),
                                "dem:\n", "mechanics: {}\ndem:\n");
  expect_error(errors(y), at(y, "dem]"), "physics[1]",
               {"found 'dem' beside 'mechanics'", "one process that moves the blocks"});
}

}  // namespace
}  // namespace fissure::testing
