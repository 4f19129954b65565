// DDA static-friction stability sweep (foundation issue, "Stability stress
// test"): a 10 x 10 staggered brick wall (bricks 1.0 x 0.5 m, friction 30 deg,
// fixed base, gravity applied at t = 0) must stand, its top brick moving less
// than 1 mm in 1 s; a block on a 22.6 deg slope with friction 30 deg must move
// less than 1e-4 m in 2 s. Both for every dt in {1e-4, 1e-3, 1e-2} s and
// penalty in {5, 50, 500} x E and automatic (E = 10 GPa), dynamic DDA (k01 = 1).
//
// Usage: bench_dda_stability [OUTPUT.csv]   (default: results.csv here)
// Prints one row per case; the CSV feeds docs/performance.md.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "core/base/stopwatch.h"
#include "mechanics/dda/dda_settings.h"
#include "tests/support/dda_scenes.h"
#include "tests/support/run_scene.h"

using namespace fissure;

namespace {

struct Case {
  std::string scene;
  double dt, penalty_factor;  // 0 = automatic
};

}  // namespace

int main(int argc, char** argv) {
  const std::string csv =
      argc > 1 ? argv[1] : FISSURE_SOURCE_DIR "/benchmarks/dda_stability/results.csv";
  std::ofstream out(csv);
  out << "scene,dt,penalty_factor,status,steps,time_step_cuts,open_close_iterations,"
         "displacement,limit,passed,wall_seconds\n";
  std::printf("%-6s %8s %8s %10s %7s %6s %8s %12s %7s %8s\n", "scene", "dt", "penalty", "status",
              "steps", "cuts", "oc_its", "displacement", "passed", "wall_s");
  int failures = 0;
  for (const char* name : {"slope", "wall"})
    for (const double dt : {1e-4, 1e-3, 1e-2})
      for (const double pf : {5.0, 50.0, 500.0, 0.0}) {
        const bool wall = std::string(name) == "wall";
        Scene s = wall ? testing::brick_wall_scene(10, 10, 1.0, 0.5, 30, dt, pf * 10e9, 1.0)
                       : testing::incline_scene(22.6, 30, dt, pf * 10e9, 2.0);
        if (pf == 0) mechanics_controls(s).dda.penalty.reset();
        const Stopwatch clock;
        const testing::RunResult r = testing::run_scene(s, "bench_dda_stability");
        const double wall_s = clock.seconds();
        const auto& m = r.summary.monitors[wall ? "top" : "block"];
        const double u = std::hypot(m["ux"].get<double>(), m["uy"].get<double>());
        const double limit = wall ? 1e-3 : 1e-4;
        const auto& mech = r.summary.processes["mechanics"];
        const long cuts = mech["time_step_cuts"]["open_close"].get<long>() +
                          mech["time_step_cuts"]["displacement_ratio"].get<long>();
        const bool passed = r.summary.status == "completed" && u < limit;
        failures += !passed;
        const std::string penalty = pf == 0 ? "auto" : std::to_string(static_cast<int>(pf)) + "E";
        std::printf("%-6s %8.0e %8s %10s %7ld %6ld %8ld %12.3e %7s %8.2f\n", name, dt,
                    penalty.c_str(), r.summary.status.c_str(), r.summary.steps, cuts,
                    mech["open_close_iterations"].get<long>(), u, passed ? "yes" : "NO", wall_s);
        std::fflush(stdout);
        out << name << ',' << dt << ',' << penalty << ',' << r.summary.status << ','
            << r.summary.steps << ',' << cuts << ',' << mech["open_close_iterations"] << ',' << u
            << ',' << limit << ',' << (passed ? 1 : 0) << ',' << wall_s << '\n';
      }
  std::printf("%d of 24 cases failed\n", failures);
  return failures == 0 ? 0 : 1;
}
