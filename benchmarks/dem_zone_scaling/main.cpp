// Deformable DEM blocks (issue 37, section 4: at most 0.2 microseconds per
// zone per step on one core): a square block of 1e3, 1e4 and 1e5 triangular
// zones (mechanics/dem/zoned_block.h: constant strain, nodal-averaged
// volumetric strain, plane-strain elasticity, local damping 0.8), settling
// under gravity on a fixed base from an initial stress. Prints the zones,
// nodes, the meshing time and the CPU time per step and per zone and step
// (median of 5 runs of 20 steps, after 5 steps).
// Then the whole DEM cycle (mechanics/dem/dem_system.h) on staggered walls
// of deformable bricks (1.0 x 0.5 m, zones of 0.25 m, every boundary node a
// contact point) of 10 x 10, 30 x 30 and 60 x 60 bricks on a rigid base:
// wall-clock time per cycle, per zone and cycle and per contact and cycle
// (least of 3 runs of 20 cycles, after 20), on the threads OMP_NUM_THREADS
// allows.
//
// Usage: bench_dem_zone_scaling [OUTPUT.csv]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "core/base/stopwatch.h"
#include "mechanics/dem/dem_system.h"
#include "mechanics/dem/zoned_block.h"
#include "rockmass/joints/coulomb_slip.h"

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

  std::printf("\n%8s %10s %10s %14s %16s %18s\n", "bricks", "zones", "contacts", "ms per cycle",
              "us/zone/cycle", "us/contact/cycle");
  csv << "\nbricks,zones,contacts,cycle_s,us_per_zone_cycle,us_per_contact_cycle\n";
  joints::CoulombProperties joint;
  joint.normal_stiffness = 10e9;
  joint.shear_stiffness = 5e9;
  joint.friction_angle = 0.5;
  for (int n : {10, 30, 60}) {
    std::vector<DemBlock> blocks;
    DemBlock base;
    base.polygon = Polygon({{-1, -1}, {n + 1.0, -1}, {n + 1.0, 0}, {-1, 0}});
    base.fixed = true;
    blocks.push_back(base);
    int zones = 0;
    for (int c = 0; c < n; ++c)
      for (double x0 = c % 2 ? -0.5 : 0; x0 < n; x0 += 1) {
        const double a = std::max(x0, 0.0), b = std::min(x0 + 1, double(n));
        const double y0 = 0.5 * c, y1 = y0 + 0.5;
        DemBlock brick;
        brick.zoned.emplace(mesh_block(Polygon({{a, y0}, {b, y0}, {b, y1}, {a, y1}}), 0.25), rock);
        zones += brick.zoned->n_zones();
        blocks.push_back(std::move(brick));
      }
    const auto bricks = static_cast<int>(blocks.size()) - 1;
    DemSettings settings;
    settings.rounding = settings.margin = 5e-3;
    settings.gravity = Vec2(0, -9.81);
    settings.damping.local = 0.8;
    DemSystem system(std::move(blocks), {joints::JointLaw(joint)}, settings);
    system.prepare();
    system.set_time_step(0.5 * system.critical_time_step());
    for (int k = 0; k < 20; ++k) system.step();
    double best = 1e300;
    for (int r = 0; r < 3; ++r) {
      fissure::Stopwatch clock;
      for (int k = 0; k < 20; ++k) system.step();
      best = std::min(best, clock.seconds() / 20);
    }
    const auto contacts = static_cast<double>(system.contacts().size());
    std::printf("%8d %10d %10.0f %14.3f %16.4f %18.4f\n", bricks, zones, contacts, 1e3 * best,
                1e6 * best / zones, 1e6 * best / contacts);
    csv << bricks << "," << zones << "," << contacts << "," << best << "," << 1e6 * best / zones
        << "," << 1e6 * best / contacts << "\n";
  }
  return 0;
}
