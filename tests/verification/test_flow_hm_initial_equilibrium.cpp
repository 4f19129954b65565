// The initial stage (coupling.initial_equilibrium, issue 22 item 2): the
// blocks are brought to rest by the mechanics alone, the displacements are
// reset, and the coupled run starts from that state (docs/flow.md 7 and 13,
// docs/scene-reference.md 8).
//
// 1. HM: configs/flow_hm_injection_transient.yaml (80 blocks cut stress-free
//    from a 10 m x 10 m rock mass, hydrostatic water, a well ramped to
//    5e-6 m^2/s; transient flow, backward Euler) for its first 0.05 s.
//    What is physically possible there: the pressure cannot fall below
//    absolute vacuum, -1e5 Pa gauge (the scene's pressures are gauge: 0 at
//    the water table), and cannot rise above the largest total stress in the
//    model, the overburden at its base, rho_r g H = 2650 x 9.81 x 10 =
//    2.6e5 Pa: there the fluid carries the whole rock column, the joints
//    open (up to e_max = 1 mm, where the well's 5e-6 m^2/s needs a gradient
//    of 12 mu q / e^3 = 60 Pa/m) and the water leaves instead of building up
//    pressure. With the stage every pressure the flow commits
//    (summary.json processes.flow.pressure.run) stays within these bounds
//    (measured: -1.4e4 to 9.81e4 Pa, the hydrostatic pressure at the base).
//    Without it (the contrast, checked below): the stress-free blocks settle
//    in the first steps, their joints close by sigma_n'/k_n (a few um of
//    50 um), and the trapped water takes that load: 1.04 MPa, four times the
//    overburden. (Before the fixed-stress storage of the transient coupling,
//    docs/flow.md 7, both runs reached 3.6 GPa and diverged: the water's
//    stiffness K_f/e = 4.4e13 Pa/m is 2200 times the joints' k_n, and the
//    lagged loop pressure -> opening -> pressure had that gain.)
// 2. The stage ends by its criterion: after the first step at whose end no
//    block vertex moves faster than max_speed; a smaller max_speed takes
//    more steps, a max_time too short for it ends the run as diverged with
//    the speed reached; time.max_steps stops it (status max_steps). A brick
//    column settles on a fixed base; after the stage the monitors start at
//    zero displacement at the settled position, and stay there (the run
//    starts at rest), whereas without the stage the same run shows the
//    settlement.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "coupling/process_registry.h"
#include "tests/support/results_file_reader.h"
#include "tests/support/run_scene.h"

