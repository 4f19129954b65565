// verification.md (w), docs/dda.md section 10: a block on a plane whose
// base follows a recorded ground motion slides as Newmark's rigid-plastic
// block (Newmark 1965), integrated separately in
// tests/support/newmark_sliding_block.h (exact between the record's
// samples, no DDA code). The DDA's block differs by the penalty springs'
// elastic offset (mu m g / p_s ~ 1e-6 m) and its first-order start and stop
// of sliding within a step (dt = 1 ms against periods of 0.5 s): about 0.1 %
// of the slip, well inside the 2 % the tests allow.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "tests/support/dynamic_scenes.h"
#include "tests/support/newmark_sliding_block.h"
#include "tests/support/results_file_reader.h"
#include "tests/support/run_scene.h"

namespace fissure::testing {
namespace {

constexpr double kDeg = std::numbers::pi / 180;
const Eigen::Vector2d kGravity(0, -9.81);

MotionSamples samples_of(const BaseAcceleration& a) {
  return {a.t, a.ax, a.ay};
}

SlidingPlane plane_of(double slope) {
  return slope == 0 ? SlidingPlane{} : incline_rising_towards_x(slope * kDeg);
}

struct Comparison {
  double final_dda = 0, final_newmark = 0;
  nlohmann::json energy;     ///< the run's energy terms at its end
  double largest_slip = 0;   ///< of the reference over the run
  double largest_error = 0;  ///< over the output times
};

/// The DDA's slip (block relative to base, along the plane's tangent) at
/// every output time against Newmark's.
Comparison compare(const ShakenBlockSpec& spec, const BaseAcceleration& base,
                   const std::string& name) {
  const RunResult r =
      run_scene(block_on_shaken_plane(spec, samples_of(base), scratch_dir(name + "_scene")), name);
  EXPECT_EQ(r.summary.status, "completed") << r.summary.message;
  auto m = test::monitor_columns(r.outdir);
  const SlidingPlane plane = plane_of(spec.slope);
  const SlidingBlockHistory newmark = newmark_sliding_block(
      base, plane, std::tan(spec.friction_angle * kDeg), kGravity, spec.end, spec.output_interval);
  EXPECT_FALSE(newmark.lifted_off);
  Comparison c;
  c.energy = r.summary.energy;
  const std::size_t n = std::min(m["t"].size(), newmark.t.size());
  EXPECT_GT(n, 10u);
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_NEAR(m["t"][i], newmark.t[i], 1e-9);
    const Eigen::Vector2d relative(m["block.ux"][i] - m["base.ux"][i],
                                   m["block.uy"][i] - m["base.uy"][i]);
    const double slip = relative.dot(plane.tangent);
    c.largest_slip = std::max(c.largest_slip, std::abs(newmark.slip[i]));
    c.largest_error = std::max(c.largest_error, std::abs(slip - newmark.slip[i]));
    c.final_dda = slip;
    c.final_newmark = newmark.slip[i];
  }
  std::printf("%s: slip %.6f m (Newmark %.6f m), largest difference %.3g m of %.4f m\n",
              name.c_str(), c.final_dda, c.final_newmark, c.largest_error, c.largest_slip);
  return c;
}

TEST(DdaGroundMotion, ABlockOnAShakenFloorSlidesBothWaysAsNewmarks) {
  // 0.8 g at 2 Hz against a yield acceleration of g tan 30 = 0.58 g.
  ShakenBlockSpec spec;
  const BaseAcceleration base = sinusoidal_base(0.8 * 9.81, 2, spec.end, 0.5 / 200);
  const Comparison c = compare(spec, base, "dda_shaken_floor");
  EXPECT_GT(c.largest_slip, 0.01);
  EXPECT_LT(c.largest_error, 0.02 * c.largest_slip);
}

TEST(DdaGroundMotion, ABlockOnAShakenInclineCreepsDownAsNewmarks) {
  // A 20 deg incline, phi = 35 deg: downslope yield at g tan 15 = 0.27 g,
  // upslope at g tan 55 = 1.4 g; 0.5 g at 2 Hz ratchets it down.
  ShakenBlockSpec spec;
  spec.slope = 20;
  spec.friction_angle = 35;
  spec.end = 3;
  const BaseAcceleration base = sinusoidal_base(0.5 * 9.81, 2, spec.end, 0.5 / 200);
  const Comparison c = compare(spec, base, "dda_shaken_incline");
  EXPECT_GT(c.final_newmark, 0.05);
  EXPECT_LT(c.largest_error, 0.02 * c.largest_slip);
  // The energy ledger balances: what the base put in (base_work) is what
  // friction took out plus the change of the block's energy (its potential
  // m g 0.25 cos(slope) at the start, at rest), to the first-order terms of
  // the end-of-step forces.
  const nlohmann::json& e = c.energy;
  const double start = 2700 * 0.5 * 9.81 * 0.25 * std::cos(spec.slope * kDeg);
  const double base_work = e["base_work"].get<double>();
  EXPECT_GT(base_work, 100.0);
  EXPECT_NEAR(e["total"].get<double>() + e["friction_dissipation"].get<double>(), start,
              1e-3 * base_work);
}

TEST(DdaGroundMotion, ABlockUnderARecordedLikeAccelerogramSlidesAsNewmarks) {
  // 10 s of a synthetic record (Kanai-Tajimi filtered noise, Saragoni-Hart
  // envelope) of 0.5 g on the same incline, and 2 s after it.
  ShakenBlockSpec spec;
  spec.slope = 20;
  spec.friction_angle = 35;
  spec.end = 12;
  spec.output_interval = 0.02;
  const BaseAcceleration base = synthetic_accelerogram(10, 0.005, 0.5 * 9.81, 1);
  const Comparison c = compare(spec, base, "dda_recorded_like");
  EXPECT_GT(c.final_newmark, 0.005);  // 1.1 cm in a few pulses above the yield
  EXPECT_LT(c.largest_error, 0.02 * c.largest_slip);
}

TEST(DdaGroundMotion, TheSlipGrowsWithTheShakingAsOnTheShakingTable) {
  // Tsesarsky, Hatzor and Sitar (2005) shook a block on an incline with
  // sinusoids of rising amplitude: no slip below the yield acceleration,
  // then a permanent slip that grows faster than the amplitude, which
  // Newmark's block and their DDA followed. Here: 2 Hz, 2 s, the 20/35 deg
  // incline (yield 0.27 g), amplitudes from 0.2 g to 0.8 g.
  ShakenBlockSpec spec;
  spec.slope = 20;
  spec.friction_angle = 35;
  double previous = 0;
  for (const double g : {0.2, 0.35, 0.5, 0.65, 0.8}) {
    const BaseAcceleration base = sinusoidal_base(g * 9.81, 2, spec.end, 0.5 / 200);
    const Comparison c = compare(spec, base, "dda_shaking_table");
    if (g < 0.27) {  // locked: only the springs' elastic offset
      EXPECT_EQ(c.final_newmark, 0);
      EXPECT_LT(std::abs(c.final_dda), 1e-4);
      continue;
    }
    EXPECT_NEAR(c.final_dda, c.final_newmark, 0.02 * c.final_newmark) << g << " g";
    EXPECT_GT(c.final_dda, previous) << g << " g";
    previous = c.final_dda;
  }
}

}  // namespace
}  // namespace fissure::testing
