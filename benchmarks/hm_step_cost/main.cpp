// Cost of a coupled HM step against the mechanics step alone (issue 4,
// "Benchmarks"; docs/performance.md "hm_step_cost"). The scene is
// configs/flow_hm_injection.yaml (80 blocks of two orthogonal joint sets, a
// well injecting at the centre) and the same rock mass on a 20 m square (320
// blocks), run for a fixed number of DDA steps:
//   mechanics       physics [mechanics] only (the flow section dropped);
//   hm_interval     the config: flow (steady) every 5 ms = 5 DDA steps;
//   hm_every_step   flow after every DDA step (coupling_interval 0).
// The coupled runs are not the same motion as the mechanics alone (the
// pressure loads move the blocks, and the contacts follow), so the DDA's own
// time per step differs too; the cost of coupling is the flow's time (network
// update, apertures, solve, pressure loads) against the DDA's.
// Reported per DDA step: wall time, the mechanics' and the flow's own time.
//
// It also writes the history of the config's full run (well pressure,
// apertures, uplift of the monitor above the well) to history.csv and its
// final state to final_blocks.csv / final_network.csv for the figures of
// docs/flow.md (plot.py).
//
// Usage: bench_hm_step_cost [steps=200] [OUTPUT.csv]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "coupling/process_registry.h"
#include "rockmass/fields/fracture_flow.h"
#include "rockmass/generate_rock_mass.h"
#include "tests/support/run_scene.h"

using namespace fissure;

namespace {

const std::string kDir = FISSURE_SOURCE_DIR "/benchmarks/hm_step_cost";

std::string config_text() {
  std::ifstream in(FISSURE_SOURCE_DIR "/configs/flow_hm_injection.yaml");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

Scene scene_of(std::string text, bool large) {
  if (large) {
    const std::string box = "[[0, 0], [10, 0], [10, 10], [0, 10]]";
    text.replace(text.find(box), box.size(), "[[0, 0], [20, 0], [20, 20], [0, 20]]");
  }
  return read_scene_text(text, "flow_hm_injection.yaml");
}

struct Timing {
  double wall = 0, mechanics = 0, flow = 0;  // s per DDA step
  long steps = 0, flow_updates = 0;
};

Timing run(Scene scene, long steps) {
  scene.time.max_steps = steps;
  scene.output.hdf5 = false;
  const testing::RunResult r = testing::run_scene(scene, "bench_hm_step_cost");
  Timing t;
  t.steps = r.summary.steps;
  const double n = std::max<long>(t.steps, 1);
  t.wall = r.summary.wall_seconds / n;
  const auto& p = r.summary.processes;
  const auto& m = p["mechanics"]["seconds"];
  for (const auto& [k, v] : m.items())
    if (v.is_number()) t.mechanics += v.get<double>();
  t.mechanics /= n;
  if (p.contains("flow")) {
    t.flow = p["flow"]["seconds"].get<double>() / n;
    t.flow_updates = p["flow"]["flow_updates"].get<long>();
  }
  return t;
}

int nearest_node(const FractureGraph& g, const Vec2& x) {
  int best = 0;
  for (int v = 1; v < g.n_nodes(); ++v)
    if ((g.nodes[v] - x).norm() < (g.nodes[best] - x).norm()) best = v;
  return best;
}

void write_history(const std::string& text) {
  // The config's run, stopped at a sequence of times (each from t = 0).
  std::ofstream out(kDir + "/history.csv");
  out << "t,well_pressure,max_aperture,uplift\n";
  RockMass last;
  for (double t_end : {0.02, 0.05, 0.1, 0.15, 0.2, 0.3, 0.4, 0.5}) {
    Scene s = scene_of(text, false);
    s.time.end_time = t_end;
    s.output.hdf5 = false;
    const testing::RunResult r = testing::run_scene(s, "bench_hm_step_cost_history");
    const FractureFlowState& flow = r.state.fields.get(kFractureFlow);
    double e_max = 0;
    for (std::size_t k = 0; k < flow.aperture_a.size(); ++k)
      e_max = std::max({e_max, flow.aperture_a[k], flow.aperture_b[k]});
    const double p = flow.pressure[nearest_node(r.state.fields.get(kFractureGraph), Vec2(5, 5))];
    const double uy = r.summary.monitors["above_well"]["uy"].get<double>();
    out << t_end << ',' << p << ',' << e_max << ',' << uy << '\n';
    std::printf("t = %.2f s: well pressure %.4g Pa, max aperture %.4g m, uplift %.4g m (%s)\n",
                t_end, p, e_max, uy, r.summary.status.c_str());
    last = r.state;
  }
  std::ofstream blocks(kDir + "/final_blocks.csv");
  blocks << "block,fixed,x,y\n";
  for (std::size_t b = 0; b < last.blocks.size(); ++b)
    for (const Vec2& v : last.blocks[b].polygon.loop(0))
      blocks << b << ',' << last.blocks[b].fixed << ',' << v.x() << ',' << v.y() << '\n';
  std::ofstream net(kDir + "/final_network.csv");
  net << "xa,ya,xb,yb,pa,pb,aperture,flux\n";
  const FractureGraph& g = last.fields.get(kFractureGraph);
  const FractureFlowState& flow = last.fields.get(kFractureFlow);
  for (int k = 0; k < g.n_segments(); ++k) {
    const auto& s = g.segments[k];
    net << g.nodes[s.node_a].x() << ',' << g.nodes[s.node_a].y() << ',' << g.nodes[s.node_b].x()
        << ',' << g.nodes[s.node_b].y() << ',' << flow.pressure[s.node_a] << ','
        << flow.pressure[s.node_b] << ',' << 0.5 * (flow.aperture_a[k] + flow.aperture_b[k]) << ','
        << flow.flux[k] << '\n';
  }
}

}  // namespace

int main(int argc, char** argv) {
  setenv("OPENBLAS_NUM_THREADS", "1", 1);
  setenv("OMP_NUM_THREADS", "1", 1);
  const long steps = argc > 1 ? std::atol(argv[1]) : 200;
  const std::string csv = argc > 2 ? argv[2] : kDir + "/results.csv";
  const std::string text = config_text();
  std::ofstream out(csv);
  out << "blocks,case,steps,flow_updates,wall_per_step_s,mechanics_per_step_s,flow_per_step_s,"
         "ratio_to_mechanics\n";
  std::printf("%6s %-14s %6s %7s %12s %12s %12s %7s\n", "blocks", "case", "steps", "updates",
              "wall/step", "mech/step", "flow/step", "ratio");
  for (bool large : {false, true}) {
    const Scene base = scene_of(text, large);
    double mechanics_wall = 0;
    for (const char* name : {"mechanics", "hm_interval", "hm_every_step"}) {
      Scene s = base;
      const std::string c = name;
      if (c == "mechanics") s.physics = {"mechanics"};
      if (c == "hm_every_step") s.coupling.intervals.erase("flow");
      const Timing t = run(s, steps);
      if (c == "mechanics") mechanics_wall = t.wall;
      const double ratio = t.wall / mechanics_wall;
      out << base.blocks.size() << ',' << name << ',' << t.steps << ',' << t.flow_updates << ','
          << t.wall << ',' << t.mechanics << ',' << t.flow << ',' << ratio << '\n';
      std::printf("%6zu %-14s %6ld %7ld %12.3e %12.3e %12.3e %7.3f\n", base.blocks.size(), name,
                  t.steps, t.flow_updates, t.wall, t.mechanics, t.flow, ratio);
      std::fflush(stdout);
    }
  }
  write_history(text);
  return 0;
}
