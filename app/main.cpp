// fissure: the command line (architecture.md 4).
//
//   fissure run SCENE.yaml [-o OUTDIR]    run a scene
//   fissure validate SCENE.yaml           check a scene without running it
//
// Exit codes: 0 success; 1 invalid scene or usage; 2 the run stopped early
// (diverged or failed; the output written so far and summary.json are kept).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>

#include "core/base/errors.h"
#include "core/base/progress.h"
#include "core/scene/parse_scene.h"
#include "coupling/coordinator.h"

namespace fs = std::filesystem;
using namespace fissure;

namespace {

int run_scene(const std::string& scene_file, std::string outdir, bool quiet) {
  // 1. Read and validate the scene; nothing runs on an invalid scene.
  const Scene scene = parse_scene(scene_file);
  if (outdir.empty()) outdir = (fs::path("out") / scene.name).string();

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
  for (const auto& [name, v] : s.monitors.items())
    std::printf("  monitor %-12s x = %.6g  y = %.6g  ux = %.4e  uy = %.4e m\n", name.c_str(),
                v["x"].get<double>(), v["y"].get<double>(), v["ux"].get<double>(),
                v["uy"].get<double>());
  return s.status == "completed" || s.status == "max_steps" ? 0 : 2;
}

int validate_scene(const std::string& scene_file) {
  const Scene scene = parse_scene(scene_file);
  std::printf("%s: valid (%zu blocks, %zu materials, %zu joints, %zu monitors)\n",
              scene_file.c_str(), scene.blocks.size(), scene.materials.size(),
              scene.joints.size(), scene.monitors.size());
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

  CLI::App* validate = app.add_subcommand("validate", "Check a scene without running it");
  validate->add_option("scene", scene_file, "Scene file (YAML)")
      ->required()
      ->check(CLI::ExistingFile);

  CLI11_PARSE(app, argc, argv);
  try {
    if (run->parsed()) return run_scene(scene_file, outdir, quiet);
    if (validate->parsed()) return validate_scene(scene_file);
  } catch (const SceneError& e) {
    std::fprintf(stderr, "error: invalid scene\n%s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  return 1;
}
