// DDA and DEM: work against precision (issue 37, section 3;
// docs/performance.md, "DDA and DEM: work against precision"). Both block
// methods bring two scenes of configs/ to rest, at several step sizes and
// solve ratios, and each run's CPU time is set against the error of its end
// state against the same method's converged state on the same path:
//  1. the brick wall as rigid blocks on linear joints in both methods
//     (tests/support/dda_dem_scenes.h), the top brick's settlement:
//     * DDA, static steps (velocity carry-over k01 = 0) of 1, 10 and 100 ms,
//       n of them (converged: 50 of 100 ms); dynamic steps (k01 = 1, the
//       scene's) of 1 ms to a time;
//     * DEM, one update solved to an unbalanced-force ratio R
//       (dem.solve_ratio); in real time under local damping 0.8 (the
//       scene's) to a time (converged: 0.5 s, ratio 4e-16);
//     and each against its closed form too (the joints' closures; the DDA's
//     plus its blocks' shortening at E = 1 TPa, whose closed form leaves out
//     the bricks' lateral stresses: 1.5e-5 of the settlement);
//  2. the jointed slope (jointed_slope.yaml, dem_jointed_slope.yaml), the
//     crest's displacement: its end state depends on the path (friction is
//     mobilized while it settles), so it has no closed form; the DDA's
//     static steps of 10 ms (converged: 100 of them), the DEM's solves
//     (converged: R = 1e-10).
// The DEM's unbalanced-force ratio at the end is printed beside.
//
// CPU time of this process (std::clock, all threads) and wall time, each the
// least of 3 runs (the machine is shared: the least is the run least
// disturbed); every run writes its monitors and summary (no HDF5).
//
// Usage: bench_dda_vs_dem [OUTPUT.csv]   (default: results.csv here)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "core/base/stopwatch.h"
#include "tests/support/dda_dem_scenes.h"
#include "tests/support/run_scene.h"

using namespace fissure;
using namespace fissure::testing;

