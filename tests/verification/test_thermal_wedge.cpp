// The thermally ratcheting wedge (configs/thermal_wedge.yaml; Bakun-Mazor,
// Hatzor, Glaser and Santamarina 2013, Int. J. Rock Mech. Min. Sci. 61,
// 196-211): a block held by
// friction on a 25 degree plane (friction 35 degrees), a wedge in the tension
// crack behind it, daily air temperature cycles, static DDA in steps of an
// hour, thermal steps of an hour, through the real coordinator.
//
// The seed's estimate of one cycle's permanent slip is the wedge's thermal
// expansion across the crack less the elastic give of rock and contacts,
// delta_p = delta_T - delta_sigma - delta_j*. Here delta_T = (1 + nu)
// alpha_T dT w (plane strain; w = 0.149 m, the wedge's mean width; dT its
// temperature swing in the cycle, from the monitor at its centroid), along
// the plane delta_T / cos 25. delta_sigma and delta_j* are below 0.1 um (the
// block's resistance, a few kN/m, against E = 43 GPa and a penalty of 1e11
// N/m), 1 % of delta_T: the estimate is delta_T. It is first order only: the
// wedge is 0.118 m wide at its bottom and 0.180 m at its top (+-20 % about
// w), the contact forces that push the block are not at mid-height, and the
// wedge's mean temperature swings by up to 15 % more than its centroid's
// (the wedge is about one daily skin depth, 0.15 m, wide). So the slip per
// cycle must be within a factor 1.5 of the estimate (measured: 0.96).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "coupling/process_registry.h"
#include "tests/support/results_file_reader.h"
#include "tests/support/run_scene.h"

