// DDA scaling (foundation issue, "Benchmarks"): staggered brick walls of about
// 100, 1,000 and 10,000 blocks (bricks 1.0 x 0.5 m, friction 30 deg, fixed
// base) settling under gravity from t = 0, dynamic DDA (k01 = 1), dt = 1 ms,
// automatic penalty; g2 is set so that the largest step displacement g2 w is
// 2 cm whatever the model size. Each case runs in a child process, so that
// its peak memory (ru_maxrss) is its own.
//
// Reported per accepted step: contact detection, assembly, linear solve,
// open-close update; open-close iterations per step; the fitted cost
// exponent of contact detection (t ~ N^a). Solvers: direct (CHOLMOD /
// UMFPACK), pcg (block-Jacobi CG / BiCGStab), petsc (CG + GAMG on BAIJ).
//
// Usage: bench_dda_scaling [steps=40] [OUTPUT.csv]
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "tests/support/dda_scenes.h"
#include "tests/support/run_scene.h"

using namespace fissure;

namespace {

struct Size {
  int courses, bricks;
};

struct Row {
  int blocks = 0;
  double detection = 0, assembly = 0, solve = 0, open_close = 0, total = 0;  // s per step
  double iterations = 0;                                                       // per step
  long steps = 0, cuts = 0;
  char status[16] = "";
};

Row run_case(const Size& size, LinearSolverControls::Type solver, double steps) {
  const double dt = 1e-3;
  Scene s = testing::brick_wall_scene(size.courses, size.bricks, 1.0, 0.5, 30, dt, 0, steps * dt);
  s.mechanics.dda.penalty.reset();
  const double w = 0.5 * (size.bricks + 2);  // half the larger side of the model
  s.mechanics.dda.max_displacement_ratio = 0.02 / w;
  s.mechanics.dda.solver.type = solver;
  s.mechanics.dda.solver.relative_tolerance = 1e-10;
  const testing::RunResult r = testing::run_scene(s, "bench_dda_scaling");
  const auto& m = r.summary.processes["mechanics"];
  Row row;
  row.blocks = static_cast<int>(s.blocks.size()) - 1;
  row.steps = m["steps"].get<long>();
  const double n = std::max<long>(row.steps, 1);
  row.detection = m["seconds"]["contact_detection"].get<double>() / n;
  row.assembly = m["seconds"]["assembly"].get<double>() / n;
  row.solve = m["seconds"]["solve"].get<double>() / n;
  row.open_close = m["seconds"]["open_close"].get<double>() / n;
  row.total = r.summary.wall_seconds / n;
  row.iterations = m["open_close_iterations"].get<double>() / n;
  row.cuts = m["time_step_cuts"]["open_close"].get<long>() +
             m["time_step_cuts"]["displacement_ratio"].get<long>();
  std::snprintf(row.status, sizeof row.status, "%s", r.summary.status.c_str());
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  const double steps = argc > 1 ? std::atof(argv[1]) : 40;
  const std::string csv =
      argc > 2 ? argv[2] : FISSURE_SOURCE_DIR "/benchmarks/dda_scaling/results.csv";
  const std::vector<Size> sizes = {{10, 10}, {20, 50}, {50, 200}};
  const std::vector<std::pair<const char*, LinearSolverControls::Type>> solvers = {
      {"direct", LinearSolverControls::Type::Direct},
      {"pcg", LinearSolverControls::Type::Pcg},
      {"petsc", LinearSolverControls::Type::Petsc}};

  std::ofstream out(csv);
  out << "solver,blocks,steps,status,cuts,iterations_per_step,detection_s,assembly_s,solve_s,"
         "open_close_s,total_s,peak_memory_mb\n";
  std::printf("%-7s %7s %6s %10s %5s %6s %10s %10s %10s %10s %10s %9s\n", "solver", "blocks",
              "steps", "status", "cuts", "its", "detect_ms", "assem_ms", "solve_ms", "oc_ms",
              "step_ms", "peak_MB");
  for (const auto& [solver_name, solver] : solvers)
    for (const Size& size : sizes) {
      // One child per case: its peak memory is its own.
      int pipe_fd[2];
      if (pipe(pipe_fd) != 0) return 1;
      const pid_t pid = fork();
      if (pid == 0) {
        close(pipe_fd[0]);
        const Row row = run_case(size, solver, steps);
        if (write(pipe_fd[1], &row, sizeof row) != sizeof row) _exit(1);
        _exit(0);
      }
      close(pipe_fd[1]);
      Row row;
      const bool ok = read(pipe_fd[0], &row, sizeof row) == sizeof row;
      close(pipe_fd[0]);
      int status = 0;
      rusage usage{};
      wait4(pid, &status, 0, &usage);
      if (!ok) {
        std::printf("%-7s %7d   failed (child exit %d)\n", solver_name, size.courses * size.bricks,
                    status);
        continue;
      }
      const double peak_mb = usage.ru_maxrss / 1024.0;
      std::printf("%-7s %7d %6ld %10s %5ld %6.2f %10.3f %10.3f %10.3f %10.3f %10.3f %9.1f\n",
                  solver_name, row.blocks, row.steps, row.status, row.cuts, row.iterations,
                  1e3 * row.detection, 1e3 * row.assembly, 1e3 * row.solve, 1e3 * row.open_close,
                  1e3 * row.total, peak_mb);
      std::fflush(stdout);
      out << solver_name << ',' << row.blocks << ',' << row.steps << ',' << row.status << ','
          << row.cuts << ',' << row.iterations << ',' << row.detection << ',' << row.assembly
          << ',' << row.solve << ',' << row.open_close << ',' << row.total << ',' << peak_mb
          << '\n';
    }
  return 0;
}
