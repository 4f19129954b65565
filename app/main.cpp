// fissure: the command line (README.md "Command line").
//
//   fissure run SCENE.yaml [-o OUTDIR] [--max-steps N] [--end T] [--restart CHECKPOINT]
//               [--no-plots]
//                                         run a scene, or continue it from a checkpoint;
//                                         T in s, or with a unit: 1 yr, 30d
//                                         (docs/scene-reference.md section 2)
//   fissure validate SCENE.yaml           check a scene without running it
//   fissure mesh SCENE.yaml [-o OUTDIR]   generate the rock mass only: blocks, fracture graph,
//                                         picture (docs/rock-mass.md)
//   fissure rev STUDY.yaml [-o OUTDIR]    permeability upscaling (REV) study
//
// Without -o a command writes to out/<file stem>/ (out/rev/<file stem>/),
// and refuses that folder when it holds another file's results
// (coupling/output_folder.h; docs/output.md, "Output folder").
//
// Exit codes: 0 success; 1 invalid scene, usage, a default output folder
// that holds another file's results, or a refused restart; 2 the run stopped early
// (diverged, failed, or interrupted by SIGINT/SIGTERM after writing a
// checkpoint; the output written so far and summary.json are kept). Under
// mpirun every rank returns the same code and mpirun passes it on, except
// when mpirun itself is signalled: Open MPI's mpirun then exits 1 whatever
// the ranks return (docs/output.md, "Checkpoint and restart").
#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <new>
#include <string>

#include "core/base/errors.h"
#include "core/base/memory_budget.h"
#include "core/base/progress.h"
#include "core/parallel/mpi_world.h"
#include "core/scene/units.h"
#include "coupling/checkpoint_file.h"
#include "coupling/coordinator.h"
#include "coupling/mesh_command.h"
#include "coupling/output_folder.h"
#include "coupling/plot_script.h"
#include "coupling/process_registry.h"
#include "coupling/rev_command.h"

namespace fs = std::filesystem;
using namespace fissure;

namespace {

/// Deprecated keys and other warnings of a scene, on stderr.
void print_warnings(const Scene& scene) {
  for (const std::string& w : scene.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
}

int run_scene(const std::string& scene_file, std::string outdir, bool quiet, long max_steps,
              double end, const std::string& restart, bool plots) {
  // Under mpirun every rank runs the scene, sharing the work of the
  // processes that can (their PETSc solvers); rank 0 writes and prints.
  parallel::ensure_started();
  const bool root = parallel::rank() == 0;
  quiet = quiet || !root;

  // 1. Read and validate the scene, every module's section with it
  // (generating its rock mass, if any); nothing runs on an invalid scene.
  Scene scene = read_scene(scene_file);
  if (root) print_warnings(scene);
  // A restart continues the files beside its checkpoint (which must be of
  // this scene: checkpoint_file.h); otherwise the folder must not hold
  // another scene's results, unless chosen with -o (output_folder.h).
  if (restart.empty()) {
    const bool chosen = !outdir.empty();
    if (!chosen) outdir = default_output_folder(scene_file).string();
    const auto warning = check_output_folder(outdir, kRunRecord, scene_file, scene.name, chosen);
    if (warning && root) std::fprintf(stderr, "warning: %s\n", warning->c_str());
  } else if (outdir.empty()) {
    outdir = fs::absolute(restart).parent_path().string();
  }
  if (max_steps > 0) scene.time.max_steps = max_steps;  // short variants (CI)
  // A short variant that ends at a time: its last frame is at the same
  // simulated time on every machine (a step count is not, where round-off
  // changes the adaptive steps).
  if (end > 0) scene.time.end_time = std::min(scene.time.end_time, end);

  // 2. Run it.
  RunOptions options;
  options.outdir = outdir;
  options.quiet = quiet;
  options.progress_bar = !quiet && Progress::stderr_is_terminal();
  options.restart = restart;
  options.write_files = root;
  Coordinator coordinator(scene, options);
  const RunSummary s = coordinator.run();
  if (!root) return s.status == "completed" || s.status == "max_steps" ? 0 : 2;

  // 3. Say where the results are and what they show.
  std::printf("%s: %s after %ld steps, t = %.6g s, wall %.2f s\n", scene.name.c_str(),
              s.status.c_str(), s.steps, s.simulated_time, s.wall_seconds);
  if (!s.message.empty()) std::printf("  reason: %s\n", s.message.c_str());
  std::printf("  results: %s/ (results.xdmf for ParaView, monitors.csv, summary.json)\n",
              outdir.c_str());
  for (const auto& [name, v] : s.monitors.items()) {
    // The brief columns of the active processes (position, displacement, ...).
    std::string line = fmt::format("  monitor {:<12}", name);
    for (const std::string& key : s.brief_monitor_columns)
      if (v.contains(key) && v[key].is_number()) {
        // No value (a monitor off the fracture network has no pressure):
        // "none", as summary.json's null, not "nan".
        const double x = v[key].get<double>();
        line += std::isfinite(x) ? fmt::format("  {} = {:.6g}", key, x)
                                 : fmt::format("  {} = none", key);
      }
    std::printf("%s\n", line.c_str());
  }

  // 4. The pictures (python3 with h5py and matplotlib, when available); not
  // after Ctrl-C or a batch system's SIGTERM, which want the program to end.
  if (plots && s.status != "interrupted") {
    std::fflush(stdout);  // before the scripts' processes start
    draw_run_pictures(outdir);
  }
  return s.status == "completed" || s.status == "max_steps" ? 0 : 2;
}

/// A command-line time read as the scene reads one (core/scene/units.h):
/// seconds, or a number with its unit ("1 yr", "30d"); > 0. CLI11 reports a
/// problem with the option's name ("--end: found '3 fortnights' with
/// unknown unit ...").
CLI::Validator time_option() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        try {
          const double seconds = to_si(text, quantity::time);
          if (!(seconds > 0)) return fmt::format("found '{}'; expected a time > 0", text);
          text = fmt::format("{:.17g}", seconds);  // CLI11 reads the seconds back exactly
          return {};
        } catch (const UnitError& e) {
          return e.what();
        }
      },
      "TIME");
}

