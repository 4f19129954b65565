// Divergence during a run (foundation issue, "Bad input"): a NaN in the state
// and a displacement ratio that no step cut can bring back below g2 stop the
// run with a diagnosis; the output written so far stays readable and
// summary.json says why. Also through the real command line (exit code 2).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "mechanics/dda/dda_settings.h"
#include "tests/support/dda_scenes.h"
#include "tests/support/run_scene.h"

namespace fissure::testing {
namespace {

namespace fs = std::filesystem;

int csv_rows(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  int rows = -1;  // header
  while (std::getline(in, line))
    if (!line.empty()) ++rows;
  return rows;
}

/// A single block on a floor; a point load ramps to an absurd force at t = 0.05 s.
Scene runaway_load_scene() {
  Scene s = base_scene();
  s.blocks.push_back(block("floor", rectangle(10, 1, 0, Vec2(-5, -1)), true));
  s.blocks.push_back(block("block", rectangle(1, 1)));
  s.monitors.push_back({"block", Vec2(0.5, 0.5), 1});
  PointLoad load;
  load.point = Vec2(0.5, 1.0);
  load.block = 1;
  load.force = Vec2(1e18, 0);
  load.history = {{0, 0}, {0.05, 0}, {0.06, 1}};
  s.point_loads.push_back(load);
  mechanics_controls(s).dda.max_time_step = 1e-3;
  s.time.end_time = 0.2;
  s.time.min_step = 1e-7;
  s.output.interval = 0.01;
  s.output.hdf5 = true;
  return s;
}

TEST(DdaDivergence, UnrecoverableDisplacementRatioStopsCleanly) {
  const RunResult r = run_scene(runaway_load_scene(), "dda_divergence_ratio");
  EXPECT_EQ(r.summary.status, "diverged");
  EXPECT_NE(r.summary.message.find("g2 w"), std::string::npos) << r.summary.message;
  EXPECT_NE(r.summary.message.find("time.min_step"), std::string::npos) << r.summary.message;
  // Stopped at the runaway, after the quiet part was written.
  EXPECT_GE(r.summary.simulated_time, 0.05 - 1e-12);
  EXPECT_LT(r.summary.simulated_time, 0.07);
  const fs::path dir = r.outdir;
  EXPECT_GE(csv_rows(dir / "monitors.csv"), 6);  // t = 0, 0.01, ..., 0.05 and the last state
  EXPECT_TRUE(fs::exists(dir / "results.h5"));
  std::ifstream summary(dir / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(summary);
  EXPECT_EQ(j["status"], "diverged");
  EXPECT_EQ(j["message"], r.summary.message);
  // The last state written is the last accepted one: finite.
  EXPECT_TRUE(std::isfinite(j["monitors"]["block"]["ux"].get<double>()));
}

TEST(DdaDivergence, NonFiniteStateStopsWithDiagnosis) {
  Scene s = runaway_load_scene();
  s.point_loads.clear();
  s.blocks[1].initial_velocity(0) = std::numeric_limits<double>::quiet_NaN();
  const RunResult r = run_scene(s, "dda_divergence_nan");
  EXPECT_EQ(r.summary.status, "diverged");
  EXPECT_NE(r.summary.message.find("non-finite"), std::string::npos) << r.summary.message;
  EXPECT_EQ(r.summary.steps, 0);
  const fs::path dir = r.outdir;
  EXPECT_EQ(csv_rows(dir / "monitors.csv"), 1);  // the initial frame
}

TEST(DdaDivergence, CommandLineReportsAndKeepsOutput) {
  const fs::path dir = scratch_dir("dda_divergence_cli");
  const fs::path scene = dir / "runaway.yaml";
  std::ofstream(scene) << R"(name: runaway
physics: [mechanics]
materials:
  - {name: rock, density: 2700, young_modulus: 10 GPa, poisson_ratio: 0.25}
joints:
  - {name: joint, friction_angle: 30}
blocks:
  - {name: floor, vertices: [[-5, -1], [5, -1], [5, 0], [-5, 0]], fixed: true}
  - {name: block, vertices: [[0, 0], [1, 0], [1, 1], [0, 1]]}
point_loads:
  - {point: [0.5, 1.0], block: block, force: [1e15, 0], history: [[0, 0], [0.05, 0], [0.06, 1]]}
monitors:
  - {name: block, point: [0.5, 0.5], block: block}
mechanics:
  dda: {time_step: 1 ms}
time: {end: 0.2, min_step: 1e-7}
output: {interval: 0.01}
)";
  const fs::path out = dir / "out";
  const std::string cmd = std::string(FISSURE_APP) + " run " + scene.string() + " -q -o " +
                          out.string() + " > " + (dir / "stdout.txt").string() + " 2>&1";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  std::ifstream log(dir / "stdout.txt");
  std::stringstream text;
  text << log.rdbuf();
  EXPECT_NE(text.str().find("diverged"), std::string::npos) << text.str();
  std::ifstream summary(out / "summary.json");
  EXPECT_EQ(nlohmann::json::parse(summary)["status"], "diverged");
  EXPECT_GE(csv_rows(out / "monitors.csv"), 6);
  EXPECT_TRUE(fs::exists(out / "results.xdmf"));
  // Nothing non-finite is written (issue 22, item 4).
  for (const char* file : {"monitors.csv", "summary.json"}) {
    std::ifstream in(out / file);
    std::stringstream content;
    content << in.rdbuf();
    for (const char* word : {"nan", "inf"})
      EXPECT_EQ(content.str().find(word), std::string::npos) << file << " holds " << word;
  }
}

}  // namespace
}  // namespace fissure::testing
