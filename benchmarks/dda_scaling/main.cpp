// DDA scaling (foundation issue, "Benchmarks"): staggered brick walls of about
// 100, 1,000 and 10,000 blocks (bricks 1.0 x 0.5 m, friction 30 deg, fixed
// base) settling under gravity from t = 0, dynamic DDA (k01 = 1), dt = 1 ms,
// automatic penalty; g2 is set so that the largest step displacement g2 w is
// 2 cm whatever the model size. Each case runs in a child process, so that
// its peak memory (ru_maxrss) is its own.
//
// Each case runs `steps` accepted steps from rest (time.max_steps), so the
// steps include the cut-and-repeated attempts of the first impact transient.
// Two modes: dynamic (k01 = 1, the wall rings on its contact springs) and
// static (k01 = 0, Shi's static analysis: every step starts at rest, the
// usual way to settle an assembly). The mean accepted dt is reported too: a
// step cut to a tenth of dt_max is cheap but ten times as many are needed.
// Reported per accepted step: the CPU time of the child process (user +
// system; unlike wall time it does not grow when other jobs share the
// cores) and its split into contact detection, assembly, linear solve and
// open-close update (the stopwatch fractions of the process statistics);
// open-close iterations per step; the fitted cost exponent of contact
// detection (t ~ N^a). Solvers: auto (the default: the cheaper of pcg and
// GMRES with a reused factorization) and pcg (block-Jacobi CG / BiCGStab) at
// every size; direct (CHOLMOD / UMFPACK, a factorization per solve) and petsc
// up to 1,000 blocks, dynamic mode.
//
// Phase "later" steps a wall 200 steps first and then measures the next
// `steps`: the 1,000-block wall with auto and pcg, the static 10,000-block
// wall with auto. Phase "whole" is a whole static settle from rest, steps
// 1-300, with auto at 1,000 and 10,000 blocks: the mean cost per step of
// settling an assembly.
//
// Usage: bench_dda_scaling [steps=40] [OUTPUT.csv]
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "core/base/stopwatch.h"
#include "mechanics/dda/dda_process.h"
#include "mechanics/dda/dda_settings.h"
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
  double iterations = 0;                                                     // per step
  long steps = 0, cuts = 0;
  double cpu = 0;      // s per step, measured by the child (windows after kSettle steps)
  double mean_dt = 0;  // s, simulated time / accepted steps
  char status[16] = "";
};

Scene wall_scene(const Size& size, LinearSolverControls::Type solver, double k01) {
  const double dt = 1e-3;
  Scene s = testing::brick_wall_scene(size.courses, size.bricks, 1.0, 0.5, 30, dt, 0, 1.0);
  mechanics_controls(s).dda.penalty.reset();
  const double w = 0.5 * (size.bricks + 2);  // half the larger side of the model
  mechanics_controls(s).dda.max_displacement_ratio = 0.02 / w;
  mechanics_controls(s).dda.solver.type = solver;
  mechanics_controls(s).dda.solver.relative_tolerance = 1e-10;
  mechanics_controls(s).dda.velocity_carry_over = k01;
  return s;
}

/// Steps `settle` + `steps` of the wall with the DDA process alone and
/// reports the last `steps`: the cost once the impact transient is over.
Row run_later_window(const Size& size, LinearSolverControls::Type solver, double k01, int settle,
                     int steps) {
  const Scene s = wall_scene(size, solver, k01);
  RockMass state = RockMass::from_scene(s);
  dda::DdaProcess dda(s);
  dda.initialize(state);
  double t = 0, t0 = 0, cpu0 = 0;
  nlohmann::json m0;
  Row row;
  for (int accepted = 0; accepted < settle + steps;) {
    if (accepted == settle && m0.is_null()) {
      m0 = dda.statistics();
      cpu0 = process_cpu_seconds();
      t0 = t;
    }
    const double dt = dda.proposed_dt(state);
    const StepReport r = dda.advance(state, t, dt);
    if (r.status == StepReport::Status::Ok) {
      t += dt;
      ++accepted;
    }
  }
  const nlohmann::json m1 = dda.statistics();
  // Growth of a counter over the window, and its mean per step.
  auto grown = [&](const nlohmann::json::json_pointer& key) {
    return m1[key].get<double>() - m0[key].get<double>();
  };
  auto per_step = [&](const char* key) { return grown(nlohmann::json::json_pointer(key)) / steps; };
  row.blocks = static_cast<int>(s.blocks.size()) - 1;
  row.steps = steps;
  row.cpu = (process_cpu_seconds() - cpu0) / steps;
  row.mean_dt = (t - t0) / steps;
  row.detection = per_step("/seconds/contact_detection");
  row.assembly = per_step("/seconds/assembly");
  row.solve = per_step("/seconds/solve");
  row.open_close = per_step("/seconds/open_close");
  row.total = row.detection + row.assembly + row.solve + row.open_close;
  row.iterations = per_step("/open_close_iterations");
  row.cuts =
      static_cast<long>(grown(nlohmann::json::json_pointer("/time_step_cuts/open_close")) +
                        grown(nlohmann::json::json_pointer("/time_step_cuts/displacement_ratio")));
  std::snprintf(row.status, sizeof row.status, "completed");
  return row;
}

