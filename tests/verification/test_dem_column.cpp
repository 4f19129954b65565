// The explicit DEM process on a column of rigid blocks at rest
// (docs/verification.md, "Explicit DEM (mechanics/dem, docs/dem.md)"): each bed joint
// carries the weight above it, so with a linear joint (Coulomb, k_n) the
// top block settles by rho g / k_n sum_k (H - y_k), and with Bandis's
// hyperbola by sum_k dV(sigma_k), dV = sigma V_m / (k_ni V_m + sigma); each
// block's average stress (the Love-Weber sum of its contact forces) is
// -rho g (H - y_c) at its centre. The update is solved to an unbalanced-force
// ratio of 1e-10 (dem.solve_ratio), so the settlement's error is that
// ratio's share of the joint forces: far below the tolerance of 1e-7. The
// stresses' tolerance is the contact points' offset: each lies midway in
// its joint's overlap, so its arm about the centre differs from h/2 by up
// to half the largest closure dV: relative 2 dV / h (2.5e-5 on the linear
// joints, 1.5e-4 on Bandis's).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "coupling/process_registry.h"
#include "rockmass/joints/barton_bandis.h"
#include "tests/support/run_scene.h"

namespace fissure::testing {
namespace {

constexpr double kDensity = 2500, kG = 9.81, kHeight = 0.5;
constexpr int kBlocks = 5;

/// A column of kBlocks 1 x 0.5 m blocks on a fixed base, on `joint`.
std::string column_scene(const std::string& joint) {
  std::string s =
      "physics: [dem]\ngravity: [0, -9.81]\nmaterials:\n"
      "  - {name: rock, density: 2500, young_modulus: 50 GPa, poisson_ratio: 0.25}\n"
      "joints:\n  - {name: bed, " +
      joint +
      "}\nblocks:\n"
      "  - {name: base, vertices: [[-1, -1], [2, -1], [2, 0], [-1, 0]], fixed: true}\n";
  for (int k = 0; k < kBlocks; ++k) {
    const double y0 = k * kHeight, y1 = y0 + kHeight;
    s += "  - {name: b" + std::to_string(k) + ", vertices: [[0, " + std::to_string(y0) + "], [1, " +
         std::to_string(y0) + "], [1, " + std::to_string(y1) + "], [0, " + std::to_string(y1) +
         "]]}\n";
  }
  s += "dem:\n  rounding: 5 mm\n  solve_ratio: 1e-10\n  max_cycles: 200000\n"
       "time:\n  end: 1\n";
  return s;
}

/// The weight per unit area on bed joint k (the one below block k), Pa.
double overburden(int k) {
  return kDensity * kG * (kBlocks - k) * kHeight;
}

struct Column {
  double settlement;              ///< of the top block, m
  std::vector<double> stress_yy;  ///< per block, Pa
  long unsolved;
};

Column run_column(const std::string& joint, const std::string& name) {
  const RunResult r = run_scene(read_scene_text(column_scene(joint), name + ".yaml"), name);
  Column c;
  const Block& top = r.state.blocks[kBlocks];
  c.settlement = top.initial_vertices[0].y() - top.polygon.vertices[0].y();
  for (int k = 1; k <= kBlocks; ++k) c.stress_yy.push_back(r.state.blocks[k].stress.y());
  const nlohmann::json summary = nlohmann::json::parse(file_bytes(r.outdir + "/summary.json"));
  c.unsolved = summary["processes"]["dem"]["unsolved_updates"].get<long>();
  return c;
}

/// `closure`: the largest joint closure, m.
void expect_block_stresses(const Column& c, double closure) {
  for (int k = 0; k < kBlocks; ++k) {
    const double expected = -kDensity * kG * (kBlocks - k - 0.5) * kHeight;
    EXPECT_NEAR(c.stress_yy[k], expected, 2 * closure / kHeight * std::abs(expected))
        << "block " << k;
  }
}

TEST(DemColumn, OnLinearJointsTheTopSettlesByTheSumOfTheBedJointsClosures) {
  constexpr double kn = 10e9;
  const Column c = run_column(
      "friction_angle: 30, normal_stiffness: 10 GPa/m, "
      "shear_stiffness: 5 GPa/m",
      "dem_column_linear");
  double expected = 0;
  for (int k = 0; k < kBlocks; ++k) expected += overburden(k) / kn;
  EXPECT_EQ(c.unsolved, 0);
  EXPECT_NEAR(c.settlement, expected, 1e-7 * expected);
  expect_block_stresses(c, overburden(0) / kn);
}

TEST(DemColumn, OnBandisJointsTheTopSettlesByTheSumOfTheHyperbolasClosures) {
  // k_ni and V_m given: 1 GPa/m and 0.1 mm, so the joints stiffen by
  // (1 + sigma / (k_ni V_m))^2 = 1.2 under the base's 61 kPa.
  const joints::BandisClosure bandis{1e9, 1e-4};
  const Column c = run_column(
      "friction_angle: 25, model: barton_bandis, jrc: 10, jcs: 100 MPa, lab_length: 0.1 m, "
      "initial_aperture: 0.5 mm, initial_normal_stiffness: 1 GPa/m, max_closure: 0.1 mm",
      "dem_column_bandis");
  double expected = 0;
  for (int k = 0; k < kBlocks; ++k) expected += joints::bandis_closure(overburden(k), bandis);
  EXPECT_EQ(c.unsolved, 0);
  EXPECT_NEAR(c.settlement, expected, 1e-7 * expected);
  expect_block_stresses(c, joints::bandis_closure(overburden(0), bandis));
}

}  // namespace
}  // namespace fissure::testing
