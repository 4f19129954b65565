// The flow state in the output folder (docs/output.md, docs/flow.md "Output"):
// a steady single-fracture flow scene whose results.h5 holds the closed-form
// pressures and heads, whose results.xdmf refers to datasets that exist, and
// whose monitors.csv and summary.json give m.p by linear interpolation along
// the fracture; and a coupled HM run that writes blocks and fractures in every
// frame.
//
// Closed form: one horizontal fracture y = 0.3 across a 1 m box, pressures
// P1 on the left and 0 on the right, uniform aperture: the pressure is linear,
// p = P1 (1 - x) + rho g (0.3 - 0.3), and the head h = p* / (rho g) with p* =
// p + rho g y linear too; three dead-end branches hanging from it carry no
// flow, so their p* is that of their junction (hydrostatic p). The steady
// solve is direct (CHOLMOD): the tolerance 1e-9 x P1 is round-off with room
// to spare (verification.md (f) finds 1e-10 relative for the same chain).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>

#include "coupling/coordinator.h"
#include "rockmass/fields/fracture_flow.h"
#include "tests/support/flow_networks.h"
#include "tests/support/results_file_reader.h"
#include "tests/support/run_scene.h"

namespace fs = std::filesystem;

namespace fissure::testing {
namespace {

constexpr double kP1 = 1e5, kRho = 1000, kG = 9.81, kY = 0.3;

struct Output {
  RunSummary summary;
  RockMass state;
  fs::path dir;
};

Output run(const Scene& scene, const std::string& name) {
  RunOptions options;
  options.outdir = scratch_dir(name);
  options.quiet = true;
  Coordinator coordinator(scene, options);
  Output out{coordinator.run(), {}, options.outdir};
  out.state = coordinator.state();
  return out;
}

std::vector<std::vector<std::string>> csv(const fs::path& file) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(test::read_text(file));
  for (std::string line; std::getline(in, line);) {
    rows.emplace_back();
    // Every cell, also an empty last one (a missing value).
    for (std::size_t start = 0;;) {
      const std::size_t comma = line.find(',', start);
      rows.back().push_back(line.substr(start, comma == std::string::npos ? comma : comma - start));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  }
  return rows;
}

Scene single_fracture_scene() {
  const double e = 100e-6;
  Scene s = trace_flow_scene({{Eigen::Vector2d(-0.5, kY), Eigen::Vector2d(1.5, kY), e},
                              {Eigen::Vector2d(0.2, 0.1), Eigen::Vector2d(0.2, 0.5), e},
                              {Eigen::Vector2d(0.5, 0.2), Eigen::Vector2d(0.5, 0.6), e},
                              {Eigen::Vector2d(0.75, 0.05), Eigen::Vector2d(0.75, 0.45), e}},
                             Vec2(0, 0), Vec2(1, 1));
  s.gravity = Eigen::Vector2d(0, -kG);
  flow_controls(s).gravity = true;
  flow_controls(s).fluid.density = kRho;
  FlowBoundaryCondition left, right;
  left.boundary = "left";
  left.value = kP1;
  right.boundary = "right";
  right.value = 0;
  flow_controls(s).conditions = {left, right};
  s.output.hdf5 = true;
  s.monitors = {{"main", Eigen::Vector2d(0.35, kY), -1},
                {"branch", Eigen::Vector2d(0.5, 0.5), -1},
                {"away", Eigen::Vector2d(0.9, 0.9), -1}};
  return s;
}

/// p* of the main fracture at x (closed form), Pa.
double potential(double x) {
  return kP1 * (1 - x) + kRho * kG * kY;
}

TEST(flow_output, SteadyFracturePressuresHeadsAndMonitors) {
  const Output out = run(single_fracture_scene(), "flow_output");
  ASSERT_EQ(out.summary.status, "completed") << out.summary.message;
  ASSERT_EQ(out.summary.output_frames, 2);
  const double tol = 1e-9 * kP1;

  test::H5Reader h5(out.dir / "results.h5");
  const std::vector<double> nodes = h5.doubles("/mesh/fractures/nodes");
  const std::size_t n = nodes.size() / 2;
  ASSERT_EQ(n, 11u);  // 2 ends + 3 junctions + 6 branch ends
  for (const char* frame : {"/frames/000000/fractures/", "/frames/000001/fractures/"}) {
    SCOPED_TRACE(frame);
    const std::vector<double> p = h5.doubles(std::string(frame) + "pressure");
    const std::vector<double> h = h5.doubles(std::string(frame) + "head");
    ASSERT_EQ(p.size(), n);
    ASSERT_EQ(h.size(), n);
    for (std::size_t v = 0; v < n; ++v) {
      const double x = nodes[2 * v], y = nodes[2 * v + 1];
      // On a branch p* is the junction's: the same closed form at its x.
      const double p_star = potential(x);
      EXPECT_NEAR(p[v], p_star - kRho * kG * y, tol) << "node " << v;
      EXPECT_NEAR(h[v], p_star / (kRho * kG), tol / (kRho * kG)) << "node " << v;
    }
    const std::vector<double> flux = h5.doubles(std::string(frame) + "flux");
    const std::vector<double> ea = h5.doubles(std::string(frame) + "aperture_a");
    ASSERT_EQ(flux.size(), ea.size());
    for (double e : ea) EXPECT_EQ(e, 100e-6);
  }
  // The boundary nodes hold exactly the boundary pressures.
  const std::vector<int> left = h5.ints("/mesh/fractures/boundaries/left");
  ASSERT_EQ(left.size(), 1u);
  EXPECT_NEAR(h5.doubles("/frames/000001/fractures/pressure")[left[0]], kP1, tol);

  const std::string xml = test::read_text(out.dir / "results.xdmf");
  EXPECT_TRUE(test::xml_tags_balanced(xml));
  EXPECT_EQ(test::count_occurrences(xml, "<Grid Name=\"blocks\""), 2);
  EXPECT_EQ(test::count_occurrences(xml, "<Grid Name=\"fractures\""), 2);
  EXPECT_EQ(test::count_occurrences(xml, "<Attribute Name=\"head\""), 2);
  test::expect_xdmf_refs_match(xml, h5);

  // m.p: linear along the nearest segment; missing away from the network.
  const double p_main = potential(0.35) - kRho * kG * kY;
  const double p_branch = potential(0.5) - kRho * kG * 0.5;
  const auto rows = csv(out.dir / "monitors.csv");
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0], (std::vector<std::string>{"t", "main.p", "branch.p", "away.p"}));
  for (int r = 1; r <= 2; ++r) {
    ASSERT_EQ(rows[r].size(), 4u);
    EXPECT_NEAR(std::stod(rows[r][1]), p_main, tol);
    EXPECT_NEAR(std::stod(rows[r][2]), p_branch, tol);
    EXPECT_EQ(rows[r][3], "");  // missing: an empty cell, never nan
  }
  const nlohmann::json& m = out.summary.monitors;
  EXPECT_NEAR(m["main"]["p"].get<double>(), p_main, tol);
  EXPECT_NEAR(m["branch"]["p"].get<double>(), p_branch, tol);
  EXPECT_FALSE(m["away"].contains("p"));  // off the network: left out, never null
}