namespace fissure::testing {
namespace {

constexpr double kVacuum = -1.01325e5;              // Pa gauge: absolute zero
constexpr double kOverburden = 2650 * 9.81 * 10.0;  // Pa: rho_r g H at the base

Scene hm_scene(bool with_stage) {
  Scene scene =
      read_scene(std::string(FISSURE_SOURCE_DIR "/configs/flow_hm_injection_transient.yaml"));
  EXPECT_TRUE(scene.coupling.initial_equilibrium.has_value());
  if (!with_stage) scene.coupling.initial_equilibrium.reset();
  scene.time.end_time = 0.05;
  scene.output.hdf5 = false;
  return scene;
}

TEST(flow_hm_initial_equilibrium, PressuresStayPhysicallyPossibleFromTheSettledState) {
  const RunResult r = run_scene(hm_scene(true), "hm_initial_equilibrium");
  ASSERT_EQ(r.summary.status, "completed") << r.summary.message;
  const nlohmann::json& stage = r.summary.processes["coordinator"]["initial_equilibrium"];
  EXPECT_LE(stage["fastest_point"].get<double>(), 1e-5);
  const nlohmann::json& run = r.summary.processes["flow"]["pressure"]["run"];
  const double lowest = run["min"].get<double>(), highest = run["max"].get<double>();
  EXPECT_GE(lowest, kVacuum);
  EXPECT_LE(highest, kOverburden);
  // The hydrostatic pressure at the base (9.81e4 Pa) is reached: the bound
  // is not met by a flow that never started.
  EXPECT_GT(highest, 9e4);
}

TEST(flow_hm_initial_equilibrium, WithoutTheStageTheSettlingSqueezesTheWaterBeyondThePossible) {
  const RunResult r = run_scene(hm_scene(false), "hm_without_initial_equilibrium");
  ASSERT_EQ(r.summary.status, "completed") << r.summary.message;
  const nlohmann::json& run = r.summary.processes["flow"]["pressure"]["run"];
  EXPECT_GT(run["max"].get<double>(), 2 * kOverburden);
}

/// A column of three 1 m x 0.5 m bricks on a fixed base, quasi-static, with
/// a monitor on the top brick.
Scene brick_column(const std::string& stage) {
  return read_scene_text(R"(name: brick_column
physics: [mechanics]
gravity: [0, -9.81]
materials:
  - {name: rock, density: 2650 kg/m^3, young_modulus: 10 GPa, poisson_ratio: 0.25}
joints:
  - {name: joint, friction_angle: 30}
blocks:
  - {name: base, vertices: [[-1, -1], [2, -1], [2, 0], [-1, 0]], fixed: true}
  - {name: b1, vertices: [[0, 0], [1, 0], [1, 0.5], [0, 0.5]]}
  - {name: b2, vertices: [[0, 0.5], [1, 0.5], [1, 1], [0, 1]]}
  - {name: b3, vertices: [[0, 1], [1, 1], [1, 1.5], [0, 1.5]]}
monitors:
  - {name: top, point: [0.5, 1.25]}
mechanics:
  dda: {time_step: 1 ms, velocity_carry_over: 0}
time:
  end: 20 ms
output:
  every_steps: 1
  hdf5: false
)" + stage,
                         "brick_column.yaml");
}

struct MonitorRow {
  double y, uy;
};

/// The monitor `top` in row `row` of monitors.csv (0: the first frame).
MonitorRow top_monitor(const std::string& outdir, std::size_t row) {
  const std::vector<std::string> lines = test::text_lines(outdir + "/monitors.csv");
  EXPECT_GT(lines.size(), row + 1);
  if (lines.size() <= row + 1) return {};
  std::vector<std::string> header;
  std::stringstream names(lines[0]);
  for (std::string name; std::getline(names, name, ',');) header.push_back(name);
  const std::vector<double> values = test::csv_numbers(lines[row + 1]);
  MonitorRow m{NAN, NAN};
  for (std::size_t c = 0; c < header.size() && c < values.size(); ++c) {
    if (header[c] == "top.y") m.y = values[c];
    if (header[c] == "top.uy") m.uy = values[c];
  }
  return m;
}

TEST(flow_hm_initial_equilibrium, TheStageEndsByItsCriterionAndResetsTheDisplacements) {
  const RunResult free = run_scene(brick_column(""), "column_without_stage");
  ASSERT_EQ(free.summary.status, "completed") << free.summary.message;
  const double settlement = -top_monitor(free.outdir, 20).uy;
  EXPECT_GT(settlement, 0);

  const RunResult r = run_scene(
      brick_column("coupling: {initial_equilibrium: {max_speed: 1e-6 m/s, max_time: 1 s}}\n"),
      "column_with_stage");
  ASSERT_EQ(r.summary.status, "completed") << r.summary.message;
  const nlohmann::json& stage = r.summary.processes["coordinator"]["initial_equilibrium"];
  EXPECT_EQ(stage["processes"], nlohmann::json::array({"mechanics"}));
  EXPECT_LE(stage["fastest_point"].get<double>(), 1e-6);
  const long steps = stage["steps"].get<long>();
  EXPECT_GE(steps, 2);
  EXPECT_NEAR(stage["simulated_time"].get<double>(), 1e-3 * steps, 1e-12);
  // The first frame is the settled state at t = 0, with zero displacement:
  // the settlement is there already, and the blocks stay at rest.
  const MonitorRow start = top_monitor(r.outdir, 0), end = top_monitor(r.outdir, 20);
  EXPECT_EQ(start.uy, 0.0);
  EXPECT_NEAR(1.25 - start.y, settlement, 0.01 * settlement);
  EXPECT_LT(std::abs(end.uy), 0.01 * settlement);

  // A stricter criterion takes more steps.
  const RunResult strict = run_scene(
      brick_column("coupling: {initial_equilibrium: {max_speed: 1e-8 m/s, max_time: 1 s}}\n"),
      "column_with_strict_stage");
  ASSERT_EQ(strict.summary.status, "completed") << strict.summary.message;
  const nlohmann::json& strict_stage =
      strict.summary.processes["coordinator"]["initial_equilibrium"];
  EXPECT_GT(strict_stage["steps"].get<long>(), steps);
  EXPECT_LE(strict_stage["fastest_point"].get<double>(), 1e-8);

  // Not at rest within max_time: diverged, with the speed reached.
  const RunResult short_stage = run_scene(
      brick_column("coupling: {initial_equilibrium: {max_speed: 1e-6 m/s, max_time: 1 ms}}\n"),
      "column_with_short_stage");
  EXPECT_EQ(short_stage.summary.status, "diverged");
  EXPECT_NE(short_stage.summary.message.find("initial equilibrium not reached"), std::string::npos)
      << short_stage.summary.message;
  EXPECT_GT(short_stage.summary.processes["coordinator"]["initial_equilibrium"]["fastest_point"]
                .get<double>(),
            1e-6);

  // time.max_steps bounds the stage too: the run stops there, no step taken.
  Scene capped =
      brick_column("coupling: {initial_equilibrium: {max_speed: 1e-6 m/s, max_time: 1 s}}\n");
  capped.time.max_steps = 3;
  const RunResult stopped = run_scene(capped, "column_with_capped_stage");
  EXPECT_EQ(stopped.summary.status, "max_steps");
  EXPECT_NE(stopped.summary.message.find("initial stage"), std::string::npos)
      << stopped.summary.message;
  EXPECT_EQ(stopped.summary.steps, 0);
  EXPECT_EQ(stopped.summary.processes["coordinator"]["initial_equilibrium"]["steps"], 3);
}

}  // namespace
}  // namespace fissure::testing
