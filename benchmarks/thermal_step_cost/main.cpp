// Cost of a thermal step and of meshing the blocks (issue 23, "Benchmarks";
// docs/performance.md "thermal_step_cost").
//   step:  one square block of granite meshed to about 1e4, 1e5 and 1e6
//          nodes (one unknown per node), T fixed on the left, a flux on the
//          right, backward Euler with a fixed step: the first step factorizes,
//          the next ones reuse the factor. Reported: meshing (initialize),
//          the first step, and the mean of the next 10 steps.
//   mesh:  grids of 1 m square blocks (32 x 32 = 1,024 and 100 x 100 =
//          10,000 blocks) with perfect contact, element size 0.25 m: the
//          time of initialize (edge splitting, the meshes, joint faces,
//          matrices) and the first step.
// One core (CHOLMOD is run serial). Writes results.csv next to this file.
//
// Usage: bench_thermal_step_cost [largest_nodes=1e6]
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "core/base/stopwatch.h"
#include "tests/support/thermal_runs.h"

using namespace fissure;

namespace {

const ThermalMaterial kGranite{Eigen::Vector3d(3, 3, 0), 2.4e6};

ThermalControls controls(double h) {
  ThermalControls c;
  c.element_size = h;
  c.max_elements = 1e8;
  ThermalCondition left, right;
  left.boundary = "left";
  left.value = 50;
  right.boundary = "right";
  right.type = ThermalCondition::Type::Flux;
  right.value = 10;
  c.conditions = {left, right};
  return c;
}

struct Row {
  std::string kind;
  long blocks = 0, nodes = 0, triangles = 0;
  double mesh = 0, first_step = 0, step = 0, solve = 0;
};

Row measure(const std::string& kind, const std::vector<std::vector<Vec2>>& blocks, double h,
            int steps) {
  Row r;
  r.kind = kind;
  r.blocks = static_cast<long>(blocks.size());
  Stopwatch clock;
  testing::ThermalRun run(testing::thermal_scene(blocks, controls(h), kGranite));
  r.mesh = clock.lap();
  r.nodes = run.process->mesh().n_nodes();
  r.triangles = run.process->mesh().n_triangles();
  run.run(3600, 1);
  r.first_step = clock.lap();
  if (steps > 0) {
    const double solved = run.process->statistics()["solve_seconds"].get<double>();
    run.run(3600, steps);
    r.step = clock.lap() / steps;
    r.solve = (run.process->statistics()["solve_seconds"].get<double>() - solved) / steps;
  }
  std::printf(
      "%-5s %6ld blocks %9ld nodes %9ld triangles: mesh %8.3f s, first step %8.4f s, "
      "step %8.4f s (solve %8.4f s)\n",
      kind.c_str(), r.blocks, r.nodes, r.triangles, r.mesh, r.first_step, r.step, r.solve);
  std::fflush(stdout);
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  const double largest = argc > 1 ? std::atof(argv[1]) : 1e6;
  std::vector<Row> rows;
  // About 2.5 h^-2 nodes on the unit square (0.2 h^2 per triangle).
  for (const double nodes : {1e4, 1e5, 1e6}) {
    if (nodes > largest) break;
    const double h = std::sqrt(2.5 / nodes);
    rows.push_back(measure("step", {testing::box(0, 0, 1, 1)}, h, 10));
  }
  for (const int n : {32, 100}) {
    std::vector<std::vector<Vec2>> grid;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) grid.push_back(testing::box(i, j, i + 1, j + 1));
    rows.push_back(measure("mesh", grid, 0.25, 0));
  }
  std::ofstream out(FISSURE_SOURCE_DIR "/benchmarks/thermal_step_cost/results.csv");
  out << "kind,blocks,nodes,triangles,mesh_seconds,first_step_seconds,step_seconds,"
         "solve_seconds\n";
  for (const Row& r : rows)
    out << r.kind << ',' << r.blocks << ',' << r.nodes << ',' << r.triangles << ',' << r.mesh << ','
        << r.first_step << ',' << r.step << ',' << r.solve << '\n';
  return 0;
}
