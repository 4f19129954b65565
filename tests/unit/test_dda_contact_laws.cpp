// The joint laws of the DDA's contacts (mechanics/dda/contact_laws.h): the
// friction coefficient each law gives a contact (JointLaw::friction_coefficient),
// which contacts carry a law's state, and a run with Barton-Bandis contacts
// that restarts from a checkpoint to the bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>

#include "core/io/memory_checkpoint.h"
#include "mechanics/dda/dda_process.h"
#include "rockmass/joints/joint_model.h"
#include "tests/support/dda_scenes.h"

namespace fissure::testing {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

joints::BartonBandisProperties barton_bandis() {
  joints::BartonBandisProperties p;
  p.jrc = 10;
  p.jcs = 100e6;
  p.lab_length = p.field_length = 0.1;  // no scale correction
  p.residual_friction_angle = 30 * kDeg;
  p.initial_aperture = 0.5e-3;
  return p;
}

TEST(DdaContactLaws, BartonBandisFrictionIsTheMobilizedAngleAtTheNormalStress) {
  const joints::JointLaw law(joints::JointModel{barton_bandis()});
  const double sigma = 1e6;  // i = 10 log10(100) = 20 deg
  const double delta_peak = 0.1 / 500 * std::pow(10 / 0.1, 0.33);
  joints::JointLaw::State s = law.state_at(0, false);
  EXPECT_EQ(law.friction_coefficient(s, sigma, 1), 0);  // phi_mob = 0 at rest (Barton 1982)
  std::get<joints::BartonBandis::State>(s).mobilized_displacement = delta_peak;
  EXPECT_NEAR(law.friction_coefficient(s, sigma, 1), std::tan(50 * kDeg), 1e-12);
  std::get<joints::BartonBandis::State>(s).mobilized_displacement = 200 * delta_peak;
  EXPECT_NEAR(law.friction_coefficient(s, sigma, 1), std::tan(30 * kDeg), 1e-12);
}

TEST(DdaContactLaws, ContinuouslyYieldingFrictionIsItsBoundingAngle) {
  joints::ContinuouslyYieldingProperties p;
  p.normal_stiffness = p.shear_stiffness = 10e9;
  p.friction_angle = 30 * kDeg;
  p.initial_friction_angle = 45 * kDeg;
  p.roughness_length = 1e-3;
  const joints::JointLaw law(joints::JointModel{p});
  joints::JointLaw::State s = law.state_at(0, false);
  EXPECT_NEAR(law.friction_coefficient(s, 1e6, 1), 1.0, 1e-15);
  std::get<joints::ContinuouslyYielding::State>(s).bounding_friction_angle = 35 * kDeg;
  EXPECT_NEAR(law.friction_coefficient(s, 2e6, 1), std::tan(35 * kDeg), 1e-15);
}

TEST(DdaContactLaws, OnlyJointsWithANonCoulombModelHaveALaw) {
  std::vector<JointProperties> list(3);
  list[0].friction_angle = 30 * kDeg;  // no model: Coulomb
  joints::CoulombProperties coulomb;
  coulomb.friction_angle = 30 * kDeg;
  list[1].model.set(joints::kJointModel, joints::JointModel{coulomb});
  list[2].model.set(joints::kJointModel, joints::JointModel{barton_bandis()});
  const dda::ContactLaws laws = dda::contact_laws(list);
  ASSERT_EQ(laws.size(), 3u);
  EXPECT_FALSE(laws[0]);
  EXPECT_FALSE(laws[1]);
  ASSERT_TRUE(laws[2]);
  EXPECT_EQ(laws[2]->kind(), joints::JointModelKind::BartonBandis);
}

/// A block sliding down a 50 degree incline on a Barton-Bandis joint of
/// JRC 2 (peak friction 38 degrees at its 8.5 kPa; dynamic): its contacts'
/// law states change in every step.
Scene sliding_block() {
  Scene s = incline_scene(50, 30, 1e-3, 5e9, 1.0);
  joints::BartonBandisProperties p = barton_bandis();
  p.jrc = 2;
  s.joints[0].model.set(joints::kJointModel, joints::JointModel{p});
  return s;
}

/// Steps the process until `steps` steps are accepted.
double run_steps(dda::DdaProcess& dda, RockMass& state, double t, int steps) {
  for (int accepted = 0; accepted < steps;) {
    const double dt = dda.proposed_dt(state);
    if (dda.advance(state, t, dt).status != StepReport::Status::Ok) continue;
    t += dt;
    ++accepted;
  }
  return t;
}

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(DdaContactLaws, ARunWithLawStatesRestartsFromACheckpointToTheBit) {
  const Scene s = sliding_block();
  RockMass state = RockMass::from_scene(s);
  dda::DdaProcess straight(s);
  straight.initialize(state);
  double t = run_steps(straight, state, 0, 60);
  MemoryCheckpoint saved;
  CheckpointWriter writer = saved.writer();
  straight.save(writer, state);
  RockMass saved_state = state;
  const double t_saved = t;
  t = run_steps(straight, state, t, 60);

  dda::DdaProcess restarted(s);
  restarted.initialize(saved_state);
  CheckpointReader reader = saved.reader();
  restarted.restore(reader, saved_state);
  const double t_restarted = run_steps(restarted, saved_state, t_saved, 60);

  EXPECT_TRUE(same_bits(t, t_restarted));
  const Vec2 a = state.blocks[1].section.centroid, b = saved_state.blocks[1].section.centroid;
  EXPECT_TRUE(same_bits(a.x(), b.x()) && same_bits(a.y(), b.y()));
  ASSERT_EQ(straight.contacts().size(), restarted.contacts().size());
  int with_law = 0;
  for (std::size_t k = 0; k < straight.contacts().size(); ++k) {
    const dda::DdaContact &x = straight.contacts()[k], &y = restarted.contacts()[k];
    ASSERT_EQ(x.law.has_value(), y.law.has_value());
    if (!x.law) continue;
    ++with_law;
    const auto& p = std::get<joints::BartonBandis::State>(*x.law);
    const auto& q = std::get<joints::BartonBandis::State>(*y.law);
    EXPECT_TRUE(same_bits(p.mobilized_displacement, q.mobilized_displacement));
    EXPECT_TRUE(same_bits(p.shear_displacement, q.shear_displacement));
    EXPECT_TRUE(same_bits(x.law_friction, y.law_friction));
    EXPECT_GT(p.mobilized_displacement, 0);  // the slide mobilized it
  }
  EXPECT_EQ(with_law, 2);  // the block's two base corners
}

}  // namespace
}  // namespace fissure::testing
