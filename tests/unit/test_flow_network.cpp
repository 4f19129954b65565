// Unit tests of the network pieces of flow/network (theory.md 3.3): the
// graph from traces, dead-end and isolated-cluster reduction, named
// conditions, the steady solver's back ends, and the tensor fit.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "core/base/errors.h"
#include "flow/network/apertures.h"
#include "flow/network/boundary_conditions.h"
#include "flow/network/network_reduction.h"
#include "flow/network/steady_solver.h"
#include "flow/network/trace_network.h"
#include "flow/rev/read_rev_study.h"
#include "flow/rev/tensor_fit.h"
#include "tests/support/flow_networks.h"

namespace fissure::flow {
namespace {

Box unit_box() {
  Box b;
  b.lo = Vec2(0, 0);
  b.hi = Vec2(1, 1);
  return b;
}

std::vector<double> conductances(const FractureGraph& g) {
  std::vector<double> c(g.n_segments());
  for (int s = 0; s < g.n_segments(); ++s)
    c[s] = segment_conductance(g.segments[s].aperture, g.segments[s].aperture, g.length(s), 1e-3);
  return c;
}

TEST(flow_network, CrossingTracesMakeFiveNodesAndFourSegments) {
  const std::vector<Trace> traces = {{Vec2(-1, 0.5), Vec2(2, 0.5), 1e-4, 0, 0},
                                     {Vec2(0.5, -1), Vec2(0.5, 2), 1e-4, 1, 1}};
  TraceNetworkStatistics stats;
  const FractureGraph g = build_trace_network(traces, unit_box(), 1e-9, &stats);
  EXPECT_EQ(g.n_nodes(), 5);
  EXPECT_EQ(g.n_segments(), 4);
  EXPECT_EQ(stats.intersections, 1);
  EXPECT_EQ(g.boundary_nodes.at("left").size(), 1u);
  EXPECT_EQ(g.boundary_nodes.at("right").size(), 1u);
  EXPECT_EQ(g.boundary_nodes.at("bottom").size(), 1u);
  EXPECT_EQ(g.boundary_nodes.at("top").size(), 1u);
  double total = 0;
  for (int s = 0; s < g.n_segments(); ++s) total += g.length(s);
  EXPECT_NEAR(total, 2, 1e-14);
}

TEST(flow_network, TJunctionsAndTripleCrossingsShareNodes) {
  // A trace ending on another (T), and three traces through one point.
  const std::vector<Trace> traces = {{Vec2(0.1, 0.5), Vec2(0.9, 0.5), 1e-4},
                                     {Vec2(0.5, 0.5), Vec2(0.5, 0.9), 1e-4},
                                     {Vec2(0.2, 0.2), Vec2(0.8, 0.8), 1e-4}};
  const FractureGraph g = build_trace_network(traces, unit_box(), 1e-9);
  // Nodes: 0.1/0.9 ends, (0.5, 0.5) shared by all three, (0.5, 0.9), (0.2,0.2), (0.8,0.8).
  EXPECT_EQ(g.n_nodes(), 6);
  EXPECT_EQ(g.n_segments(), 5);
  EXPECT_TRUE(g.boundary_nodes.at("left").empty());
}

TEST(flow_network, ClipToBox) {
  Vec2 a(-1, -1), b(2, 2);
  ASSERT_TRUE(clip_to_box(a, b, unit_box()));
  EXPECT_NEAR((a - Vec2(0, 0)).norm(), 0, 1e-15);
  EXPECT_NEAR((b - Vec2(1, 1)).norm(), 0, 1e-15);
  Vec2 c(2, 0), d(3, 1);
  EXPECT_FALSE(clip_to_box(c, d, unit_box()));
}

TEST(flow_network, DeadEndsArePeeledAndIsolatedClustersLeftOut) {
  // Chain 0-1-2 between fixed ends, a dead-end tree 1-3-4 hanging from node 1,
  // and a separate loop 5-6-7.
  FractureGraph g;
  g.nodes = {Vec2(0, 0), Vec2(1, 0), Vec2(2, 0), Vec2(1, 1),
             Vec2(1, 2), Vec2(5, 5), Vec2(6, 5), Vec2(6, 6)};
  for (auto [a, b] : {std::pair{0, 1}, {1, 2}, {1, 3}, {3, 4}, {5, 6}, {6, 7}, {7, 5}}) {
    FractureSegment s;
    s.node_a = a, s.node_b = b, s.aperture = 1e-4;
    g.segments.push_back(s);
  }
  NodeConditions bc(8);
  bc.fixed_pressure[0] = 100;
  bc.fixed_pressure[2] = 0;
  const std::vector<double> c = conductances(g);
  const NetworkTopology t = reduce_network(g, c, bc, true);
  EXPECT_EQ(t.dead_ends.size(), 2u);
  EXPECT_TRUE(t.solved(1));
  EXPECT_FALSE(t.solved(5));
  SteadySolver solver({});
  const std::vector<double> previous(8, 7.0);
  const NetworkSolution sol = solver.solve(g, c, bc, FluidProperties{}, Vec2::Zero(), previous);
  EXPECT_EQ(sol.n_unknowns, 1);
  EXPECT_EQ(sol.n_isolated_nodes, 3);
  EXPECT_NEAR(sol.pressure[1], 50, 1e-12);
  EXPECT_NEAR(sol.pressure[3], 50, 1e-12);  // dead end: its neighbour's pressure
  EXPECT_NEAR(sol.pressure[4], 50, 1e-12);
  EXPECT_EQ(sol.pressure[5], 7.0);  // isolated: unchanged
  EXPECT_EQ(sol.flux[2], 0.0);
  EXPECT_EQ(sol.flux[4], 0.0);
  // Injecting into the isolated cluster has no steady state: a clear error.
  bc.source[5] = 1e-6;
  EXPECT_THROW(solver.solve(g, c, bc, FluidProperties{}, Vec2::Zero()), SolverError);
}

// An exchanging node (node_conditions.h; a mouth tied to a continuum)
// anchors its cluster like a fixed pressure and is no dead end: a chain of
// 10 segments from a fixed 1 MPa to a node that exchanges with 0.2 MPa
// through c carries (p0 - p_e) / (R + 1 / c), R the chain's resistance; a
// second chain held only by two exchanging ends carries
// (p_e1 - p_e2) / (R + 2 / c). Series resistances: exact to round-off.
TEST(flow_network, ExchangingNodesAreResistancesInSeries) {
  const FractureGraph one = testing::chain_network(10, Vec2(0, 0), Vec2(2, 0), 1e-4);
  const std::vector<double> c = conductances(one);
  double resistance = 0;
  for (double k : c) resistance += 1 / k;
  const double exchange = 0.5 / resistance;  // as conductive as half the chain
  NodeConditions bc(one.n_nodes());
  bc.fixed_pressure[0] = 1e6;
  bc.exchange_conductance[10] = exchange;
  bc.exchange_pressure[10] = 0.2e6;
  SteadySolver solver({});
  const NetworkSolution sol = solver.solve(one, c, bc, FluidProperties{}, Vec2::Zero());
  const double q = 0.8e6 / (resistance + 1 / exchange);
  EXPECT_EQ(sol.n_dead_end_nodes, 0);
  EXPECT_NEAR(sol.flux[0], q, 1e-12 * q);
  EXPECT_NEAR(sol.inflow[10], -q, 1e-12 * q);  // leaves through the exchange
  EXPECT_NEAR(sol.pressure[10], 0.2e6 + q / exchange, 1e-12 * 1e6);
  EXPECT_LT(sol.balance_error, 1e-12);

  NodeConditions two(one.n_nodes());
  for (int v : {0, 10}) two.exchange_conductance[v] = exchange;
  two.exchange_pressure[0] = 0.7e6;
  two.exchange_pressure[10] = 0.1e6;
  const NetworkSolution held = solver.solve(one, c, two, FluidProperties{}, Vec2::Zero());
  const double q2 = 0.6e6 / (resistance + 2 / exchange);
  EXPECT_EQ(held.n_isolated_nodes, 0);
  EXPECT_NEAR(held.flux[5], q2, 1e-12 * q2);
  EXPECT_NEAR(held.inflow[0], q2, 1e-12 * q2);
}

TEST(flow_network, SolverBackEndsAgree) {
  const FractureGraph g = testing::chain_network(50, Vec2(0, 0), Vec2(1, 0.3), 1e-4);
  NodeConditions bc(g.n_nodes());
  bc.fixed_pressure[0] = 1e5;
  bc.source[25] = 1e-7;
  bc.fixed_pressure[50] = 0;
  const std::vector<double> c = conductances(g);
  std::vector<LinearSolverControls> controls(3);
  controls[0].type = LinearSolverControls::Type::Direct;
  controls[1].type = LinearSolverControls::Type::Pcg;
  controls[1].relative_tolerance = 1e-13;
  controls[2].type = LinearSolverControls::Type::Petsc;
  controls[2].relative_tolerance = 1e-13;
  std::vector<NetworkSolution> sols;
  for (const auto& ctl : controls) {
    SteadySolver solver(ctl);
    sols.push_back(solver.solve(g, c, bc, FluidProperties{}, Vec2::Zero()));
  }
  for (int v = 0; v < g.n_nodes(); ++v) {
    EXPECT_NEAR(sols[1].pressure[v], sols[0].pressure[v], 1e-8 * 1e5);
    EXPECT_NEAR(sols[2].pressure[v], sols[0].pressure[v], 1e-8 * 1e5);
  }
  EXPECT_LT(sols[0].balance_error, 1e-10);
}

TEST(flow_network, NamedConditions) {
  FractureGraph g = testing::chain_network(4, Vec2(0, 0), Vec2(0, 4), 1e-4);
  g.boundary_nodes["both"] = {0, 4};
  FlowBoundaryCondition head, flux;
  head.boundary = "end";
  head.type = FlowBoundaryCondition::Type::Head;
  head.value = 10;
  head.history = {{0, 0}, {2, 1}};
  flux.boundary = "both";
  flux.type = FlowBoundaryCondition::Type::Flux;
  flux.value = 2e-6;
  FlowWell well;
  well.name = "w";
  well.point = Vec2(0, 2.5);
  well.rate = 1e-6;
  const int node = locate_well(g, well, 1e-6);
  EXPECT_EQ(node, 5);  // splits segment 2 at y = 2.5
  EXPECT_EQ(g.n_segments(), 5);
  const std::vector<FlowBoundaryCondition> conditions = {flux, head};
  const std::vector<FlowWell> wells = {well};
  const std::vector<int> nodes = {node};
  const FluidProperties water{1000, 1e-3, 2.2e9};
  const NodeConditions nc = resolve_conditions(g, conditions, wells, nodes, water, Vec2(0, -10), 1);
  // Head 10 m x factor 0.5 at t = 1, at y = 4: p = rho g (h - y) = 1000 * 10 * (5 - 4).
  EXPECT_NEAR(nc.fixed_pressure[4], 1e4, 1e-9);
  EXPECT_NEAR(nc.source[0], 1e-6, 1e-18);  // half of the flux on "both"
  EXPECT_NEAR(nc.source[5], 1e-6, 1e-18);  // the well
  EXPECT_NEAR(history_factor({{0, 0}, {2, 1}}, 5), 1, 0);
  EXPECT_THROW(
      check_condition_boundaries(g, std::vector<FlowBoundaryCondition>(
                                        1, FlowBoundaryCondition{"nowhere", {}, 0, {}, ""})),
      SceneError);
  FlowWell off;
  off.point = Vec2(3, 3);
  EXPECT_THROW(locate_well(g, off, 1e-6), SceneError);
}

TEST(flow_network, TensorFitIsExactForATensor) {
  Eigen::Matrix2d k;
  k << 3, 1, 1, 2;
  std::vector<double> angles, values;
  for (int i = 0; i < 12; ++i) {
    const double b = i * std::numbers::pi / 6;
    const Vec2 n(std::cos(b), std::sin(b));
    angles.push_back(b);
    values.push_back(n.dot(k * n));
  }
  const TensorFit fit = fit_tensor(angles, values);
  EXPECT_NEAR((fit.k - k).norm(), 0, 1e-12);
  EXPECT_LT(fit.misfit, 1e-13);
  EXPECT_NEAR(fit.k_max, 2.5 + std::sqrt(1.25), 1e-12);
  EXPECT_NEAR(fit.k_min, 2.5 - std::sqrt(1.25), 1e-12);
  EXPECT_NEAR(std::tan(2 * fit.angle), 2.0, 1e-12);
  EXPECT_NEAR((rotate_into(rotate_into(k, 0.3), -0.3) - k).norm(), 0, 1e-14);
}

TEST(flow_network, DocumentationListsEveryRevStudyKey) {
  // The study file is not a scene: its keys are documented in docs/flow.md.
  std::ifstream in(std::filesystem::path(FISSURE_SOURCE_DIR) / "docs" / "flow.md");
  ASSERT_TRUE(in) << "docs/flow.md not found";
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  const std::vector<std::string> keys = known_rev_study_keys();
  EXPECT_GT(keys.size(), 20u);  // the tables are read at all
  for (const std::string& key : keys)
    EXPECT_NE(doc.find("| `" + key + "` |"), std::string::npos)
        << "docs/flow.md does not document the REV study key `" << key << "`";
}

}  // namespace
}  // namespace fissure::flow
