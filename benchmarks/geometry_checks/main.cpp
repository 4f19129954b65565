// Geometry checks benchmark
//
// Run: build/benchmarks/bench_geometry_checks
//
// Times (best of several runs) of
//  1. find_overlapping_pairs on 1e3, 1e4, 1e5 rectangles: an axis-aligned
//     brick wall (touching only; boxes separate in the broad phase), the same
//     wall rotated by 0.3 rad (touching boxes overlap, every neighbour pair
//     reaches the narrow phase), and the wall with 1% of the bricks shifted
//     by half a brick (real overlaps);
//  2. check_polygon on valid polygons: a rough circle with 1e2..1e5 vertices
//     (short edges, the usual case), a star whose 1e2..1e4 vertices form
//     long thin spikes packed side by side (worst case for a box broad phase:
//     neighbouring spikes' boxes overlap, so candidate pairs grow ~n^2/cells),
//     and a domain with 1e4 vertices in 1000 holes;
//  3. triangulate on the stars.
// Prints a table and writes results.csv next to this file.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "core/base/stopwatch.h"
#include "core/geometry/polygon_checks.h"
#include "core/geometry/triangulate.h"

using namespace fissure;

namespace {

/// Best wall time in seconds of `f` over runs totalling at least ~0.3 s.
double best_time(const std::function<void()>& f) {
  double best = 1e300, total = 0;
  for (int run = 0; run < 20 && (run < 3 || total < 0.3); ++run) {
    const Stopwatch clock;
    f();
    const double t = clock.seconds();
    best = std::min(best, t);
    total += t;
  }
  return best;
}

std::vector<Polygon> brick_wall(int n, double angle, bool shift_some) {
  const int per_row = static_cast<int>(std::sqrt(n / 2.0)) + 1;
  const double c = std::cos(angle), s = std::sin(angle);
  auto at = [&](double x, double y) { return Vec2(c * x - s * y, s * x + c * y); };
  std::vector<Polygon> wall;
  for (int i = 0; i < n; ++i) {
    const int row = i / per_row, col = i % per_row;
    double x = 2.0 * col + (row % 2);
    if (shift_some && i % 100 == 7) x += 1;  // overlaps its right neighbour
    wall.push_back(Polygon({at(x, row), at(x + 2, row), at(x + 2, row + 1), at(x, row + 1)}));
  }
  return wall;
}

Polygon star(int n_vertices, const Vec2& c = Vec2::Zero(), double scale = 1) {
  std::vector<Vec2> v;
  for (int i = 0; i < n_vertices; ++i) {
    const double a = 2 * std::numbers::pi * i / n_vertices;
    v.push_back(c + scale * (i % 2 ? 40.0 : 50.0) * Vec2(std::cos(a), std::sin(a)));
  }
  return Polygon(v);
}

/// A circle of radius 50 with n vertices and a 1% radial ripple: edges short
/// compared with the polygon, as in cut blocks and domain boundaries.
Polygon rough_circle(int n_vertices) {
  std::vector<Vec2> v;
  for (int i = 0; i < n_vertices; ++i) {
    const double a = 2 * std::numbers::pi * i / n_vertices;
    v.push_back(50 * (1 + 0.01 * std::sin(37 * a)) * Vec2(std::cos(a), std::sin(a)));
  }
  return Polygon(v);
}

Polygon domain_with_holes(int n_holes) {
  const int side = static_cast<int>(std::ceil(std::sqrt(n_holes)));
  Polygon p({{0, 0}, {double(side), 0}, {double(side), double(side)}, {0, double(side)}});
  for (int k = 0; k < n_holes; ++k) {
    const double x = k % side + 0.25, y = k / side + 0.25;
    // Clockwise square hole with 10 vertices (collinear ones included).
    std::vector<Vec2> h{{x, y},
                        {x, y + 0.25},
                        {x, y + 0.5},
                        {x + 0.25, y + 0.5},
                        {x + 0.5, y + 0.5},
                        {x + 0.5, y + 0.3},
                        {x + 0.5, y + 0.1},
                        {x + 0.5, y},
                        {x + 0.3, y},
                        {x + 0.1, y}};
    p.add_loop(h);
  }
  return p;
}

}  // namespace

int main() {
  const std::filesystem::path csv_path =
      std::filesystem::path(__FILE__).parent_path() / "results.csv";
  std::ofstream csv(csv_path);
  csv << "case,size,seconds,result\n";
  auto report = [&](const std::string& name, int size, double seconds, std::size_t result) {
    fmt::print("{:<40} {:>8} {:>12.6f} s {:>8}\n", name, size, seconds, result);
    csv << name << ',' << size << ',' << seconds << ',' << result << '\n';
  };
  fmt::print("{:<40} {:>8} {:>14} {:>8}\n", "case", "size", "time", "result");

  const double tol = 1e-9;
  for (int n : {1000, 10000, 100000}) {
    for (const auto& [name, angle, shift] :
         {std::tuple{"overlaps: touching bricks", 0.0, false},
          std::tuple{"overlaps: rotated touching bricks", 0.3, false},
          std::tuple{"overlaps: bricks, 1% shifted", 0.0, true}}) {
      const std::vector<Polygon> wall = brick_wall(n, angle, shift);
      std::size_t pairs = 0;
      const double t = best_time([&] { pairs = find_overlapping_pairs(wall, tol).size(); });
      report(name, n, t, pairs);
    }
  }
  // Arguments are evaluated in unspecified order: time first, then report.
  auto time_check = [&](const std::string& name, const Polygon& p) {
    std::size_t problems = 0;
    const double t = best_time([&] { problems = check_polygon(p, tol).size(); });
    report(name, p.n_vertices(), t, problems);
  };
  for (int n : {100, 1000, 10000, 100000})
    time_check("check_polygon: rough circle", rough_circle(n));
  for (int n : {100, 1000, 10000}) time_check("check_polygon: dense star (worst case)", star(n));
  time_check("check_polygon: domain, 1000 holes", domain_with_holes(1000));
  for (int n : {100, 1000, 10000}) {
    const Polygon p = star(n);
    std::size_t triangles = 0;
    const double t = best_time([&] { triangles = triangulate(p).size(); });
    report("triangulate: dense star", n, t, triangles);
  }
  fmt::print("CSV: {}\n", csv_path.string());
  return 0;
}
