// The continuum's output (docs/continuum.md 5): its grid in results.h5 and
// results.xdmf (what ParaView reads), its monitors and its statistics in
// summary.json, on Terzaghi's column after 5 steps.
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/process_registry.h"
#include "tests/support/results_file_reader.h"
#include "tests/support/run_scene.h"

namespace fissure {
namespace {

TEST(ContinuumOutput, TheColumnWritesItsGridMonitorsAndStatistics) {
  Scene scene = read_scene(std::string(FISSURE_SOURCE_DIR) + "/configs/continuum_terzaghi.yaml");
  scene.time.max_steps = 5;
  scene.output.every_steps = 1;
  scene.output.interval = 0;
  const testing::RunResult run = testing::run_scene(scene, "continuum_output");
  const std::filesystem::path dir = run.outdir;

  const test::H5Reader h5(dir / "results.h5");
  // 1 x 40 cells: 82 vertices, 80 triangles.
  EXPECT_EQ(h5.shape("/mesh/continuum_vertices"), (std::vector<hsize_t>{82, 2}));
  EXPECT_EQ(h5.shape("/mesh/continuum_triangles"), (std::vector<hsize_t>{80, 3}));
  EXPECT_TRUE(h5.exists("/frames/000005/continuum/pressure"));
  EXPECT_EQ(h5.shape("/frames/000005/continuum/displacement"), (std::vector<hsize_t>{82, 3}));
  EXPECT_EQ(h5.shape("/frames/000005/continuum/stress"), (std::vector<hsize_t>{80, 3}));
  // The drained top is at 0, the column's base near p0 after 500 s.
  const std::vector<double> p = h5.doubles("/frames/000005/continuum/pressure");
  double lowest = p[0], highest = p[0];
  for (double v : p) lowest = std::min(lowest, v), highest = std::max(highest, v);
  EXPECT_EQ(lowest, 0);
  EXPECT_NEAR(highest, 892857, 0.01 * 892857);

  const std::string xml = test::read_text(dir / "results.xdmf");
  EXPECT_TRUE(test::xml_tags_balanced(xml));
  EXPECT_NE(xml.find("Name=\"continuum\""), std::string::npos);
  test::expect_xdmf_refs_match(xml, h5);

  const std::vector<std::string> rows = test::text_lines(dir / "monitors.csv");
  ASSERT_EQ(rows.size(), 7u);  // header, t = 0 and 5 steps
  EXPECT_NE(rows[0].find("base.p"), std::string::npos);
  EXPECT_NE(rows[0].find("middle.szz"), std::string::npos);

  const nlohmann::json summary =
      nlohmann::json::parse(test::read_text(dir / "summary.json"))["processes"]["continuum"];
  EXPECT_EQ(summary["steps"], 5);
  EXPECT_EQ(summary["mesh"]["triangles"], 80);
  EXPECT_EQ(summary["scheme"], "fixed_stress");
  EXPECT_GE(summary["splitting_passes"].get<long>(), 5);
}

}  // namespace
}  // namespace fissure
