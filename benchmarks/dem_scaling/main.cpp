// DEM scaling (issue 37, section 4), contact detection so far: staggered
// brick walls of about 100, 1,000, 10,000 and 100,000 rigid bricks (1.0 x
// 0.5 m, 1 mm apart, every other course offset by half a brick), rounding
// length 1 cm, margin 1 cm: the time of one full detection
// (mechanics/dem/contact_geometry.h: the box-grid broad phase and the
// corner tests), the contacts found per brick, and the fitted exponent of
// the time against the number of bricks (t ~ N^a; the issue asks a <= 1.1
// from 100 to 100,000). Median of 5 detections; CPU time of this process.
//
// Usage: bench_dem_scaling [OUTPUT.csv]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <string>
#include <vector>

#include "mechanics/dem/contact_geometry.h"

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

double cpu_seconds() {
  return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
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
      const double t0 = cpu_seconds();
      contacts = fissure::dem::find_contacts(wall, 0.01, 0.01).size();
      runs.push_back(cpu_seconds() - t0);
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
  return 0;
}
