// A REV study under stress with bad input (docs/upscaling.md section 3):
// each refusal names the study's or the scene's file, line and column, the
// key, what was found and what was expected; nothing runs.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "tests/support/bad_scene_checks.h"
#include "tests/support/fissure_command.h"
#include "tests/support/run_scene.h"

namespace fissure {
namespace {

using testing::expect_contains;
using testing::run_fissure;
using testing::scratch_dir;

/// A small rock mass (two persistent sets) with `joint` and `dem` as given.
std::string rock(const std::string& physics = "[dem]",
                 const std::string& joint =
                     "{name: j, model: coulomb, friction_angle: 30, normal_stiffness: 80 GPa/m, "
                     "shear_stiffness: 30 GPa/m}",
                 const std::string& section = "dem: {solve_ratio: 1e-6}") {
  return "physics: " + physics +
         "\nmaterials:\n  - {name: granite, density: 2650, young_modulus: 50 GPa, "
         "poisson_ratio: 0.25}\njoints:\n  - " +
         joint +
         "\nrock_mass:\n  domain: [[-5, -5], [5, -5], [5, 5], [-5, 5]]\n  material: granite\n"
         "  joint_sets:\n    - {name: a, dip: 30, spacing: 1 m, joint: j, aperture: 100 um}\n" +
         section + "\ntime: {end: 1}\n";
}

/// Runs `fissure rev study.yaml` (with `options`) on `study` beside
/// rock.yaml = `rock_yaml`: the exit code, and stderr in `err`.
int run_study(const std::string& study, const std::string& rock_yaml, std::string& err,
              const std::string& options = "") {
  const std::filesystem::path dir = scratch_dir("rev_stress_bad_input");
  std::ofstream(dir / "rock.yaml") << rock_yaml;
  std::ofstream(dir / "study.yaml") << study;
  return run_fissure("rev study.yaml --no-plots -q -o out " + options, dir, err);
}

const std::string kScene =
    "network: {type: scene, scene: rock.yaml}\nsizes: [2]\nrealizations: 1\n";

TEST(RevStressBadInput, MechanicsNeedsTheRockOfAScene) {
  std::string err;
  EXPECT_EQ(run_study("network: {type: regular, sets: [{angle: 0, spacing: 1, aperture: 1e-4}]}\n"
                      "sizes: [2]\nrotations: 1\nmechanics:\n  stresses: [{sigma_1: 2 MPa, "
                      "sigma_3: 1 MPa}]\n",
                      rock(), err),
            1);
  expect_contains(err,
                  "study.yaml:5:3: mechanics: found a mechanics section with a network of type "
                  "other than scene");
  expect_contains(err, "expected network: {type: scene, scene: FILE}");
}

TEST(RevStressBadInput, TheBlockProcessMustSolveToRest) {
  std::string err;
  const std::string study =
      kScene + "rotations: 1\nmechanics:\n  stresses: [{sigma_1: 2 MPa, sigma_3: 1 MPa}]\n";
  EXPECT_EQ(run_study(study,
                      rock("[dem]",
                           "{name: j, model: coulomb, friction_angle: 30, "
                           "normal_stiffness: 80 GPa/m, shear_stiffness: 30 GPa/m}",
                           "dem: {rounding: 1 cm}"),
                      err),
            1);
  expect_contains(err, "without dem.solve_ratio; expected one");
  EXPECT_EQ(run_study(study,
                      rock("[mechanics]", "{name: j, friction_angle: 30}",
                           "mechanics: {dda: {time_step: 1 ms}}"),
                      err),
            1);
  expect_contains(err, "whose physics has no dem; expected physics [dem] with dem.solve_ratio");
}

TEST(RevStressBadInput, SquaresTurnOnlyByQuarterTurns) {
  std::string err;
  EXPECT_EQ(run_study(kScene + "rotations: 3\nrotation_step: 30 deg\nmechanics:\n  stresses: "
                               "[{sigma_1: 2 MPa, sigma_3: 1 MPa}]\n",
                      rock(), err),
            1);
  expect_contains(err, "found rotations of 30 deg; expected rotations: 1 or a rotation_step of 90");
}

TEST(RevStressBadInput, StatesAreCheckedAtTheirKeys) {
  std::string err;
  // sigma_3 above sigma_1.
  EXPECT_EQ(run_study(kScene + "rotations: 1\nmechanics:\n  stresses:\n    - {sigma_1: 1 MPa, "
                               "sigma_3: 2 MPa}\n",
                      rock(), err),
            1);
  expect_contains(err, "study.yaml:7:7: mechanics.stresses[0]: found sigma_3 = 2e+06 Pa above");
  // Both forms at once.
  EXPECT_EQ(run_study(kScene + "rotations: 1\nmechanics:\n  stresses:\n    - {stress: [-1 MPa, "
                               "-1 MPa, 0], sigma_1: 2 MPa}\n",
                      rock(), err),
            1);
  expect_contains(err, "found both stress and sigma_1/sigma_3/angle");
  // Tension after the pore pressure.
  EXPECT_EQ(run_study(kScene + "rotations: 1\nmechanics:\n  pore_pressure: 3 MPa\n  stresses:\n"
                               "    - {sigma_1: 5 MPa, sigma_3: 2 MPa}\n",
                      rock(), err),
            1);
  expect_contains(err, "found an effective principal stress in tension");
  // A stress in the wrong unit.
  EXPECT_EQ(run_study(kScene + "rotations: 1\nmechanics:\n  stresses:\n    - {sigma_1: 5 m, "
                               "sigma_3: 2 MPa}\n",
                      rock(), err),
            1);
  expect_contains(
      err,
      "study.yaml:7:17: mechanics.stresses[0].sigma_1: found '5 m', a length; expected a pressure");
  // Beyond a Barton-Bandis joint's JCS.
  EXPECT_EQ(run_study(kScene + "rotations: 1\nmechanics:\n  stresses:\n    - {sigma_1: 150 MPa, "
                               "sigma_3: 100 MPa}\n",
                      rock("[dem]",
                           "{name: j, model: barton_bandis, friction_angle: 28, jrc: 6, jcs: 120 "
                           "MPa, lab_length: 0.1 m, initial_aperture: 120 um}"),
                      err),
            1);
  expect_contains(err, "not below joint 'j''s");
}

// The short checks' options (--states, --sizes) name indices into the
// study's lists: one it does not have is refused at the list's key.
TEST(RevStressBadInput, ShortChecksNameOnlyWhatTheStudyHas) {
  std::string err;
  const std::string study =
      kScene + "rotations: 1\nmechanics:\n  stresses: [{sigma_1: 2 MPa, sigma_3: 1 MPa}]\n";
  EXPECT_EQ(run_study(study, rock(), err, "--states 1"), 1);
  expect_contains(err,
                  "study.yaml:6:3: mechanics: --states names state 1, but the study has 1; "
                  "expected indices below it (from 0)");
  EXPECT_EQ(run_study(study, rock(), err, "--sizes 0,3"), 1);
  expect_contains(err,
                  "study.yaml:2:8: sizes: --sizes names size 3, but the study has 1; "
                  "expected indices below it (from 0)");
}

// `--sizes` solves the domains of the sizes it names, in increasing order,
// and they are the full study's: a domain depends on its size and
// realization, not on the sizes around it.
TEST(RevStressBadInput, ChosenSizesGiveTheFullStudysDomains) {
  const std::filesystem::path dir = scratch_dir("rev_chosen_sizes");
  std::ofstream(dir / "study.yaml")
      << "network:\n  type: dfn\n  dfn:\n    region: 12 m\n    seed: 7\n    families:\n"
         "      - {name: a, density: {p21: 2.0 1/m}, orientation: {distribution: von_mises, mean: "
         "20 deg, kappa: 8}, length: {distribution: truncated_power_law, exponent: 1.5, min: 1 m, "
         "max: 5 m}, aperture: {distribution: log_normal, mean: 70 um, std: 8 um}}\n"
         "sizes: [2 m, 3 m, 4 m]\nrealizations: 2\nrotations: 1\n";
  std::string err;
  ASSERT_EQ(run_fissure("rev study.yaml --no-plots -q -o all", dir, err), 0) << err;
  ASSERT_EQ(run_fissure("rev study.yaml --no-plots -q -o chosen --sizes 2,0,2", dir, err), 0)
      << err;
  // The permeability columns of each (size, realization) row.
  auto rows = [&dir](const std::string& folder) {
    std::map<std::pair<double, int>, std::string> by_domain;
    std::ifstream in(dir / folder / "domains.csv");
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
      std::istringstream fields(line);
      double size = 0;
      int realization = 0;
      char comma = 0;
      fields >> size >> comma >> realization;
      by_domain[{size, realization}] = line.substr(0, line.rfind(','));  // without the seconds
    }
    return by_domain;
  };
  const auto all = rows("all"), chosen = rows("chosen");
  ASSERT_EQ(all.size(), 6u);
  ASSERT_EQ(chosen.size(), 4u);
  for (const auto& [domain, row] : chosen) {
    EXPECT_NE(domain.first, 3.0);
    ASSERT_TRUE(all.contains(domain));
    EXPECT_EQ(row, all.at(domain));
  }
}

}  // namespace
}  // namespace fissure