Row run_case(const Size& size, LinearSolverControls::Type solver, double k01, double steps) {
  Scene s = wall_scene(size, solver, k01);
  s.time.max_steps = static_cast<long>(steps);
  const testing::RunResult r = testing::run_scene(s, "bench_dda_scaling");
  const auto& m = r.summary.processes["mechanics"];
  Row row;
  row.blocks = static_cast<int>(s.blocks.size()) - 1;
  row.steps = m["steps"].get<long>();
  const double n = std::max<long>(row.steps, 1);
  row.mean_dt = r.summary.simulated_time / n;
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

/// Runs `work` in a child process (its peak memory and CPU time are its own);
/// false if the child failed.
bool in_child(const std::function<Row()>& work, Row& row, rusage& usage) {
  int pipe_fd[2];
  if (pipe(pipe_fd) != 0) return false;
  const pid_t pid = fork();
  if (pid == 0) {
    close(pipe_fd[0]);
    const Row r = work();
    if (write(pipe_fd[1], &r, sizeof r) != sizeof r) _exit(1);
    _exit(0);
  }
  close(pipe_fd[1]);
  const bool ok = read(pipe_fd[0], &row, sizeof row) == sizeof row;
  close(pipe_fd[0]);
  int status = 0;
  wait4(pid, &status, 0, &usage);
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  const double steps = argc > 1 ? std::atof(argv[1]) : 40;
  const std::string csv =
      argc > 2 ? argv[2] : FISSURE_SOURCE_DIR "/benchmarks/dda_scaling/results.csv";
  // 10,000 blocks as a long low wall: see docs/performance.md for the 50 x 200
  // wall, on which block-Jacobi CG does not converge.
  const std::vector<Size> sizes = {{10, 10}, {20, 50}, {20, 500}};
  const std::vector<std::pair<const char*, LinearSolverControls::Type>> solvers = {
      {"auto", LinearSolverControls::Type::Auto},
      {"pcg", LinearSolverControls::Type::Pcg},
      {"direct", LinearSolverControls::Type::Direct},
      {"petsc", LinearSolverControls::Type::Petsc}};
  constexpr int kSettle = 200;  // steps before the later window
  // The default and the matrix-free solver run at every size and window.
  auto at_every_size = [](LinearSolverControls::Type solver) {
    return solver == LinearSolverControls::Type::Auto || solver == LinearSolverControls::Type::Pcg;
  };

  struct Mode {
    const char* name;
    double k01;
  };
  const Mode modes[] = {{"dynamic", 1.0}, {"static", 0.0}};

  std::ofstream out(csv);
  out << "solver,blocks,mode,phase,steps,status,cuts,iterations_per_step,mean_dt_s,cpu_s,"
         "detection_s,assembly_s,solve_s,open_close_s,peak_memory_mb\n";
  std::printf("%-7s %7s %-8s %-9s %6s %10s %5s %6s %8s %9s %9s %9s %9s %9s %8s\n", "solver",
              "blocks", "mode", "phase", "steps", "status", "cuts", "its", "dt_ms", "cpu_ms",
              "detect", "assembly", "solve", "oc", "peak_MB");
  std::vector<double> log_n, log_detect;
  auto report = [&](const char* solver_name, const char* mode, const char* phase, const Row& row,
                    const rusage& usage) {
    const double cpu = usage.ru_utime.tv_sec + 1e-6 * usage.ru_utime.tv_usec +
                       usage.ru_stime.tv_sec + 1e-6 * usage.ru_stime.tv_usec;
    const double per_step = row.cpu > 0 ? row.cpu : cpu / std::max<long>(row.steps, 1);
    // The stopwatch split (wall) scaled to the CPU time per step.
    const double scale = row.total > 0 ? per_step / row.total : 0;
    const double parts[] = {row.detection * scale, row.assembly * scale, row.solve * scale,
                            row.open_close * scale};
    const double peak_mb = usage.ru_maxrss / 1024.0;
    std::printf(
        "%-7s %7d %-8s %-9s %6ld %10s %5ld %6.2f %8.3f %9.2f %9.2f %9.2f %9.2f %9.2f %8.1f\n",
        solver_name, row.blocks, mode, phase, row.steps, row.status, row.cuts, row.iterations,
        1e3 * row.mean_dt, 1e3 * per_step, 1e3 * parts[0], 1e3 * parts[1], 1e3 * parts[2],
        1e3 * parts[3], peak_mb);
    std::fflush(stdout);
    out << solver_name << ',' << row.blocks << ',' << mode << ',' << phase << ',' << row.steps
        << ',' << row.status << ',' << row.cuts << ',' << row.iterations << ',' << row.mean_dt
        << ',' << per_step << ',' << parts[0] << ',' << parts[1] << ',' << parts[2] << ','
        << parts[3] << ',' << peak_mb << '\n';
    return parts[0];
  };
  for (const Mode& mode : modes)
    for (const auto& [solver_name, solver] : solvers)
      for (const Size& size : sizes) {
        // Direct and PETSc: dynamic mode, up to 1,000 blocks.
        if (!at_every_size(solver) && (size.courses * size.bricks > 2000 || mode.k01 == 0))
          continue;
        Row row;
        rusage usage{};
        if (!in_child([&] { return run_case(size, solver, mode.k01, steps); }, row, usage)) {
          std::printf("%-7s %7d   failed\n", solver_name, size.courses * size.bricks);
          continue;
        }
        const double detection = report(solver_name, mode.name, "transient", row, usage);
        if (solver == LinearSolverControls::Type::Auto && mode.k01 == 1) {
          log_n.push_back(std::log(row.blocks));
          log_detect.push_back(std::log(detection));
        }
      }
  // Steps kSettle + 1 ... kSettle + steps: auto and pcg on the 1,000-block
  // wall, and auto on the 10,000-block wall in static mode (the mode that
  // settles; 240 steps take ~8 minutes there, pcg would take ~20).
  for (const Mode& mode : modes)
    for (const auto& [solver_name, solver] : solvers)
      for (const Size& size : {sizes[1], sizes[2]}) {
        const bool large = size.courses * size.bricks > 2000;
        if (!at_every_size(solver) ||
            (large && (solver != LinearSolverControls::Type::Auto || mode.k01 != 0)))
          continue;
        Row row;
        rusage usage{};
        const int n = static_cast<int>(steps);
        if (!in_child([&] { return run_later_window(size, solver, mode.k01, kSettle, n); }, row,
                      usage)) {
          std::printf("%-7s %7d   later window failed\n", solver_name, size.courses * size.bricks);
          continue;
        }
        report(solver_name, mode.name, "later", row, usage);
      }
  // A whole static settle from rest, steps 1 ... kWholeSettle, auto: what
  // settling an assembly costs per step on average (the from-rest window and
  // the settled one are its two ends; ~2 minutes at 10,000 blocks).
  constexpr int kWholeSettle = 300;
  for (const Size& size : {sizes[1], sizes[2]}) {
    Row row;
    rusage usage{};
    if (!in_child(
            [&] {
              return run_later_window(size, LinearSolverControls::Type::Auto, 0.0, 0, kWholeSettle);
            },
            row, usage)) {
      std::printf("auto    %7d   whole settle failed\n", size.courses * size.bricks);
      continue;
    }
    report("auto", "static", "whole", row, usage);
  }
  // Least-squares slope of log(detection time) against log(N).
  if (log_n.size() >= 2) {
    const double m = static_cast<double>(log_n.size());
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t k = 0; k < log_n.size(); ++k) {
      sx += log_n[k], sy += log_detect[k];
      sxx += log_n[k] * log_n[k], sxy += log_n[k] * log_detect[k];
    }
    std::printf("contact detection cost exponent (auto, transient): %.3f\n",
                (m * sxy - sx * sy) / (m * sxx - sx * sx));
  }
  return 0;
}
