#include "tests/support/flow_networks.h"

#include <cmath>
#include <numbers>
#include <random>

#include "mechanics/dda/dda_settings.h"
#include "tests/support/dda_scenes.h"

namespace fissure::testing {

FractureGraph chain_network(int n, const Vec2& from, const Vec2& to, double aperture) {
  FractureGraph g;
  for (int k = 0; k <= n; ++k) g.nodes.push_back(from + (to - from) * (double(k) / n));
  for (int k = 0; k < n; ++k) {
    FractureSegment s;
    s.node_a = k;
    s.node_b = k + 1;
    s.aperture = aperture;
    g.segments.push_back(s);
  }
  g.boundary_nodes["start"] = {0};
  g.boundary_nodes["end"] = {n};
  return g;
}

Scene trace_flow_scene(const std::vector<FlowTrace>& traces, const Vec2& lo, const Vec2& hi) {
  Scene s;
  s.name = "flow_test";
  s.physics = {"flow"};
  s.gravity = Vec2::Zero();
  s.materials.push_back({"rock", 2700, 10e9, 0.25});
  s.joints.push_back({"joint", 0.5, 0, 0});
  s.blocks.push_back(block("domain", rectangle(hi.x() - lo.x(), hi.y() - lo.y(), 0, lo)));
  FlowControls& flow = flow_controls(s);
  flow.network = FlowControls::NetworkSource::Traces;
  flow.traces = traces;
  flow.domain = std::make_pair(Eigen::Vector2d(lo), Eigen::Vector2d(hi));
  s.time.end_time = 1;
  s.output.hdf5 = false;
  return s;
}

std::vector<FlowTrace> random_traces(int n, double size, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  const double deg = std::numbers::pi / 180;
  std::vector<FlowTrace> traces;
  for (int k = 0; k < n; ++k) {
    const double angle = (k % 2 == 0 ? 20 : 110) * deg + (u(rng) - 0.5) * 30 * deg;
    const double length = (0.05 + 0.25 * u(rng)) * size;
    const Vec2 c(u(rng) * size, u(rng) * size);
    const Vec2 t(std::cos(angle), std::sin(angle));
    FlowTrace tr;
    tr.from = c - 0.5 * length * t;
    tr.to = c + 0.5 * length * t;
    tr.aperture = 20e-6 * std::pow(10.0, u(rng));
    traces.push_back(tr);
  }
  return traces;
}

Scene hm_stack_scene(const StackParameters& p) {
  Scene s = base_scene(10e9, 30, p.g);
  s.name = "hm_stack";
  s.physics = {"mechanics", "flow"};
  s.materials[0].density = p.density;
  s.blocks.push_back(block("base", rectangle(4, 1, 0, Vec2(-1, -1)), true));
  s.blocks.push_back(block("top", rectangle(2, p.height, 0, Vec2(0, 0))));
  mechanics_controls(s).dda.max_time_step = p.dt;
  mechanics_controls(s).dda.velocity_carry_over = 0;  // static: each step relaxes to equilibrium
  FlowControls& flow = flow_controls(s);
  flow.gravity = false;  // the fracture is horizontal: no head effect
  flow.initial_aperture = p.e0;
  flow.residual_aperture = p.residual;
  flow.hm.emplace().normal_stiffness = p.kn;
  // Both ends of the fracture: left end (0, 0) and right end (2, 0).
  flow.regions.push_back({"left_end", Eigen::Vector2d(-0.01, -0.01), Eigen::Vector2d(0.01, 0.01)});
  flow.regions.push_back({"right_end", Eigen::Vector2d(1.99, -0.01), Eigen::Vector2d(2.01, 0.01)});
  FlowBoundaryCondition left, right;
  left.boundary = "left_end";
  left.value = p.p_ref + p.dp / 2;
  left.history = p.history;
  right.boundary = "right_end";
  right.value = p.p_ref - p.dp / 2;
  right.history = p.history;
  flow.conditions = {left, right};
  s.time.end_time = p.end_time;
  s.output.hdf5 = false;
  return s;
}

}  // namespace fissure::testing
