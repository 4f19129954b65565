// Bad joints[].model values are refused with FILE:LINE:COLUMN, the key and
// what was expected (docs/scene-reference.md section 4): a negative
// stiffness, JRC outside (0, 20], an exponent outside [0, 1), a model
// misspelt, another model's key, Bandis's regressions out of their range,
// and an initial stress at or above JCS, where the scene says it.
#include <gtest/gtest.h>

#include <string>

#include "coupling/process_registry.h"
#include "tests/support/bad_scene_checks.h"

namespace fissure::testing {
namespace {

const std::string kJointLine = "    friction_angle: 30\n";

/// kValid with `keys` after the joint's friction angle.
std::string with_joint_keys(const std::string& keys) {
  return replace(kValid, kJointLine, kJointLine + keys);
}

const std::string kBartonBandis =
    "    model: barton_bandis\n    jrc: 10\n    jcs: 50 MPa\n    lab_length: 0.1 m\n"
    "    initial_aperture: 0.5 mm\n";

TEST(joint_model_bad_input, ValuesOutOfRange) {
  std::string y = with_joint_keys("    normal_stiffness: -1 GPa/m\n    shear_stiffness: 1 GPa/m\n");
  expect_error(errors(y), at(y, "-1 GPa/m"), "joints[0].normal_stiffness",
               {"found '-1 GPa/m'", "expected a joint normal stiffness > 0"});

  y = with_joint_keys(replace(kBartonBandis, "jrc: 10", "jrc: 25"));
  expect_error(errors(y), at(y, "jrc: 25", 5), "joints[0].jrc",
               {"found '25'", "expected a number in (0, 20]"});

  y = with_joint_keys(
      "    model: continuously_yielding\n    normal_stiffness: 20 GPa/m\n"
      "    normal_stiffness_exponent: 1.2\n    shear_stiffness: 10 GPa/m\n"
      "    initial_friction_angle: 20\n    roughness_length: 1 mm\n");
  const auto lines = errors(y);
  expect_error(lines, at(y, "1.2"), "joints[0].normal_stiffness_exponent",
               {"found '1.2'", "expected a number in [0, 1)"});
  // phi_m0 below phi (the friction angle, 30 deg).
  expect_error(lines, at(y, "20\n    rough"), "joints[0].initial_friction_angle",
               {"found '20'", "expected an angle in [30, 90) deg"});

  y = with_joint_keys(replace(kBartonBandis, "    model", "    max_closure: 0.6 mm\n    model"));
  expect_error(errors(y), at(y, "0.6 mm"), "joints[0].max_closure",
               {"not below initial_aperture (0.5 mm)"});

  y = replace(with_joint_keys(kBartonBandis), "friction_angle: 30", "friction_angle: 75");
  expect_error(errors(y), at(y, "75"), "joints[0].friction_angle", {"below 70 deg"});
}

TEST(joint_model_bad_input, ModelNamesAndKeys) {
  std::string y = with_joint_keys("    model: barton_bandiss\n");
  expect_error(errors(y), at(y, "barton_bandiss"), "joints[0].model",
               {"did you mean 'barton_bandis'"});

  // A misspelt key lists the keys of the joint's model.
  y = with_joint_keys(kBartonBandis + "    jcss: 1\n");
  expect_error(errors(y), at(y, "jcss"), "joints[0].jcss",
               {"unknown key 'jcss' (did you mean 'jcs'?); expected one of: name, friction_angle, "
                "model, jrc, jcs, lab_length, field_length, initial_aperture, "
                "initial_normal_stiffness, max_closure"});

  y = with_joint_keys("    jrc: 10\n");
  expect_error(errors(y), at(y, "jrc"), "joints[0].jrc",
               {"a key of model barton_bandis", "its model is coulomb"});

  y = with_joint_keys("    cohesion: 1 MPa\n" + kBartonBandis);
  expect_error(errors(y), at(y, "cohesion"), "joints[0].cohesion",
               {"a key of model coulomb", "its model is barton_bandis"});

  y = with_joint_keys(replace(kBartonBandis, "    jcs: 50 MPa\n", ""));
  expect_error(errors(y), at(y, "name: bedding"), "joints[0].jcs", {"key is missing"});

  y = with_joint_keys("    normal_stiffness: 10 GPa/m\n");
  expect_error(errors(y), at(y, "name: bedding"), "joints[0].shear_stiffness",
               {"key is missing", "both normal_stiffness and shear_stiffness, or neither"});
}

TEST(joint_model_bad_input, BandisRegressionsOutsideTheirData) {
  // k_ni = -7.15 + 1.75 + 0.02 x 10 = -5.2 MPa/mm.
  const std::string y = with_joint_keys(
      "    model: barton_bandis\n    jrc: 1\n    jcs: 10 MPa\n    lab_length: 0.1 m\n"
      "    initial_aperture: 1 mm\n");
  expect_error(
      errors(y), at(y, "name: bedding"), "joints[0]",
      {"Bandis's regressions give k_ni = -5.2 GPa/m", "expected initial_normal_stiffness given"});
  // Given, they are not needed.
  EXPECT_NO_THROW(read_scene_text(
      replace(y, "    model", "    initial_normal_stiffness: 5 GPa/m\n    model"), "ok.yaml"));
}

TEST(joint_model_bad_input, InitialStressAtJcs) {
  // A block's initial stress: the largest compression, 60 MPa, reaches JCS 50 MPa.
  std::string y = replace(with_joint_keys(kBartonBandis), "    fixed: true\n",
                          "    fixed: true\n    initial_stress: [-60 MPa, -10 MPa, 0]\n");
  expect_error(errors(y), at(y, "[-60 MPa"), "blocks[0].initial_stress",
               {"largest compression of 60 MPa", "joint 'bedding''s jcs (50 MPa"});
  // 40 MPa is below it.
  EXPECT_NO_THROW(read_scene_text(replace(y, "-60 MPa", "-40 MPa"), "ok.yaml"));
  // A shear stress adds to it: [-40, -40, 15] has 55 MPa on its principal plane.
  EXPECT_FALSE(errors(replace(y, "[-60 MPa, -10 MPa, 0]", "[-40 MPa, -40 MPa, 15 MPa]")).empty());

  // A rock mass's in-situ stress, against the joints of its sets (JCS at the
  // field length: 50 MPa x 10^-0.3 = 25 MPa at 1 m).
  const std::string rock_mass = R"(physics: [mechanics]
materials:
  - {name: granite, density: 2650 kg/m^3, young_modulus: 50 GPa, poisson_ratio: 0.25}
joints:
  - {name: plain, friction_angle: 30}
  - {name: rough, model: barton_bandis, friction_angle: 28, jrc: 10, jcs: 50 MPa,
     lab_length: 0.1 m, field_length: 1 m, initial_aperture: 0.5 mm}
rock_mass:
  domain: [[0, 0], [20, 0], [20, 10], [0, 10]]
  joint_sets:
    - {name: bedding, dip: 10, spacing: 2 m, joint: rough}
  initial_stress: [-30 MPa, -10 MPa, 0]
mechanics: {}
time:
  end: 0.01
)";
  expect_error(errors(rock_mass), at(rock_mass, "[-30 MPa"), "rock_mass.initial_stress",
               {"largest compression of 30 MPa", "joint 'rough''s jcs (25.06 MPa"});
  EXPECT_NO_THROW(read_scene_text(replace(rock_mass, "-30 MPa", "-20 MPa"), "ok.yaml"));
}

}  // namespace
}  // namespace fissure::testing