namespace fissure::testing {
namespace {

constexpr double kDay = 86400;
constexpr double kSlope = 25 * std::numbers::pi / 180;
constexpr double kNu = 0.184, kAlpha = 1e-5, kWedgeMeanWidth = 0.149;
// The block's weight over the contact penalty: 0.645 m^2 x 2700 kg/m^3 x g /
// 1e11 N/m = 0.17 um, the elastic settling on the plane.
constexpr double kElasticSettling = 0.645 * 2700 * 9.81 / 1e11;

std::string config_text() {
  return test::read_text(std::string(FISSURE_SOURCE_DIR "/configs/thermal_wedge.yaml"));
}

/// `text` with `from` replaced once (a failure when it is not there).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "configs/thermal_wedge.yaml lacks: " << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// The scene over `days` days, without results.h5 (monitors.csv is enough).
Scene wedge_scene(std::string text, int days) {
  text = replaced(text, "end: 6 d", "end: " + std::to_string(days) + " d");
  text = replaced(text, "  interval: 1 h", "  interval: 1 h\n  hdf5: false");
  return read_scene_text(text, "thermal_wedge.yaml");
}

/// The variant in which only the wedge expands: the rock and the sliding
/// block of a second material with the same properties but alpha_T = 0.
std::string wedge_only(std::string text) {
  const std::string dolomite = "young_modulus: 43 GPa, poisson_ratio: 0.184}\n";
  text = replaced(text, dolomite, dolomite + "  - {name: inert, density: 2700, " + dolomite);
  text = replaced(text, "  - name: rock\n", "  - name: rock\n    material: inert\n");
  text = replaced(text, "  - name: block\n", "  - name: block\n    material: inert\n");
  text = replaced(text, "  - name: wedge\n", "  - name: wedge\n    material: dolomite\n");
  const std::string expanding = "thermal_expansion: 1e-5}\n";
  return replaced(
      text, expanding,
      expanding + "    - {name: inert, conductivity: 2.5 W/m/K, heat_capacity: 2.4 MJ/m^3/K}\n");
}

struct Cycle {
  double slip;      ///< permanent downslope slip of the block over the day (m)
  double estimate;  ///< (1 + nu) alpha_T dT w / cos 25 (m)
};

struct WedgeRun {
  std::vector<double> slip;  ///< downslope displacement of the block, per frame (m)
  std::vector<Cycle> cycles;
  long solver_cuts = 0;  ///< DDA steps cut for a failed linear solve
};

WedgeRun run_wedge(const Scene& scene, const std::string& name) {
  const RunResult r = run_scene(scene, name);
  EXPECT_EQ(r.summary.status, "completed") << r.summary.message;
  WedgeRun run;
  run.solver_cuts =
      r.summary.processes.at("mechanics").at("time_step_cuts").value("linear_solver", -1L);
  auto m = test::monitor_columns(r.outdir);
  const std::vector<double>& t = m["t"];
  for (std::size_t i = 0; i < t.size(); ++i)
    run.slip.push_back(m["block.ux"][i] * std::cos(kSlope) - m["block.uy"][i] * std::sin(kSlope));
  // Frames every hour: the full days end at rows 24, 48, ...
  for (std::size_t end = 24; end < t.size(); end += 24) {
    EXPECT_NEAR(t[end], static_cast<double>(end / 24) * kDay, 1e-6);
    const auto first = m["wedge.T"].begin() + static_cast<long>(end - 24);
    const auto last = m["wedge.T"].begin() + static_cast<long>(end) + 1;
    const double swing = *std::max_element(first, last) - *std::min_element(first, last);
    run.cycles.push_back({run.slip[end] - run.slip[end - 24],
                          (1 + kNu) * kAlpha * swing * kWedgeMeanWidth / std::cos(kSlope)});
  }
  return run;
}

TEST(thermal_wedge, WithoutThermalExpansionTheBlockOnlySettlesElastically) {
  const std::string text =
      replaced(config_text(), "thermal_expansion: 1e-5", "thermal_expansion: 0");
  const WedgeRun run = run_wedge(wedge_scene(text, 2), "thermal_wedge_no_expansion");
  ASSERT_EQ(run.slip.size(), 49u);
  for (double s : run.slip) EXPECT_LE(std::abs(s), 3 * kElasticSettling);
}

TEST(thermal_wedge, OnlyTheWedgeExpandingRatchetsByTheSeedsEstimate) {
  const WedgeRun run = run_wedge(wedge_scene(wedge_only(config_text()), 3), "thermal_wedge_only");
  ASSERT_EQ(run.cycles.size(), 3u);
  for (const Cycle& c : run.cycles) {
    EXPECT_GT(c.slip, 0);
    EXPECT_LE(c.slip, 1.5 * c.estimate);
    EXPECT_GE(c.slip, c.estimate / 1.5);
  }
  // A ratchet: the slip never goes back up the plane by more than the
  // elastic give within a day.
  for (std::size_t i = 1; i < run.slip.size(); ++i)
    EXPECT_GE(run.slip[i], run.slip[i - 1] - kElasticSettling);
}

TEST(thermal_wedge, TheSceneRatchetsEveryCycleBeyondTheWedgesExpansion) {
  // Every block expanding: the wedge also locks in the block's own thermal
  // contraction (its back face moves down the plane as it cools), so each
  // cycle slips more than the wedge's expansion alone, and by the same
  // amount each day once the first day's start from 25 degC is over.
  const WedgeRun run = run_wedge(wedge_scene(config_text(), 3), "thermal_wedge_scene");
  ASSERT_EQ(run.cycles.size(), 3u);
  // The cooling wedge loses all its contacts in some long static steps: the
  // DDA cuts them (docs/dda.md section 1; before, this run failed at 6 h
  // with "UMFPACK: the block system matrix is singular"). 1 such cut here.
  EXPECT_GE(run.solver_cuts, 0);
  for (const Cycle& c : run.cycles) EXPECT_GT(c.slip, c.estimate);
  EXPECT_NEAR(run.cycles[2].slip, run.cycles[1].slip, 0.05 * run.cycles[1].slip);
}

}  // namespace
}  // namespace fissure::testing
