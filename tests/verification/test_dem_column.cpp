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
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "coupling/process_registry.h"
#include "rockmass/joints/barton_bandis.h"
#include "tests/support/run_scene.h"

namespace fissure::testing {
namespace {

constexpr double kDensity = 2500, kG = 9.81, kHeight = 0.5;
constexpr int kBlocks = 5;

/// A column of kBlocks 1 x 0.5 m blocks on a fixed base, on `joint`; `dem`:
/// more keys of the dem section.
std::string column_scene(const std::string& joint,
                         const std::string& rock = "50 GPa, poisson_ratio: 0.25",
                         const std::string& dem = "") {
  std::string s =
      "physics: [dem]\ngravity: [0, -9.81]\nmaterials:\n"
      "  - {name: rock, density: 2500, young_modulus: " +
      rock +
      "}\n"
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
  // The top's middle (of a deformable block: its own shortening too; the
  // mean of its corners would add the top face's bending).
  s += "monitors:\n  - {name: top, point: [0.5, " + std::to_string(kBlocks * kHeight) +
       "], block: b" + std::to_string(kBlocks - 1) + "}\n";
  s += "dem:\n  rounding: 5 mm\n  solve_ratio: 1e-10\n  max_cycles: 200000\n" + dem +
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

Column run_column(const std::string& joint, const std::string& name,
                  const std::string& rock = "50 GPa, poisson_ratio: 0.25",
                  const std::string& dem = "") {
  const RunResult r =
      run_scene(read_scene_text(column_scene(joint, rock, dem), name + ".yaml"), name);
  Column c;
  const MaterialPoint& top = r.state.points[0];  // the monitor
  c.settlement = top.initial.y() - top.current.y();
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

/// A column of 1 m wide blocks of the given heights (m) on linear joints,
/// solved to 1e-10, with or without density scaling: the top's settlement
/// and the cycles taken.
std::pair<double, long> layered_column(const std::vector<double>& heights, bool scaled) {
  std::string s =
      "physics: [dem]\ngravity: [0, -9.81]\nmaterials:\n"
      "  - {name: rock, density: 2500, young_modulus: 50 GPa, poisson_ratio: 0.25}\n"
      "joints:\n  - {name: bed, friction_angle: 30, normal_stiffness: 10 GPa/m, "
      "shear_stiffness: 5 GPa/m}\nblocks:\n"
      "  - {name: base, vertices: [[-1, -1], [2, -1], [2, 0], [-1, 0]], fixed: true}\n";
  double y = 0;
  for (std::size_t k = 0; k < heights.size(); ++k) {
    const std::string y0 = std::to_string(y), y1 = std::to_string(y += heights[k]);
    s += "  - {name: b" + std::to_string(k) + ", vertices: [[0, " + y0 + "], [1, " + y0 +
         "], [1, " + y1 + "], [0, " + y1 + "]]}\n";
  }
  s += "monitors:\n  - {name: top, point: [0.5, " + std::to_string(y) + "], block: b" +
       std::to_string(heights.size() - 1) + "}\n";
  s += std::string("dem:\n  rounding: 5 mm\n  solve_ratio: 1e-10\n  max_cycles: 400000\n") +
       "  density_scaling: " + (scaled ? "true" : "false") + "\ntime:\n  end: 1\n";
  const std::string name = std::string("dem_layered_column_") + (scaled ? "scaled" : "plain");
  const RunResult r = run_scene(read_scene_text(s, name + ".yaml"), name);
  const nlohmann::json summary = nlohmann::json::parse(file_bytes(r.outdir + "/summary.json"));
  EXPECT_EQ(summary["processes"]["dem"]["unsolved_updates"].get<long>(), 0);
  return {r.state.points[0].initial.y() - r.state.points[0].current.y(),
          summary["processes"]["dem"]["cycles"].get<long>()};
}

TEST(DemColumn, DensityScalingReachesTheSameRestInFewerCycles) {
  // Thick beds (0.5 m) with thin ones (5 cm) between them: the thin blocks'
  // critical step is a tenth of the thick ones', and sets the step of every
  // cycle unscaled. Scaled, every block steps at the thick blocks' step;
  // the weights are unchanged, so the joints close as before: sum_k rho g
  // (H - y_k) / k_n, to the solve ratio's 1e-10 (the tolerance of the
  // unscaled column, 1e-7).
  const std::vector<double> heights = {0.5, 0.05, 0.5, 0.05, 0.5, 0.05, 0.5};
  double expected = 0, above = 0;
  for (auto h = heights.rbegin(); h != heights.rend(); ++h) expected += (above += *h);
  expected *= kDensity * kG / 10e9;
  const auto [plain, plain_cycles] = layered_column(heights, false);
  const auto [scaled, scaled_cycles] = layered_column(heights, true);
  std::printf(
      "layered column: settles %.9e m unscaled in %ld cycles, %.9e m with density scaling in "
      "%ld cycles (closed form %.9e m)\n",
      plain, plain_cycles, scaled, scaled_cycles, expected);
  EXPECT_NEAR(plain, expected, 1e-7 * expected);
  EXPECT_NEAR(scaled, expected, 1e-7 * expected);
  EXPECT_LT(2 * scaled_cycles, plain_cycles);
}

TEST(DemColumn, OfZonedBlocksTheTopSettlesByTheJointsClosuresAndTheBlocksShortening) {
  // Deformable blocks (E = 5 GPa, nu = 0: the column shortens as a bar,
  // rho g H^2 / (2E) = 1.53e-5 m at its top, beside the joints' 1.84e-5 m).
  // Constant-strain zones with their weight a third at each node are
  // exact at the nodes for a bar's linear stress, and each joint's contacts
  // share its length as the nodes share the zones' traction: what is left
  // is the discretization of the bar's quadratic displacement by linear
  // zones that are not aligned with it (the mesh is unstructured): second
  // order in the zone size h, measured 8.3e-4 of the settlement at h = 0.25
  // m and 7e-5 at 0.125 m (6e-7 at 0.0625 m). Bound: 1.5e-3 (h / 0.25 m)^2.
  constexpr double kn = 10e9, young = 5e9, height = kBlocks * kHeight;
  for (const double h : {0.25, 0.125}) {
    const std::string size = std::to_string(h);
    const Column c = run_column(
        "friction_angle: 30, normal_stiffness: 10 GPa/m, "
        "shear_stiffness: 5 GPa/m",
        "dem_column_zoned_" + size, "5 GPa, poisson_ratio: 0", "  zone_size: " + size + "\n");
    double expected = kDensity * kG * height * height / (2 * young);
    for (int k = 0; k < kBlocks; ++k) expected += overburden(k) / kn;
    std::printf("zoned column, zones of %.3f m: the top settles %.8e m against %.8e m (%.2e)\n", h,
                c.settlement, expected, std::abs(c.settlement / expected - 1));
    EXPECT_EQ(c.unsolved, 0);
    EXPECT_NEAR(c.settlement, expected, 1.5e-3 * std::pow(h / 0.25, 2) * expected) << size;
    // The zones' mean stress is the block's: the bar's linear stress at its centre.
    for (int k = 0; k < kBlocks; ++k) {
      const double stress = -kDensity * kG * (kBlocks - k - 0.5) * kHeight;
      EXPECT_NEAR(c.stress_yy[k], stress, 1e-6 * std::abs(stress)) << "block " << k;
    }
  }
}

}  // namespace
}  // namespace fissure::testing