int validate_scene(const std::string& scene_file) {
  const Scene scene = read_scene(scene_file);
  print_warnings(scene);
  // What the run checks before its first step, too: a flow boundary no
  // fracture reaches or a heat source outside the rock is found only once
  // the network and the meshes exist.
  Coordinator(scene, RunOptions{}).check();
  std::printf("%s: valid (%zu blocks, %zu materials, %zu joints, %zu monitors)\n",
              scene_file.c_str(), scene.blocks.size(), scene.materials.size(), scene.joints.size(),
              scene.monitors.size());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Fissure: coupled thermo-hydro-mechanical analysis of fractured rock"};
  app.require_subcommand(1);

  std::string scene_file, outdir;
  bool quiet = false;
  CLI::App* run = app.add_subcommand("run", "Run a scene");
  run->add_option("scene", scene_file, "Scene file (YAML)")->required()->check(CLI::ExistingFile);
  run->add_option("-o,--output", outdir,
                  "Output folder (default: out/<scene file stem>, refused when it holds the "
                  "results of another scene file)");
  run->add_flag("-q,--quiet", quiet, "No progress output");
  long max_steps = 0;
  run->add_option("--max-steps", max_steps,
                  "Stop after this many steps (overrides time.max_steps; for short checks)")
      ->check(CLI::PositiveNumber);
  double end = 0;
  run->add_option("--end", end,
                  "Stop at this simulated time if before time.end (for short checks): seconds, "
                  "or a time with its unit, as in the scene (1 yr, 30d, 2.5 h)")
      ->transform(time_option());
  std::string restart;
  run->add_option("--restart", restart,
                  "Continue the run from this checkpoint (OUTDIR/checkpoint.h5; the output folder "
                  "defaults to the checkpoint's)")
      ->check(CLI::ExistingFile);
  bool no_run_plots = false;
  run->add_flag("--no-plots", no_run_plots, "Do not draw monitors.png and final_state.png");

  CLI::App* validate = app.add_subcommand("validate", "Check a scene without running it");
  validate->add_option("scene", scene_file, "Scene file (YAML)")
      ->required()
      ->check(CLI::ExistingFile);

  bool no_plot = false;
  CLI::App* mesh = app.add_subcommand(
      "mesh",
      "Generate a scene's rock mass (its blocks and joint network) without running physics; "
      "writes results.h5/.xdmf, summary.json and rock_mass.png");
  mesh->add_option("scene", scene_file, "Scene file (YAML)")->required()->check(CLI::ExistingFile);
  mesh->add_option("-o,--output", outdir,
                   "Output folder (default: out/<scene file stem>, refused when it holds the "
                   "results of another scene file)");
  mesh->add_flag("--no-plot", no_plot, "Do not draw rock_mass.png");

  RevCommand rev_options;
  bool no_plots = false;
  CLI::App* rev = app.add_subcommand(
      "rev",
      "Permeability upscaling (REV) study of a DFN (docs/flow.md); under mpirun the "
      "realizations are shared among the ranks");
  rev->add_option("study", rev_options.study_file, "Study file (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  rev->add_option("-o,--output", rev_options.outdir,
                  "Output folder (default: out/rev/<study file stem>, refused when it holds the "
                  "results of another study file)");
  rev->add_option("-j,--threads", rev_options.threads,
                  "Threads per rank (default: the study's, else all)");
  rev->add_option("--realizations", rev_options.realizations,
                  "Realizations per size (overrides the study's; for short checks)")
      ->check(CLI::PositiveNumber);
  rev->add_option("--states", rev_options.states,
                  "Under stress: only these stress states (0-based indices into the "
                  "study's list of stresses; for short checks)")
      ->delimiter(',')
      ->check(CLI::NonNegativeNumber);
  rev->add_option("--sizes", rev_options.sizes,
                  "Only these sizes (0-based indices into the study's list of sizes; for "
                  "short checks)")
      ->delimiter(',')
      ->check(CLI::NonNegativeNumber);
  rev->add_flag("--no-plots", no_plots, "Do not make the PNG plots");
  rev->add_flag("-q,--quiet", rev_options.quiet, "Less output");

  // Every command: the memory budget its scene is checked against before
  // anything large is allocated (core/base/memory_budget.h).
  std::string memory_limit;
  const CLI::Validator memory_size(
      [](std::string& text) -> std::string {
        try {
          parse_memory_size(text);
        } catch (const Error& e) {
          return e.what();
        }
        return {};
      },
      "SIZE");
  for (CLI::App* command : {run, validate, mesh, rev})
    command
        ->add_option("--memory-limit", memory_limit,
                     "Memory the command may use, such as 8 GB (default: what the machine has "
                     "available); scenes that need more are refused before they start")
        ->check(memory_size);

  // A usage error (an unknown option, a value an option refuses) exits 1, as
  // an invalid scene does, with CLI11's message naming the option; --help 0.
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 1;
  }
  if (!memory_limit.empty()) set_memory_budget(parse_memory_size(memory_limit));
  try {
    if (run->parsed())
      return run_scene(scene_file, outdir, quiet, max_steps, end, restart, !no_run_plots);
    if (validate->parsed()) return validate_scene(scene_file);
    if (mesh->parsed()) return mesh_command(scene_file, outdir, !no_plot);
    if (rev->parsed()) {
      rev_options.plots = !no_plots;
      return rev_command(rev_options);
    }
  } catch (const SceneError& e) {
    std::fprintf(stderr, "error: invalid scene\n%s\n", e.what());
    return 1;
  } catch (const OutputFolderError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  } catch (const RestartRefused& e) {
    std::fprintf(stderr, "error: the restart is refused, nothing was written: %s\n", e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    // An allocation no estimate foresaw (the estimates refuse what cannot
    // fit before it starts: docs/performance.md, "Memory").
    std::fprintf(stderr,
                 "error: out of memory: `fissure %s %s` needed more than the machine gave it "
                 "(%s were available at the start); expected a smaller scene, or more memory\n",
                 app.get_subcommands().front()->get_name().c_str(),
                 (scene_file.empty() ? rev_options.study_file : scene_file).c_str(),
                 format_bytes(memory_budget()).c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  return 1;
}
