// A cut block system runs in DDA (issue 3 verification 4; docs/rock-mass.md
// section 4): a small rock slope (toe at x = 4 m, crest at x = 8 m, a 45 deg
// face 4 m high) cut by a persistent bedding set dipping 20 deg out of the
// face and a steep cross set, blocks on the base and the sides fixed, settles
// under gravity for 0.2 s of dynamic DDA (k01 = 1).
//
// With bedding friction 35 deg > 20 deg dip nothing may slide: the run
// completes, the total energy (kinetic + potential + strain + springs) never
// rises above its start, no contact penetrates deeper than the penalty
// springs allow, and every free block moves only by the elastic and
// contact-spring settlement of the slope. The same slope with 10 deg bedding
// friction is the control: the blocks that daylight on the face slide
// down-dip by centimetres, so the "stays" check can tell the two apart.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "coupling/process_registry.h"
#include "mechanics/dda/dda_process.h"
#include "rockmass/generate_rock_mass.h"

namespace fissure {
namespace {

constexpr double kDensity = 2500, kYoung = 10e9, kG = 9.81, kHeight = 6;
constexpr double kEndTime = 0.2;

std::string slope_scene(int bedding_friction_deg) {
  return R"(physics: [mechanics]
materials:
  - {name: sandstone, density: 2500 kg/m^3, young_modulus: 10 GPa, poisson_ratio: 0.25}
joints:
  - {name: bedding, friction_angle: )" +
         std::to_string(bedding_friction_deg) + R"(}
  - {name: cross, friction_angle: 40}
rock_mass:
  domain: [[0, 0], [12, 0], [12, 6], [8, 6], [4, 2], [0, 2]]
  material: sandstone
  joint_sets:
    - {name: bedding, dip: 20, spacing: 1.2 m, phase: 0.5, joint: bedding}
    - {name: cross, dip: 105, spacing: 2.5 m, phase: 0.3, joint: cross}
  merge_tolerance: 5 cm
  fixed_blocks: {boundaries: [bottom, left, right]}
mechanics:
  dda:
    time_step: 1 ms
time:
  end: 0.2
)";
}

struct SettlingRun {
  int blocks = 0, free_blocks = 0, steps = 0, retries = 0;
  double end_time = 0;           ///< s, simulated time reached
  double worst_energy_gain = 0;  ///< J, largest total energy above the start
  double energy_scale = 0;       ///< J, sum of |m g y| at the start
  double max_penetration = 0;    ///< m, over every step
  double max_displacement = 0;   ///< m, largest centroid displacement of a free block
  double free_weight = 0;        ///< N/m, weight of the free blocks
  double normal_penalty = 0, shear_penalty = 0;  ///< N/m
};

SettlingRun settle(int bedding_friction_deg) {
  const Scene scene = read_scene_text(slope_scene(bedding_friction_deg), "slope.yaml");
  RockMass state = RockMass::from_scene(scene);
  dda::DdaProcess dda(scene);
  dda.initialize(state);

  SettlingRun r;
  r.blocks = static_cast<int>(state.blocks.size());
  std::vector<Vec2> start;
  for (const Block& b : state.blocks) {
    start.push_back(b.section.centroid);
    if (b.fixed) continue;
    ++r.free_blocks;
    r.free_weight += kDensity * b.section.area * kG;
    r.energy_scale += std::abs(kDensity * b.section.area * kG * b.section.centroid.y());
  }
  r.normal_penalty = dda.parameters().normal_penalty;
  r.shear_penalty = dda.parameters().shear_penalty;

  const double e0 = dda.energy(state)["total"];
  double t = 0;
  r.worst_energy_gain = -1e300;
  while (t < kEndTime && r.retries < 1000) {
    const double dt = std::min(dda.proposed_dt(state), kEndTime - t);
    const StepReport report = dda.advance(state, t, dt);
    if (report.status != StepReport::Status::Ok) {
      ++r.retries;
      continue;
    }
    t += dt;
    ++r.steps;
    r.worst_energy_gain =
        std::max(r.worst_energy_gain, dda.energy(state)["total"].get<double>() - e0);
  }
  r.end_time = t;
  r.max_penetration = dda.statistics()["max_penetration"].get<double>();
  for (size_t b = 0; b < state.blocks.size(); ++b)
    if (!state.blocks[b].fixed)
      r.max_displacement =
          std::max(r.max_displacement, (state.blocks[b].section.centroid - start[b]).norm());
  return r;
}

TEST(CutBlocksInDda, JointedSlopeSettlesWithoutSlidingOrEnergyGain) {
  const SettlingRun r = settle(35);
  std::printf(
      "slope: %d blocks (%d free), %d steps, %d retries; energy gain %.3e J (scale "
      "%.3e J); max penetration %.3e m; max displacement %.3e m\n",
      r.blocks, r.free_blocks, r.steps, r.retries, r.worst_energy_gain, r.energy_scale,
      r.max_penetration, r.max_displacement);
  ASSERT_GT(r.free_blocks, 5) << "the joint sets must cut free blocks out of the slope";

  // Completes the whole 0.2 s (a rejected step, at the displacement limit or
  // the open-close iteration, is retried with the smaller dt the process
  // proposes, as the coordinator does); the last step ends on kEndTime up to
  // the round-off of summing the steps.
  EXPECT_NEAR(r.end_time, kEndTime, 1e-12);

  // Energy: Newmark with beta = 1/2, gamma = 1 and Coulomb friction only
  // dissipate. Allowance: round-off of the potential-energy sum, ~1e4 ulps of
  // its terms |m g y|.
  EXPECT_LE(r.worst_energy_gain, 1e-12 * r.energy_scale);

  // Penetration: a contact carries at most the weight of every free block
  // (W), and a load applied from rest at most doubles a linear spring's
  // static deflection W / p_n.
  EXPECT_LT(r.max_penetration, 2 * r.free_weight / r.normal_penalty);

  // Stays: what a block may move without sliding is the elastic shortening
  // of the slope under its own weight (a column of height H: rho g H^2 /
  // (2 E)) plus the contact springs, normal and shear, of the joints below
  // it (at most one per 1.2 m bedding layer, each loaded by at most W), both
  // doubled for the dynamic load from rest. Sliding at 20 deg dip would
  // instead move the face blocks by centimetres (the control below).
  const int layers = static_cast<int>(std::ceil(kHeight / 1.2));
  const double elastic = kDensity * kG * kHeight * kHeight / (2 * kYoung);
  const double springs = layers * r.free_weight * (1 / r.normal_penalty + 1 / r.shear_penalty);
  std::printf("bounds: penetration %.3e m, displacement %.3e m\n",
              2 * r.free_weight / r.normal_penalty, 2 * (elastic + springs));
  EXPECT_LT(r.max_displacement, 2 * (elastic + springs));
}

TEST(CutBlocksInDda, SameSlopeSlidesWhenBeddingFrictionIsBelowTheDip) {
  // Friction 10 deg on a 20 deg plane: a free block on it accelerates at
  // g (sin 20 - cos 20 tan 10) = 1.73 m/s^2, 3.5 cm in 0.2 s. Blocks held
  // back by their neighbours slide less; one block that slides at least half
  // as far (three orders above the bound of the first test) shows the check
  // tells sliding from settling.
  const SettlingRun r = settle(10);
  std::printf("control: %d steps, max displacement %.3e m\n", r.steps, r.max_displacement);
  constexpr double deg = std::numbers::pi / 180;
  const double free_slide = 0.5 * kG *
                            (std::sin(20 * deg) - std::cos(20 * deg) * std::tan(10 * deg)) *
                            kEndTime * kEndTime;
  EXPECT_GT(r.max_displacement, 0.5 * free_slide);
  EXPECT_LE(r.worst_energy_gain, 1e-12 * r.energy_scale);
}

}  // namespace
}  // namespace fissure
