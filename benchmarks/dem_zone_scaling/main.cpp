// Deformable DEM blocks (issue 37, section 4: at most 0.2 microseconds per
// zone per step on one core): a square block of 1e3, 1e4 and 1e5 triangular
// zones (mechanics/dem/zoned_block.h: constant strain, nodal-averaged
// volumetric strain, plane-strain elasticity, local damping 0.8), settling
// under gravity on a fixed base from an initial stress. Prints the zones,
// nodes, the meshing time and the CPU time per step and per zone and step
// (median of 5 runs of 20 steps, after 5 steps).
//
// Usage: bench_dem_zone_scaling [OUTPUT.csv]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "core/base/stopwatch.h"
#include "mechanics/dem/zoned_block.h"

int main(int argc, char** argv) {
  using namespace fissure;
  using namespace fissure::dem;
  const std::string out =
      argc > 1 ? argv[1] : FISSURE_SOURCE_DIR "/benchmarks/dem_zone_scaling/results.csv";
  std::ofstream csv(out);
  csv << "zones,nodes,mesh_s,step_s,us_per_zone_step\n";
  std::printf("%10s %10s %10s %14s %16s\n", "zones", "nodes", "mesh s", "ms per step",
              "us/zone/step");
  const ZoneMaterial rock{10e9, 0.25, 2500};
  // A 10 m square; zones of about 0.2 h^2 (polygon_mesher.h).
  for (double zone_size : {0.7, 0.22, 0.07}) {
    const double t_mesh = fissure::process_cpu_seconds();
    ZonedBlock block(mesh_block(Polygon({{0, 0}, {10, 0}, {10, 10}, {0, 10}}), zone_size), rock);
    const double mesh_s = fissure::process_cpu_seconds() - t_mesh;
    for (int a = 0; a < block.n_nodes(); ++a)
      if (block.positions()[a].y() == 0) block.fix(a, true, true);
    block.set_stress({-1e6, -2e6, 0.1e6, -1.5e6});
    const double dt = 0.5 * block.critical_time_step();
    const DampingControls damping{0.8, 0};
    const Vec2 gravity(0, -9.81);
    for (int k = 0; k < 5; ++k) block.step(dt, gravity, damping);
    std::vector<double> runs;
    for (int r = 0; r < 5; ++r) {
      const double t0 = fissure::process_cpu_seconds();
      for (int k = 0; k < 20; ++k) block.step(dt, gravity, damping);
      runs.push_back((fissure::process_cpu_seconds() - t0) / 20);
    }
    std::sort(runs.begin(), runs.end());
    const double per_step = runs[2];
    const double per_zone = 1e6 * per_step / block.n_zones();
    std::printf("%10d %10d %10.3f %14.3f %16.4f\n", block.n_zones(), block.n_nodes(), mesh_s,
                1e3 * per_step, per_zone);
    csv << block.n_zones() << "," << block.n_nodes() << "," << mesh_s << "," << per_step << ","
        << per_zone << "\n";
  }
  return 0;
}
