// fissure: the command line (architecture.md 4).
//
//   fissure run SCENE.yaml [-o OUTDIR] [--max-steps N]    run a scene
//   fissure validate SCENE.yaml           check a scene without running it
//   fissure mesh SCENE.yaml [-o OUTDIR]   generate the rock mass only: blocks, fracture graph,
//                                         picture (docs/rock-mass.md)
//   fissure rev STUDY.yaml [-o OUTDIR]    permeability upscaling (REV) study
//
// Exit codes: 0 success; 1 invalid scene or usage; 2 the run stopped early
// (diverged or failed; the output written so far and summary.json are kept).
#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>

#include "core/base/errors.h"
#include "core/base/progress.h"
#include "core/scene/parse_scene.h"
#include "coupling/coordinator.h"
#include "coupling/rev_sources.h"
#include "flow/rev/read_rev_study.h"
#include "flow/rev/rev_mpi.h"
#include "flow/rev/rev_output.h"
#include "rockmass/generate_rock_mass.h"
#include "rockmass/rock_mass_output.h"

namespace fs = std::filesystem;
using namespace fissure;

namespace {

int run_scene(const std::string& scene_file, std::string outdir, bool quiet, long max_steps) {
  // 1. Read and validate the scene (generating its rock mass, if any);
  // nothing runs on an invalid scene.
  Scene scene = parse_scene(scene_file, scene_generators());
  if (outdir.empty()) outdir = (fs::path("out") / scene.name).string();
  if (max_steps > 0) scene.time.max_steps = max_steps;  // short variants (CI)

  // 2. Run it.
  RunOptions options;
  options.outdir = outdir;
  options.quiet = quiet;
  options.progress_bar = !quiet && Progress::stderr_is_terminal();
  Coordinator coordinator(scene, options);
  const RunSummary s = coordinator.run();

  // 3. Say where the results are and what they show.
  std::printf("%s: %s after %ld steps, t = %.6g s, wall %.2f s\n", scene.name.c_str(),
              s.status.c_str(), s.steps, s.simulated_time, s.wall_seconds);
  if (!s.message.empty()) std::printf("  reason: %s\n", s.message.c_str());
  std::printf("  results: %s/ (results.xdmf for ParaView, monitors.csv, summary.json)\n",
              outdir.c_str());
  for (const auto& [name, v] : s.monitors.items()) {
    // The values the active processes wrote (mechanics: x, y, ux, uy; flow: p).
    std::string line = fmt::format("  monitor {:<12}", name);
    for (const char* key : {"x", "y", "ux", "uy", "p"})
      if (v.contains(key) && v[key].is_number())
        line += fmt::format("  {} = {:.6g}", key, v[key].get<double>());
    std::printf("%s\n", line.c_str());
  }
  return s.status == "completed" || s.status == "max_steps" ? 0 : 2;
}

int validate_scene(const std::string& scene_file) {
  const Scene scene = parse_scene(scene_file, scene_generators());
  std::printf("%s: valid (%zu blocks, %zu materials, %zu joints, %zu monitors)\n",
              scene_file.c_str(), scene.blocks.size(), scene.materials.size(), scene.joints.size(),
              scene.monitors.size());
  return 0;
}

int mesh_scene(const std::string& scene_file, std::string outdir, bool plot) {
  // 1. Read the scene; its rock mass is generated while it is parsed.
  const Scene scene = parse_scene(scene_file, scene_generators());
  if (outdir.empty()) outdir = (fs::path("out") / scene.name).string();

  // 2. Blocks and fracture graph as frame 0, summary.json with the counts.
  write_rock_mass(scene, outdir);
  const nlohmann::json s = rock_mass_summary(scene);
  std::printf("%s: %zu blocks (%d fixed), %d fracture segments (%d nodes) from %ld fractures\n",
              scene.name.c_str(), scene.blocks.size(), s["fixed_blocks"].get<int>(),
              s["segments"].get<int>(), s["nodes"].get<int>(), s["fractures_in_rock"].get<long>());
  std::printf("  network: %d components (%d isolated, %d dead-end), %d dead-end segments\n",
              s["components"].get<int>(), s["isolated_components"].get<int>(),
              s["dead_end_components"].get<int>(), s["dead_end_segments"].get<int>());
  for (const auto& [pair, yes] : s["percolation"].items())
    if (yes.get<bool>()) std::printf("  percolates: %s\n", pair.c_str());
  std::printf("  generation %.3f s, cutting %.3f s\n", s["generation_seconds"].get<double>(),
              s["cutting_seconds"].get<double>());
  std::printf("  results: %s/ (results.xdmf for ParaView, summary.json)\n", outdir.c_str());

  // 3. The picture (python3 with h5py and matplotlib, when available).
  if (plot) {
    const std::string python = fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
    const std::string command =
        python + " " + FISSURE_SCRIPTS_DIR + "/plot_rock_mass.py '" + outdir + "' > /dev/null 2>&1";
    if (std::system(command.c_str()) == 0)
      std::printf("  picture: %s/rock_mass.png\n", outdir.c_str());
    else
      std::printf(
          "  picture: not made (needs python3 with h5py and matplotlib: "
          "scripts/plot_rock_mass.py)\n");
  }
  return 0;
}

int run_rev(const std::string& study_file, std::string outdir, int threads, int realizations,
            bool plots, bool quiet) {
  // 1. Read the study; every rank reads it (it is small).
  flow::RevStudy study = flow::read_rev_study(study_file, rev_dfn_source_factory());
  if (threads > 0) study.config.threads = threads;
  if (realizations > 0) study.config.realizations = realizations;  // short variants (CI)
  if (outdir.empty()) outdir = (fs::path("out") / "rev" / study.config.name).string();

  // 2. Run it: threads here, and the other ranks when launched by mpirun.
  const flow::ParallelContext parallel = flow::mpi_context();
  if (!quiet && parallel.rank == 0)
    std::printf("%s: %s\n  %zu sizes x %d realizations x %d rotations on %d rank(s)\n",
                study.config.name.c_str(), study.source->describe().c_str(),
                study.config.sizes.size(), study.config.realizations, study.config.rotations,
                parallel.size);
  const flow::RevStudyResult r = flow::run_rev_study(study.config, *study.source, parallel);
  if (parallel.rank != 0) return 0;

  // 3. CSV + JSON, then the plots (python3 with matplotlib, when available).
  flow::write_rev_output(r, outdir);
  std::printf("%s: %zu domains in %.2f s wall (%d threads x %d ranks)\n", study.config.name.c_str(),
              r.domains.size(), r.wall_seconds, r.threads, r.ranks);
  for (const flow::SizeStatistics& s : r.sizes)
    std::printf("  L = %6.3g m: k_max %.4e (CV %.3f), k_min %.4e (CV %.3f), misfit %.3f%s\n",
                s.size, s.mean_kmax, s.cv_kmax, s.mean_kmin, s.cv_kmin, s.mean_misfit,
                s.meets_criterion ? "  representative" : "");
  if (r.rev_size)
    std::printf("  REV size: %.4g m\n", *r.rev_size);
  else
    std::printf("  REV size: not reached within the sizes studied\n");
  std::printf("  results: %s/ (domains.csv, fits.csv, sizes.csv, rev.json)\n", outdir.c_str());
  if (plots) {
    const std::string python = fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
    const std::string command =
        python + " " + FISSURE_SCRIPTS_DIR + "/plot_rev.py '" + outdir + "' > /dev/null 2>&1";
    if (std::system(command.c_str()) == 0)
      std::printf("  plots: %s/rev_size.png, %s/rev_polar.png\n", outdir.c_str(), outdir.c_str());
    else
      std::printf("  plots: not made (needs python3 with matplotlib: scripts/plot_rev.py)\n");
  }
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
  run->add_option("-o,--output", outdir, "Output folder (default: out/<scene name>)");
  run->add_flag("-q,--quiet", quiet, "No progress output");
  long max_steps = 0;
  run->add_option("--max-steps", max_steps,
                  "Stop after this many steps (overrides time.max_steps; for short checks)")
      ->check(CLI::PositiveNumber);

  CLI::App* validate = app.add_subcommand("validate", "Check a scene without running it");
  validate->add_option("scene", scene_file, "Scene file (YAML)")
      ->required()
      ->check(CLI::ExistingFile);

  bool no_plot = false;
  CLI::App* mesh = app.add_subcommand(
      "mesh",
      "Generate a scene's rock mass (blocks and fracture graph) without running physics; "
      "writes results.h5/.xdmf, summary.json and rock_mass.png");
  mesh->add_option("scene", scene_file, "Scene file (YAML)")->required()->check(CLI::ExistingFile);
  mesh->add_option("-o,--output", outdir, "Output folder (default: out/<scene name>)");
  mesh->add_flag("--no-plot", no_plot, "Do not draw rock_mass.png");

  std::string study_file;
  int threads = 0, realizations = 0;
  bool no_plots = false;
  CLI::App* rev = app.add_subcommand(
      "rev",
      "Permeability upscaling (REV) study of a DFN (docs/flow.md); under mpirun the "
      "realizations are shared among the ranks");
  rev->add_option("study", study_file, "Study file (YAML)")->required()->check(CLI::ExistingFile);
  rev->add_option("-o,--output", outdir, "Output folder (default: out/rev/<study name>)");
  rev->add_option("-j,--threads", threads, "Threads per rank (default: the study's, else all)");
  rev->add_option("--realizations", realizations,
                  "Realizations per size (overrides the study's; for short checks)")
      ->check(CLI::PositiveNumber);
  rev->add_flag("--no-plots", no_plots, "Do not make the PNG plots");
  rev->add_flag("-q,--quiet", quiet, "Less output");

  CLI11_PARSE(app, argc, argv);
  try {
    if (run->parsed()) return run_scene(scene_file, outdir, quiet, max_steps);
    if (validate->parsed()) return validate_scene(scene_file);
    if (mesh->parsed()) return mesh_scene(scene_file, outdir, !no_plot);
    if (rev->parsed()) return run_rev(study_file, outdir, threads, realizations, !no_plots, quiet);
  } catch (const SceneError& e) {
    std::fprintf(stderr, "error: invalid scene\n%s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  return 1;
}