TEST(flow_output, CoupledRunWritesBlocksAndFracturesInEveryFrame) {
  StackParameters p;
  p.kn = 2.5e8;
  p.dp = 100;
  p.history = {{0, 2}, {1, 2}};
  p.end_time = 0.01;
  Scene s = hm_stack_scene(p);
  s.output.hdf5 = true;
  s.output.every_steps = 5;
  s.monitors = {{"mid", Eigen::Vector2d(1, 0), 1}};  // on the joint, riding on the top block
  const Output out = run(s, "flow_output");
  ASSERT_EQ(out.summary.status, "completed") << out.summary.message;
  ASSERT_EQ(out.summary.output_frames, 3);  // t = 0, 5 and 10 ms

  test::H5Reader h5(out.dir / "results.h5");
  const std::string xml = test::read_text(out.dir / "results.xdmf");
  EXPECT_EQ(test::count_occurrences(xml, "<Grid Name=\"blocks\""), 3);
  EXPECT_EQ(test::count_occurrences(xml, "<Grid Name=\"fractures\""), 3);
  EXPECT_EQ(test::count_occurrences(xml, "<Attribute Name=\"pressure\""), 3);
  test::expect_xdmf_refs_match(xml, h5);
  // The last frame is the final state, bit for bit.
  const FractureFlowState& flow = out.state.fields.get(kFractureFlow);
  EXPECT_EQ(h5.doubles("/frames/000002/fractures/pressure"), flow.pressure);
  EXPECT_EQ(h5.doubles("/frames/000002/fractures/aperture_a"), flow.aperture_a);
  EXPECT_EQ(h5.doubles("/frames/000002/fractures/flux"), flow.flux);
  EXPECT_FALSE(h5.exists("/frames/000002/fractures/head"));  // the stack has flow.gravity off

  // Both ends are held (20100 and 19900 Pa): 20000 Pa in the middle.
  const auto rows = csv(out.dir / "monitors.csv");
  ASSERT_EQ(rows.size(), 4u);
  const std::vector<std::string> header{"t",      "mid.x", "mid.y",   "mid.ux",  "mid.uy", "mid.vx",
                                        "mid.vy", "mid.p", "mid.sxx", "mid.syy", "mid.sxy"};
  EXPECT_EQ(rows[0], header);
  EXPECT_NEAR(std::stod(rows[3][7]), 2 * p.p_ref, 1e-9 * p.p_ref);
  EXPECT_NEAR(out.summary.monitors["mid"]["p"].get<double>(), 2 * p.p_ref, 1e-9 * p.p_ref);
}

}  // namespace
}  // namespace fissure::testing
