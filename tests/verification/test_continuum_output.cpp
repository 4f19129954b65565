// The continuum's output (docs/continuum.md 5, docs/output.md): its grid in
// results.h5 and results.xdmf (what ParaView reads) with the named stress
// components, the excess pressure and temperature change and the unit of
// every field, the markers of its sources, its monitors and its statistics
// in summary.json: on Terzaghi's column after 5 steps, on the axisymmetric
// heater ring and on the heated repository after one step.
#include <gtest/gtest.h>

#include <cmath>

#include "continuum/poroelasticity/continuum_settings.h"
#include "coupling/process_registry.h"
#include "tests/support/results_file_reader.h"
#include "tests/support/run_scene.h"

namespace fissure {
namespace {

// One step of a shipped continuum scene, written under NAME.
testing::RunResult run_first_step(const char* config, const char* name) {
  Scene scene = read_scene(std::string(FISSURE_SOURCE_DIR "/configs/") + config);
  scene.time.max_steps = 1;
  return testing::run_scene(scene, name);
}

// The step before each output frame is shorter than the scene's dt by the
// round-off of the times summed into it (1.5e-12 of dt here): it keeps the
// factor and is taken with the factor's dt (core/base/same_step.h). Mandel's
// whole run, 1,400 steps with a frame every 70, factorizes for the undrained
// start and for its one step size: twice (41 times when dt was compared with
// ==); its pressures are those of the run without frames to 1e-9 p0 (a
// step 1e-9 longer is 1e-9 of a step's change; measured 0).
TEST(ContinuumOutput, StepsBeforeOutputFramesKeepTheFactor) {
  Scene scene = read_scene(std::string(FISSURE_SOURCE_DIR "/configs/continuum_mandel.yaml"));
  scene.output.hdf5 = false;
  const testing::RunResult framed = testing::run_scene(scene, "continuum_frames");
  EXPECT_EQ(framed.summary.output_frames, 21);
  EXPECT_EQ(framed.summary.processes["continuum"]["factorizations"], 2);
  scene.output.interval = 0;
  const testing::RunResult plain = testing::run_scene(scene, "continuum_no_frames");
  EXPECT_EQ(plain.summary.processes["continuum"]["factorizations"], 2);
  ASSERT_EQ(framed.summary.steps, plain.summary.steps);
  const double p0 = 1e6 / 2.7;  // the undrained pressure, ~0.371 MPa
  for (const char* monitor : {"centre", "half"}) {
    const double a = framed.summary.monitors[monitor]["p"].get<double>();
    const double b = plain.summary.monitors[monitor]["p"].get<double>();
    EXPECT_NEAR(a, b, 1e-9 * p0) << monitor;
  }
}

// The steps' saddle point after the undrained start is analysed in the
// start's METIS order carried to its unknowns (the drained side's pressures
// left out; continuum_linear_solver.cpp), sparing a second METIS run: its
// factor is as small as that of the same system ordered afresh (a run
// without the undrained start). A wrong carry, or UMFPACK's automatic
// strategy with a given order, made it ten times larger.
TEST(ContinuumOutput, TheStepsReuseTheUndrainedStartsOrder) {
  auto steps_factor = [](bool undrained_start, const char* name) {
    Scene scene = read_scene(std::string(FISSURE_SOURCE_DIR "/configs/continuum_mandel.yaml"));
    ContinuumControls& c = continuum_controls(scene);
    c.scheme = ContinuumControls::Scheme::Monolithic;
    c.divisions = {32, 32};
    c.undrained_start = undrained_start;
    scene.time.max_steps = 1;
    scene.output.hdf5 = false;
    const testing::RunResult run = testing::run_scene(scene, name);
    return run.summary.processes["continuum"]["factors"]["monolithic"]["entries"].get<double>();
  };
  const double carried = steps_factor(true, "continuum_carried_order");
  const double fresh = steps_factor(false, "continuum_fresh_order");
  EXPECT_NEAR(carried / fresh, 1, 0.03) << carried << " " << fresh;
}

TEST(ContinuumOutput, TheColumnWritesItsGridMonitorsAndStatistics) {
  Scene scene = read_scene(std::string(FISSURE_SOURCE_DIR "/configs/continuum_terzaghi.yaml"));
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
  for (const char* s : {"sxx", "syy", "sxy", "szz"})
    EXPECT_EQ(h5.shape(std::string("/frames/000005/continuum/") + s), (std::vector<hsize_t>{80}))
        << s;
  EXPECT_FALSE(h5.exists("/frames/000005/continuum/stress"));  // the components instead
  // Without heat: no temperature change.
  EXPECT_FALSE(h5.exists("/frames/000005/continuum/temperature_change"));
  // The drained top is at 0, the column's base near p0 after 500 s.
  const std::vector<double> p = h5.doubles("/frames/000005/continuum/pressure");
  double lowest = p[0], highest = p[0];
  for (double v : p) lowest = std::min(lowest, v), highest = std::max(highest, v);
  EXPECT_EQ(lowest, 0);
  EXPECT_NEAR(highest, 892857, 0.01 * 892857);
  // The column starts at p = 0: its excess pressure is its pressure.
  EXPECT_EQ(h5.doubles("/frames/000005/continuum/excess_pressure"), p);

  const std::string xml = test::read_text(dir / "results.xdmf");
  EXPECT_TRUE(test::xml_tags_balanced(xml));
  EXPECT_NE(xml.find("Name=\"continuum\""), std::string::npos);
  test::expect_xdmf_refs_match(xml, h5);
  // Every attribute carries its unit; the time is in s, the scene's unit noted.
  EXPECT_EQ(test::count_occurrences(xml, "<Attribute "),
            test::count_occurrences(xml, "<Information Name=\"unit\""));
  EXPECT_NE(xml.find("<Attribute Name=\"excess_pressure\" AttributeType=\"Scalar\" "
                     "Center=\"Node\">\n            <Information Name=\"unit\" Value=\"Pa\"/>"),
            std::string::npos);
  EXPECT_NE(xml.find("<Attribute Name=\"szz\" AttributeType=\"Scalar\" Center=\"Cell\">\n"
                     "            <Information Name=\"unit\" Value=\"Pa\"/>"),
            std::string::npos);
  EXPECT_NE(xml.find("<Information Name=\"time_unit\" Value=\"s\"/>"), std::string::npos);
  EXPECT_NE(xml.find("<Information Name=\"scene_time_unit\" Value=\"s\"/>"), std::string::npos);
  EXPECT_NE(xml.find("Value=\"plane strain: szz is the out-of-plane stress\""), std::string::npos);
  // The monitors' places, for the pictures.
  EXPECT_EQ(h5.strings("/mesh/markers/monitors/names"),
            (std::vector<std::string>{"base", "middle", "top"}));
  EXPECT_EQ(h5.doubles("/mesh/markers/monitors/points"),
            (std::vector<double>{0.5, 0, 0.5, 5, 0.5, 10}));

  const std::vector<std::string> rows = test::text_lines(dir / "monitors.csv");
  ASSERT_EQ(rows.size(), 7u);  // header, t = 0 and 5 steps
  EXPECT_NE(rows[0].find("base.p"), std::string::npos);
  EXPECT_NE(rows[0].find("middle.szz"), std::string::npos);

  const nlohmann::json summary =
      nlohmann::json::parse(test::read_text(dir / "summary.json"))["processes"]["continuum"];
  EXPECT_EQ(summary["steps"], 5);
  EXPECT_EQ(summary["mesh"]["triangles"], 80);
  EXPECT_EQ(summary["scheme"], "fixed_stress");
  EXPECT_EQ(summary["geometry"], "plane_strain");
  EXPECT_GE(summary["splitting_passes"].get<long>(), 5);
  // The factors' sizes: CHOLMOD's of the staggered systems, UMFPACK's of
  // the monolithic undrained start; an LU of the 1 x 40 column's systems
  // has more entries than the system's 82 x 2 + 41 unknowns.
  for (const char* system : {"mechanics", "flow", "monolithic"}) {
    ASSERT_TRUE(summary["factors"].contains(system)) << system;
    EXPECT_GT(summary["factors"][system]["entries"].get<double>(), 82) << system;
    EXPECT_GT(summary["factors"][system]["flops"].get<double>(),
              summary["factors"][system]["entries"].get<double>())
        << system;
  }
}

// The axisymmetric ring: x is the radius, y the axis; its stresses are
// written as srr, szz, srz and the hoop stress shoop; with heat the
// temperature change from the initial 12 degC.
TEST(ContinuumOutput, TheAxisymmetricRingNamesItsStressesInRAndZWithTheHoopStress) {
  const testing::RunResult run = run_first_step("continuum_heater.yaml", "continuum_output_ring");
  ASSERT_EQ(run.summary.status, "max_steps") << run.summary.message;
  const test::H5Reader h5(std::filesystem::path(run.outdir) / "results.h5");
  const std::string at = "/frames/000001/continuum/";
  for (const char* s : {"srr", "szz", "srz", "shoop"}) EXPECT_TRUE(h5.exists(at + s)) << s;
  for (const char* s : {"sxx", "syy", "sxy"}) EXPECT_FALSE(h5.exists(at + s)) << s;
  const std::vector<double> t = h5.doubles(at + "temperature"),
                            change = h5.doubles(at + "temperature_change");
  ASSERT_EQ(t.size(), change.size());
  for (std::size_t v = 0; v < t.size(); ++v) EXPECT_EQ(change[v], t[v] - 12) << v;
  const std::string xml = test::read_text(std::filesystem::path(run.outdir) / "results.xdmf");
  EXPECT_NE(xml.find("<Attribute Name=\"shoop\""), std::string::npos);
  EXPECT_NE(xml.find("<Attribute Name=\"temperature_change\" AttributeType=\"Scalar\" "
                     "Center=\"Node\">\n            <Information Name=\"unit\" Value=\"K\"/>"),
            std::string::npos);
  EXPECT_NE(xml.find("axisymmetric: x is the radius r, y the axis z"), std::string::npos);
  // time.end is 1 yr: the scene's unit.
  EXPECT_NE(xml.find("<Information Name=\"scene_time_unit\" Value=\"yr\"/>"), std::string::npos);
  EXPECT_EQ(run.summary.processes["continuum"]["geometry"], "axisymmetric");
}

// The repository starts hydrostatic (p0 = -9810 Pa/m x y): its excess
// pressure is p - p0(y) at every vertex, and its nine heat sources are
// marked.
TEST(ContinuumOutput, TheRepositoryWritesItsExcessPressureAndMarksItsSources) {
  const testing::RunResult run =
      run_first_step("continuum_repository.yaml", "continuum_output_repository");
  ASSERT_EQ(run.summary.status, "max_steps") << run.summary.message;
  const test::H5Reader h5(std::filesystem::path(run.outdir) / "results.h5");
  const std::vector<double> xy = h5.doubles("/mesh/continuum_vertices"),
                            p = h5.doubles("/frames/000001/continuum/pressure"),
                            excess = h5.doubles("/frames/000001/continuum/excess_pressure");
  ASSERT_EQ(2 * p.size(), xy.size());
  double largest = 0;
  for (std::size_t v = 0; v < p.size(); ++v) {
    EXPECT_NEAR(excess[v], p[v] - (-9810 * xy[2 * v + 1]), 1e-9 * std::abs(p[v]) + 1e-9) << v;
    largest = std::max(largest, std::abs(excess[v]));
  }
  EXPECT_GT(largest, 1e3);  // the heated water's rise over hydrostatic
  const std::vector<std::string> sources = h5.strings("/mesh/markers/continuum_heat_sources/names");
  ASSERT_EQ(sources.size(), 9u);
  EXPECT_EQ(sources[0], "drift0");
  const std::vector<double> points = h5.doubles("/mesh/markers/continuum_heat_sources/points");
  EXPECT_EQ(points[0], 900);
  EXPECT_EQ(points[1], -500);
  EXPECT_FALSE(h5.exists("/mesh/markers/continuum_wells"));  // no fluid source
}

}  // namespace
}  // namespace fissure