namespace {

constexpr int kRepetitions = 3;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Case {
  std::string scene, method, mode;
  double parameter;  ///< the step (s), the end time (s) or the solve ratio
  Scene build;
  bool reference = false;  ///< the method's converged run on this scene
};

struct Run {
  std::string status;
  long steps = 0, cycles = 0;  ///< the DDA's steps, the DEM's cycles
  double ux = kNaN, uy = kNaN, ratio = kNaN;
  double cpu = std::numeric_limits<double>::infinity(), wall = cpu;
};

Run run(const Case& c, const std::string& monitor) {
  Run r;
  for (int k = 0; k < kRepetitions; ++k) {
    const std::clock_t cpu0 = std::clock();
    const Stopwatch clock;
    const RunResult result = run_scene(c.build, "bench_dda_vs_dem");
    r.wall = std::min(r.wall, clock.seconds());
    r.cpu = std::min(r.cpu, static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC);
    if (k > 0) continue;
    r.status = result.summary.status;
    const nlohmann::json& m = result.summary.monitors.at(monitor);
    r.ux = m.at("ux").get<double>();
    r.uy = m.at("uy").get<double>();
    const nlohmann::json& p = result.summary.processes;
    if (c.method == "dda") {
      r.steps = p.at("mechanics").at("steps").get<long>();
    } else {
      r.cycles = p.at("dem").at("cycles").get<long>();
      r.ratio = p.at("dem").at("unbalanced_force_ratio").at("last").get<double>();
    }
  }
  return r;
}

std::string dem_solve(double ratio) {
  return fmt::format("  solve_ratio: {}\n  max_cycles: 1000000\n", ratio);
}

Scene dda_slope(double time_step, int steps) {
  return edited_config("jointed_slope",
                       {{"time_step: 2 ms", fmt::format("time_step: {} s", time_step)},
                        {"velocity_carry_over: 0.9", "velocity_carry_over: 0"},
                        {"end: 0.3", fmt::format("end: {}", steps * time_step)},
                        {"interval: 0.05", "interval: 10"}});
}

Scene dem_slope(double ratio) {
  return edited_config("dem_jointed_slope", {{"  solve_ratio: 1e-5\n", dem_solve(ratio)},
                                             {"end: 0.3", "end: 0.05"},
                                             {"interval: 0.05", "interval: 10"}});
}

/// The least CPU time of the runs of (scene, method) whose error is at most `target`.
double time_to(const std::vector<std::pair<Case, Run>>& runs, const std::vector<double>& errors,
               const std::string& scene, const std::string& method, double target) {
  double best = kNaN;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const auto& [c, r] = runs[k];
    if (c.scene == scene && c.method == method && errors[k] <= target && !(r.cpu >= best))
      best = r.cpu;
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string csv_path =
      argc > 1 ? argv[1] : FISSURE_SOURCE_DIR "/benchmarks/dda_vs_dem/results.csv";
  std::vector<Case> cases;
  // 1. The wall.
  for (const double dt : {1e-3, 1e-2, 1e-1})
    for (const int n : {1, 2, 3, 5, 10, 20, 50})
      cases.push_back(
          {"wall", "dda", "static", dt, stiff_wall_dda(dt, 0, n * dt), dt == 1e-1 && n == 50});
  for (const double end : {0.05, 0.1, 0.2, 0.5, 1.0})
    cases.push_back({"wall", "dda", "dynamic", end, stiff_wall_dda(1e-3, 1, end)});
  for (const double ratio : {1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9})
    cases.push_back({"wall", "dem", "solved", ratio, rigid_wall_dem(dem_solve(ratio), 0.02)});
  for (const double end : {0.02, 0.05, 0.1, 0.2, 0.5})
    cases.push_back({"wall", "dem", "damped", end, rigid_wall_dem("", end), end == 0.5});
  // 2. The slope.
  for (const int n : {1, 2, 3, 5, 10, 20, 100})
    cases.push_back({"slope", "dda", "static", n * 1e-2, dda_slope(1e-2, n), n == 100});
  for (const double ratio : {1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-10})
    cases.push_back({"slope", "dem", "solved", ratio, dem_slope(ratio), ratio == 1e-10});

  std::vector<std::pair<Case, Run>> runs;
  for (const Case& c : cases) runs.emplace_back(c, run(c, c.scene == "wall" ? "top" : "crest"));

  // Errors: the wall's against its closed forms (the DDA's with its blocks'
  // shortening, whose closed form leaves out the bricks' lateral stresses);
  // every run's against its method's converged run on the same path (the
  // reference's own is NaN: not a result).
  const double joints = wall_joints_settlement();
  const double blocks = wall_blocks_shortening(wall::kStiffYoungModulus);
  std::vector<double> closed_form_errors, errors;
  for (const auto& [c, r] : runs) {
    const double exact = joints + (c.method == "dda" ? blocks : 0);
    closed_form_errors.push_back(c.scene == "wall" ? std::abs(-r.uy - exact) / exact : kNaN);
    const Run* converged = nullptr;
    for (const auto& [c2, r2] : runs)
      if (c2.scene == c.scene && c2.method == c.method && c2.reference) converged = &r2;
    errors.push_back(converged == &r ? kNaN
                                     : std::hypot(r.ux - converged->ux, r.uy - converged->uy) /
                                           std::hypot(converged->ux, converged->uy));
  }

  std::ofstream csv(csv_path);
  csv << "scene,method,mode,parameter,status,steps,cycles,ux,uy,error_closed_form,error,ratio,cpu_"
         "seconds,wall_seconds\n";
  std::printf("%-6s %-4s %-8s %9s %6s %8s %12s %10s %10s %10s %9s %9s\n", "scene", "", "mode",
              "param", "steps", "cycles", "settlement", "closed f.", "converged", "ratio",
              "cpu (s)", "wall (s)");
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const auto& [c, r] = runs[k];
    csv << fmt::format("{},{},{},{},{},{},{},{:.12g},{:.12g},{:.6e},{:.6e},{:.6e},{:.6f},{:.6f}\n",
                       c.scene, c.method, c.mode, c.parameter, r.status, r.steps, r.cycles, r.ux,
                       r.uy, closed_form_errors[k], errors[k], r.ratio, r.cpu, r.wall);
    std::printf("%-6s %-4s %-8s %9.0e %6ld %8ld %12.6e %10.2e %10.2e %10.2e %9.4f %9.4f\n",
                c.scene.c_str(), c.method.c_str(), c.mode.c_str(), c.parameter, r.steps, r.cycles,
                -r.uy, closed_form_errors[k], errors[k], r.ratio, r.cpu, r.wall);
  }
  std::printf(
      "\nCPU time (s) to reach an error against the converged state (the least over the runs "
      "that reach it):\n");
  std::printf("%-6s %-4s %10s %10s %10s %10s\n", "scene", "", "1e-2", "1e-3", "1e-4", "1e-6");
  for (const std::string scene : {"wall", "slope"})
    for (const std::string method : {"dda", "dem"}) {
      std::printf("%-6s %-4s", scene.c_str(), method.c_str());
      for (const double target : {1e-2, 1e-3, 1e-4, 1e-6})
        std::printf(" %10.4f", time_to(runs, errors, scene, method, target));
      std::printf("\n");
    }
  return 0;
}
