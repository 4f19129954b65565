// joints[].model and its keys (docs/scene-reference.md section 4): read in
// SI from the units a scene writes, kept for the processes in
// JointProperties::model; a joint with today's keys alone keeps no model
// (Coulomb with the process's own springs: the DDA's scenes unchanged).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <variant>

#include "coupling/process_registry.h"
#include "rockmass/joints/joint_model.h"
#include "tests/support/bad_scene_checks.h"

namespace fissure::testing {
namespace {

using joints::JointModel;

constexpr double kDeg = std::numbers::pi / 180;

/// kValid with the joint entry's keys after `friction_angle: 30` added.
Scene with_joint_keys(const std::string& keys) {
  return read_scene_text(
      replace(kValid, "    friction_angle: 30\n", "    friction_angle: 30\n" + keys), "joint.yaml");
}

TEST(joint_model_reading, TodaysKeysKeepNoModel) {
  const Scene s = read_scene_text(kValid, "joint.yaml");
  ASSERT_EQ(s.joints.size(), 1u);
  EXPECT_TRUE(s.warnings.empty());
  EXPECT_FALSE(s.joints[0].model.contains(joints::kJointModel.name));
  EXPECT_EQ(s.joints[0].largest_normal_stress, std::numeric_limits<double>::infinity());
  const JointModel m = joints::joint_model(s.joints[0]);
  ASSERT_EQ(joints::kind_of(m), joints::JointModelKind::Coulomb);
  const auto& c = std::get<joints::CoulombProperties>(m);
  EXPECT_DOUBLE_EQ(c.friction_angle, 30 * kDeg);
  EXPECT_EQ(c.normal_stiffness, 0);  // the process's own springs
  EXPECT_EQ(c.dilation_angle, 0);
}

TEST(joint_model_reading, CoulombWithStiffnessAndDilation) {
  const Scene s = with_joint_keys(
      "    cohesion: 0.5 MPa\n    normal_stiffness: 10 GPa/m\n    shear_stiffness: 5 MPa/mm\n"
      "    dilation_angle: 5\n    zero_dilation_displacement: 2 mm\n");
  const JointModel m = joints::joint_model(s.joints[0]);
  const auto& c = std::get<joints::CoulombProperties>(m);
  EXPECT_DOUBLE_EQ(c.cohesion, 0.5e6);
  EXPECT_DOUBLE_EQ(c.normal_stiffness, 10e9);
  EXPECT_DOUBLE_EQ(c.shear_stiffness, 5e9);
  EXPECT_DOUBLE_EQ(c.dilation_angle, 5 * kDeg);
  EXPECT_DOUBLE_EQ(c.zero_dilation_displacement, 2e-3);
  // Named without keys of its own: still the process's springs.
  const Scene named = with_joint_keys("    model: coulomb\n");
  EXPECT_EQ(
      std::get<joints::CoulombProperties>(joints::joint_model(named.joints[0])).normal_stiffness,
      0);
}

TEST(joint_model_reading, BartonBandisInTheUnitsOfItsLiterature) {
  const Scene s = with_joint_keys(
      "    model: barton_bandis\n    jrc: 10\n    jcs: 100 MPa\n    lab_length: 100 mm\n"
      "    field_length: 1 m\n    initial_aperture: 500 um\n");
  const JointModel m = joints::joint_model(s.joints[0]);
  ASSERT_EQ(joints::kind_of(m), joints::JointModelKind::BartonBandis);
  const auto& b = std::get<joints::BartonBandisProperties>(m);
  EXPECT_EQ(b.jrc, 10);
  EXPECT_DOUBLE_EQ(b.jcs, 100e6);
  EXPECT_DOUBLE_EQ(b.lab_length, 0.1);
  EXPECT_DOUBLE_EQ(b.field_length, 1);
  EXPECT_DOUBLE_EQ(b.initial_aperture, 0.5e-3);
  EXPECT_DOUBLE_EQ(b.residual_friction_angle, 30 * kDeg);  // friction_angle is phi_r
  EXPECT_EQ(b.initial_normal_stiffness, 0);                // from the regressions
  // The initial stresses are checked against JCS at the field length.
  EXPECT_DOUBLE_EQ(s.joints[0].largest_normal_stress, 100e6 * std::pow(10, -0.3));
  EXPECT_EQ(s.joints[0].largest_normal_stress_key, "jcs");
  EXPECT_NO_THROW(joints::BartonBandis law(b));
  // The DDA's contacts use the model (docs/dda.md section 9): no warning.
  EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
}

TEST(joint_model_reading, ContinuouslyYieldingWithItsExponents) {
  const Scene s = with_joint_keys(
      "    model: continuously_yielding\n    normal_stiffness: 20 GPa/m\n"
      "    normal_stiffness_exponent: 0.5\n    shear_stiffness: 10 GPa/m\n"
      "    reference_normal_stress: 2 MPa\n    initial_friction_angle: 45 deg\n"
      "    roughness_length: 0.5 mm\n");
  const JointModel m = joints::joint_model(s.joints[0]);
  const auto& y = std::get<joints::ContinuouslyYieldingProperties>(m);
  EXPECT_DOUBLE_EQ(y.normal_stiffness, 20e9);
  EXPECT_EQ(y.normal_stiffness_exponent, 0.5);
  EXPECT_EQ(y.shear_stiffness_exponent, 0);
  EXPECT_DOUBLE_EQ(y.reference_normal_stress, 2e6);
  EXPECT_DOUBLE_EQ(y.friction_angle, 30 * kDeg);
  EXPECT_DOUBLE_EQ(y.initial_friction_angle, 45 * kDeg);
  EXPECT_DOUBLE_EQ(y.roughness_length, 0.5e-3);
  EXPECT_NO_THROW(joints::ContinuouslyYielding law(y));
}

}  // namespace
}  // namespace fissure::testing
