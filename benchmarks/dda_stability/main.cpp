// DDA static-friction stability sweep (foundation issue, "Stability stress
// test"; issue 22, "Static friction at every time step"): a 10 x 10 staggered
// brick wall (bricks 1.0 x 0.5 m, friction 30 deg, fixed base, gravity applied
// at t = 0) must stand, its top brick moving less than 1 mm; a block on a
// 22.6 deg slope with friction 30 deg must move less than 1e-4 m in 2 s and
// end with its contacts closed. Both for every dt in {1e-6, ..., 1e-2} s and
// penalty in {1, 10, 100, 1000} x E and automatic (E = 10 GPa), dynamic DDA
// (k01 = 1).
//
// The slope runs 2 s at every dt (2e6 steps at 1e-6 s, ~20 s). The wall runs
// 1 s at dt >= 1e-4 s and `kWallSteps` steps below (0.1 s at 1e-5 s, 0.01 s
// at 1e-6 s): a step of the 100-brick wall costs ~2-3 ms, and 1 s at 1e-6 s
// would take most of an hour per case. The kinetic energy left at the end
// tells a wall at rest from one still moving.
//
// Usage: bench_dda_stability [OUTPUT.csv] [SCENE [DT [PENALTY_FACTOR [DAMPING_RATIO
//                            [CONTACTS]]]]]
//   (default output: results.csv here; SCENE slope|wall|all, DT 0 = all,
//   PENALTY_FACTOR 0 = automatic, -1 = all: run the cases that match only;
//   DAMPING_RATIO: mechanics.dda.damping_ratio instead of its default, < 0
//   the default; CONTACTS penalty (default) or augmented: the augmented
//   Lagrangian contacts of docs/dda.md section 11 (penetrations and stuck
//   slips to 1 um), with the penalty factors
//   0.01 E and 0.1 E besides (docs/performance.md compares the two runs):
//     bench_dda_stability results_augmented.csv all 0 -1 -1 augmented
//     bench_dda_stability results_soft_penalty.csv all 0 -1 -1 penalty)
// Prints one row per case; the CSV feeds docs/performance.md. The slope
// without vibration damping, results_undamped.csv (docs/dda.md section 4):
//   bench_dda_stability results_undamped.csv slope 0 -1 0
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "core/base/stopwatch.h"
#include "mechanics/dda/dda_settings.h"
#include "tests/support/dda_scenes.h"
#include "tests/support/run_scene.h"

using namespace fissure;

namespace {

constexpr double kYoung = 10e9;
constexpr double kWallSteps = 10000;

double duration(bool wall, double dt) {
  if (!wall) return 2.0;
  return std::min(1.0, kWallSteps * dt);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string csv =
      argc > 1 ? argv[1] : FISSURE_SOURCE_DIR "/benchmarks/dda_stability/results.csv";
  const std::string only_scene = argc > 2 ? argv[2] : "";
  const double only_dt = argc > 3 ? std::atof(argv[3]) : 0;
  const double only_pf = argc > 4 ? std::atof(argv[4]) : -1;
  const double damping_ratio = argc > 5 ? std::atof(argv[5]) : -1;
  const std::string contacts = argc > 6 ? argv[6] : "";
  const bool augmented = contacts == "augmented";
  if (!contacts.empty() && !augmented && contacts != "penalty") {
    std::fprintf(stderr, "CONTACTS must be penalty or augmented, not '%s'\n", contacts.c_str());
    return 2;
  }
  // The soft penalties where the penalty method's compliance shows.
  std::vector<double> factors = {1.0, 10.0, 100.0, 1000.0, 0.0};
  if (!contacts.empty()) factors.insert(factors.begin(), {0.01, 0.1});
  std::ofstream out(csv);
  out << "scene,dt,penalty_factor,end_time,status,steps,time_step_cuts,open_close_iterations,"
         "displacement,open_contacts,kinetic_energy,limit,passed,wall_seconds,contacts,"
         "max_penetration,augmentations\n";
  std::printf("%-6s %8s %8s %6s %10s %8s %6s %8s %12s %5s %10s %7s %8s %9s\n", "scene", "dt",
              "penalty", "t_end", "status", "steps", "cuts", "oc_its", "displacement", "open",
              "kinetic_J", "passed", "wall_s", "max_pen_m");
  int failures = 0, cases = 0;
  for (const char* name : {"slope", "wall"})
    for (const double dt : {1e-6, 1e-5, 1e-4, 1e-3, 1e-2})
      for (const double pf : factors) {
        if (!only_scene.empty() && only_scene != "all" && only_scene != name) continue;
        if (only_dt > 0 && std::abs(only_dt / dt - 1) > 1e-9) continue;
        if (only_pf >= 0 && only_pf != pf) continue;
        const bool wall = std::string(name) == "wall";
        const double t_end = duration(wall, dt);
        Scene s = wall ? testing::brick_wall_scene(10, 10, 1.0, 0.5, 30, dt, pf * kYoung, t_end)
                       : testing::incline_scene(22.6, 30, dt, pf * kYoung, t_end);
        if (pf == 0) mechanics_controls(s).dda.penalty.reset();
        if (damping_ratio >= 0) mechanics_controls(s).dda.damping_ratio = damping_ratio;
        // To 1 um: below every penalty's own penetration here.
        if (augmented) testing::use_augmented_lagrangian(s, 1e-6);
        const Stopwatch clock;
        const testing::RunResult r = testing::run_scene(s, "bench_dda_stability");
        const double wall_s = clock.seconds();
        const auto& m = r.summary.monitors[wall ? "top" : "block"];
        const double u = std::hypot(m["ux"].get<double>(), m["uy"].get<double>());
        const double limit = wall ? 1e-3 : 1e-4;
        const auto& mech = r.summary.processes["mechanics"];
        const long cuts = mech["time_step_cuts"]["open_close"].get<long>() +
                          mech["time_step_cuts"]["displacement_ratio"].get<long>();
        const long open = mech["contacts"]["open"].get<long>();
        const double kinetic = r.summary.energy["kinetic"].get<double>();
        // The block on the slope rests on its two base corners: both must stay closed.
        const bool passed = r.summary.status == "completed" && u < limit && (wall || open == 0);
        failures += !passed;
        ++cases;
        const std::string penalty = pf == 0 ? "auto" : fmt::format("{:g}E", pf);
        const double penetration = mech["max_penetration"].get<double>();
        const long augmentations =
            augmented ? mech["augmented_lagrangian"]["augmentations"].get<long>() : 0;
        std::printf("%-6s %8.0e %8s %6.3f %10s %8ld %6ld %8ld %12.3e %5ld %10.2e %7s %8.2f %9.2e\n",
                    name, dt, penalty.c_str(), t_end, r.summary.status.c_str(), r.summary.steps,
                    cuts, mech["open_close_iterations"].get<long>(), u, open, kinetic,
                    passed ? "yes" : "NO", wall_s, penetration);
        std::fflush(stdout);
        out << name << ',' << dt << ',' << penalty << ',' << t_end << ',' << r.summary.status << ','
            << r.summary.steps << ',' << cuts << ',' << mech["open_close_iterations"] << ',' << u
            << ',' << open << ',' << kinetic << ',' << limit << ',' << (passed ? 1 : 0) << ','
            << wall_s << ',' << (augmented ? "augmented" : "penalty") << ',' << penetration << ','
            << augmentations << '\n';
      }
  std::printf("%d of %d cases failed\n", failures, cases);
  return failures == 0 ? 0 : 1;
}
