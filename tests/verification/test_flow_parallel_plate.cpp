// verification.md (f), steady: flow through parallel-plate fractures.
// L = 1 m, e = 100 um, mu = 1e-3 Pa s, dp = 0.1 MPa: q = e^3 dp / (12 mu L)
// = 8.33333e-6 m^2/s and a linear pressure. The discrete network is exact for
// this case (a chain of uniform segments carries one flux), so the tolerance
// is round-off: 1e-10 relative.
#include <gtest/gtest.h>

#include <cmath>

#include "flow/network/apertures.h"
#include "flow/network/boundary_conditions.h"
#include "flow/network/steady_solver.h"
#include "rockmass/fields/fracture_flow.h"
#include "tests/support/flow_networks.h"
#include "tests/support/run_scene.h"

namespace fissure::flow {
namespace {

constexpr double kE = 100e-6, kMu = 1e-3, kDp = 0.1e6;

std::vector<double> conductances(const FractureGraph& g, double mu) {
  std::vector<double> c(g.n_segments());
  for (int s = 0; s < g.n_segments(); ++s)
    c[s] = segment_conductance(g.segments[s].aperture, g.segments[s].aperture, g.length(s), mu);
  return c;
}

TEST(flow_parallel_plate, SingleFractureCarriesTheCubicLawFlux) {
  const FractureGraph g = testing::chain_network(10, Vec2(0, 0), Vec2(1, 0), kE);
  NodeConditions bc(g.n_nodes());
  bc.fixed_pressure[0] = kDp;
  bc.fixed_pressure[10] = 0;
  SteadySolver solver({});
  const NetworkSolution sol =
      solver.solve(g, conductances(g, kMu), bc, FluidProperties{1000, kMu, 2.2e9}, Vec2::Zero());
  const double q = kE * kE * kE * kDp / (12 * kMu * 1.0);
  EXPECT_NEAR(q, 8.33333e-6, 1e-11);
  for (double f : sol.flux) EXPECT_NEAR(f, q, 1e-10 * q);
  for (int v = 0; v <= 10; ++v) EXPECT_NEAR(sol.pressure[v], kDp * (1 - v / 10.0), 1e-10 * kDp);
  EXPECT_NEAR(sol.inflow[0], q, 1e-10 * q);
  EXPECT_NEAR(sol.inflow[10], -q, 1e-10 * q);
  // Mean velocity and Reynolds number of verification.md (f).
  EXPECT_NEAR(q / kE, 0.0833333, 1e-7);
  EXPECT_NEAR(1000 * (q / kE) * 2 * kE / kMu, 16.6667, 1e-4);
}

TEST(flow_parallel_plate, TwoSegmentsInSeries) {
  // q = dp / [12 mu (L1/e1^3 + L2/e2^3)]: 0.4 m of 100 um, then 0.6 m of 60 um.
  FractureGraph g = testing::chain_network(2, Vec2(0, 0), Vec2(1, 0), kE);
  g.nodes[1] = Vec2(0.4, 0);
  g.segments[1].aperture = 60e-6;
  NodeConditions bc(3);
  bc.fixed_pressure[0] = kDp;
  bc.fixed_pressure[2] = 0;
  SteadySolver solver({});
  const NetworkSolution sol =
      solver.solve(g, conductances(g, kMu), bc, FluidProperties{1000, kMu, 2.2e9}, Vec2::Zero());
  const double q = kDp / (12 * kMu * (0.4 / std::pow(kE, 3) + 0.6 / std::pow(60e-6, 3)));
  EXPECT_NEAR(sol.flux[0], q, 1e-10 * q);
  EXPECT_NEAR(sol.flux[1], q, 1e-10 * q);
}

TEST(flow_parallel_plate, VerticalFractureWithNoFlowEndIsHydrostatic) {
  // Fixed p = 0 at the top, the bottom end closed: p = rho g (H - y), no flux.
  const double rho = 1000, g = 9.81, h = 10;
  const FractureGraph net = testing::chain_network(20, Vec2(0, 0), Vec2(0, h), kE);
  NodeConditions bc(net.n_nodes());
  bc.fixed_pressure[20] = 0;
  SteadySolver solver({});
  const std::vector<double> c = conductances(net, kMu);
  const NetworkSolution sol =
      solver.solve(net, c, bc, FluidProperties{rho, kMu, 2.2e9}, Vec2(0, -g));
  for (int v = 0; v <= 20; ++v)
    EXPECT_NEAR(sol.pressure[v], rho * g * (h - net.nodes[v].y()), 1e-10 * rho * g * h);
  // The whole chain is a dead end of the top node: removed, no unknowns.
  EXPECT_EQ(sol.n_dead_end_nodes, 20);
  const double scale = c[0] * rho * g * h;
  for (double f : sol.flux) EXPECT_LE(std::abs(f), 1e-10 * scale);
}

TEST(flow_parallel_plate, FlowProcessReportsTheCubicLawFlux) {
  // The same fracture as a scene: a trace across a 1 m box, pressure on the
  // left side, zero on the right; summary.json reports the boundary inflow.
  Scene s = testing::trace_flow_scene({{Eigen::Vector2d(-0.5, 0.3), Eigen::Vector2d(1.5, 0.3), kE}},
                                      Vec2(0, 0), Vec2(1, 1));
  FlowBoundaryCondition left, right;
  left.boundary = "left";
  left.value = kDp;
  right.boundary = "right";
  right.value = 0;
  flow_controls(s).conditions = {left, right};
  const testing::RunResult r = testing::run_scene(s, "flow_parallel_plate");
  ASSERT_EQ(r.summary.status, "completed") << r.summary.message;
  const double q = kE * kE * kE * kDp / (12 * kMu);
  EXPECT_NEAR(r.summary.processes["flow"]["boundary_inflow"]["left"].get<double>(), q, 1e-10 * q);
  EXPECT_NEAR(r.summary.processes["flow"]["boundary_inflow"]["right"].get<double>(), -q, 1e-10 * q);
  const FractureFlowState& flow = r.state.fields.get(kFractureFlow);
  ASSERT_EQ(flow.flux.size(), 1u);
  EXPECT_NEAR(flow.flux[0], q, 1e-10 * q);
}

}  // namespace
}  // namespace fissure::flow
