// DEM scaling (issue 37, section 4), contact detection so far: staggered
// brick walls of about 100, 1,000, 10,000 and 100,000 rigid bricks (1.0 x
// 0.5 m, 1 mm apart, every other course offset by half a brick), rounding
// length 1 cm, margin 1 cm: the time of one full detection
// (mechanics/dem/contact_geometry.h: the box-grid broad phase and the
// corner tests), the contacts found per brick, and the fitted exponent of
// the time against the number of bricks (t ~ N^a; the issue asks a <= 1.1
// from 100 to 100,000). Median of 5 detections; CPU time of this process.
// Then the whole cycle of dem_system.h on the walls up to 10,000 bricks:
// wall-clock time per step and per contact and step on the threads
// OMP_NUM_THREADS allows (the issue asks at most 0.3 us on one core at
// 10,000 bricks, and the speed-up on 2 cores; contacts are searched only
// after a block moved by a quarter of the margin, and updated in between).
// Measured at 166b11d (docs/performance.md, "Explicit DEM: contacts and the
// cycle"): 0.067 us per contact and step on one thread at 10,001 bricks,
// 0.049 us on two, a speed-up of 1.36 (1.33 at 1,025 bricks; none at 101,
// below the 4,096 contacts from which the loops run in parallel).
//
// Usage: bench_dem_scaling [OUTPUT.csv]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "core/base/stopwatch.h"
#include "mechanics/dem/contact_geometry.h"
#include "mechanics/dem/dem_system.h"

namespace {

using fissure::Polygon;
using fissure::Vec2;

std::vector<Polygon> brick_wall(int courses, int bricks) {
  const double w = 1.0, h = 0.5, gap = 1e-3;
  std::vector<Polygon> blocks;
  blocks.push_back(Polygon({{-1, -1},
                            {bricks * (w + gap) + 1, -1},
                            {bricks * (w + gap) + 1, -gap},
                            {-1, -gap}}));  // the base
  for (int c = 0; c < courses; ++c) {
    const double y = c * (h + gap), shift = (c % 2) * 0.5 * (w + gap);
    for (int b = 0; b < bricks; ++b) {
      const double x = shift + b * (w + gap);
      blocks.push_back(Polygon({{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}}));
    }
  }
  return blocks;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string out =
      argc > 1 ? argv[1] : FISSURE_SOURCE_DIR "/benchmarks/dem_scaling/results.csv";
  std::ofstream csv(out);
  csv << "bricks,contacts,contacts_per_brick,detection_s,detection_us_per_brick\n";
  std::printf("%10s %10s %10s %14s %12s\n", "bricks", "contacts", "per brick", "detection ms",
              "us/brick");
  std::vector<double> sizes, times;
  for (auto [courses, bricks] : {std::pair{10, 10}, {32, 32}, {100, 100}, {316, 316}}) {
    const std::vector<Polygon> wall = brick_wall(courses, bricks);
    std::vector<double> runs;
    std::size_t contacts = 0;
    for (int r = 0; r < 5; ++r) {
      const double t0 = fissure::process_cpu_seconds();
      contacts = fissure::dem::find_contacts(wall, 0.01, 0.01).size();
      runs.push_back(fissure::process_cpu_seconds() - t0);
    }
    std::sort(runs.begin(), runs.end());
    const double t = runs[2];
    const double n = static_cast<double>(wall.size());
    sizes.push_back(n);
    times.push_back(t);
    std::printf("%10.0f %10zu %10.2f %14.3f %12.3f\n", n, contacts, contacts / n, 1e3 * t,
                1e6 * t / n);
    csv << n << "," << contacts << "," << contacts / n << "," << t << "," << 1e6 * t / n << "\n";
  }
  const double exponent =
      std::log(times.back() / times.front()) / std::log(sizes.back() / sizes.front());
  std::printf("detection exponent, %.0f to %.0f bricks: %.3f\n", sizes.front(), sizes.back(),
              exponent);

  // The whole cycle (dem_system.h): the wall settling under gravity, k_n =
  // k_s = 10 GPa/m, friction 30 degrees, local damping 0.8, dt = 1e-4 s;
  // wall-clock time per step and per contact and step, the least of 3
  // rounds of 20 steps after 5, on the threads OMP_NUM_THREADS allows (the
  // loops run in parallel from 4,096 contacts).
  const char* threads = std::getenv("OMP_NUM_THREADS");
  std::printf("\nthe cycle on %s thread(s) (OMP_NUM_THREADS)\n", threads ? threads : "all");
  std::printf("%10s %10s %14s %18s\n", "bricks", "contacts", "ms per step", "us/contact/step");
  std::ofstream cycle_csv(out.substr(0, out.rfind('.')) + "_cycle.csv");
  cycle_csv << "bricks,contacts,threads,step_s,us_per_contact_step\n";
  for (auto [courses, bricks] : {std::pair{10, 10}, {32, 32}, {100, 100}}) {
    std::vector<fissure::dem::DemBlock> blocks;
    for (const Polygon& p : brick_wall(courses, bricks)) {
      fissure::dem::DemBlock b;
      b.polygon = p;
      const fissure::SectionProperties sp = fissure::section_properties(p);
      b.centroid = sp.centroid;
      b.body = fissure::dem::rigid_body(sp, 2500);
      blocks.push_back(b);
    }
    blocks[0].fixed = true;
    fissure::joints::CoulombProperties joint;
    joint.normal_stiffness = joint.shear_stiffness = 10e9;
    joint.friction_angle = 30 * 3.14159265358979 / 180;
    fissure::dem::DemSettings settings;
    settings.rounding = settings.margin = 0.01;
    settings.time_step = 1e-4;
    settings.gravity = Vec2(0, -9.81);
    settings.damping.local = 0.8;
    fissure::dem::DemSystem system(std::move(blocks), {fissure::joints::JointLaw(joint)}, settings);
    for (int k = 0; k < 5; ++k) system.step();
    double per_step = 1e30;
    for (int round = 0; round < 3; ++round) {
      const fissure::Stopwatch clock;
      for (int k = 0; k < 20; ++k) system.step();
      per_step = std::min(per_step, clock.seconds() / 20);
    }
    const double contacts = static_cast<double>(system.contacts().size());
    std::printf("%10zu %10.0f %14.3f %18.3f\n", system.blocks().size(), contacts, 1e3 * per_step,
                1e6 * per_step / contacts);
    cycle_csv << system.blocks().size() << "," << contacts << "," << (threads ? threads : "all")
              << "," << per_step << "," << 1e6 * per_step / contacts << "\n";
  }
  return 0;
}
