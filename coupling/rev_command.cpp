#include "coupling/rev_command.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "core/base/errors.h"

#include "core/io/summary_writer.h"
#include "coupling/output_folder.h"
#include "coupling/plot_script.h"
#include "coupling/process_registry.h"
#include "coupling/upscaling/scene_rock_mass_source.h"
#include "coupling/upscaling/stress_study.h"
#include "flow/rev/read_rev_study.h"
#include "flow/rev/rev_dfn_source.h"
#include "flow/rev/rev_mpi.h"
#include "flow/rev/rev_output.h"
#include "flow/rev/rev_study.h"

namespace fissure {

namespace {

/// The items of `all` that a short check's option (--states, --sizes) names
/// by index; an index the study does not have is refused at `location`.
template <class T>
std::vector<T> chosen_items(const std::vector<T>& all, const std::vector<int>& indices,
                            const std::string& location, const char* option, const char* item) {
  std::vector<T> chosen;
  for (int k : indices) {
    FISSURE_CHECK(k >= 0 && k < static_cast<int>(all.size()), SceneError,
                  location << ": " << option << " names " << item << " " << k
                           << ", but the study has " << all.size()
                           << "; expected indices below it (from 0)");
    chosen.push_back(all[k]);
  }
  return chosen;
}

/// The stress stage (docs/upscaling.md): every state's study, its tables,
/// a summary and the plot.
int run_stress_stage(const RevCommand& command, const flow::RevStudy& study,
                     const StressStudyConfig& mechanics, const std::string& outdir,
                     const flow::ParallelContext& parallel) {
  const auto* source = dynamic_cast<const SceneRockMassSource*>(study.source.get());
  FISSURE_CHECK(source, SceneError,
                mechanics.location << ": found a mechanics section with a network of type other "
                                      "than scene; expected network: {type: scene, scene: FILE} "
                                      "(the rock mass's joints and material)");
  const std::vector<StressStateResult> results =
      run_stress_study(study.config, mechanics, *source, parallel);
  if (parallel.rank != 0) return 0;
  write_stress_study(results, outdir);
  double wall = 0;
  for (const StressStateResult& r : results) wall += r.rev.wall_seconds;
  std::printf("%s: %zu stress states x %zu domains in %.2f s wall (%d threads x %d ranks)\n",
              study.config.name.c_str(), results.size(),
              results.empty() ? 0 : results.front().rev.domains.size(), wall,
              results.empty() ? 1 : results.front().rev.threads, parallel.size);
  for (const StressStateResult& r : results) {
    const flow::SizeStatistics& z = r.rev.sizes.back();
    const SizeMechanics m = size_mechanics(r.rev, static_cast<int>(r.rev.sizes.size()) - 1);
    std::printf(
        "  sigma_1' %7.3g MPa, sigma_3' %7.3g MPa (ratio %.3g): L = %g m: k_max %.4e, k_min "
        "%.4e, slip %.3f, at rest %.0f %%%s\n",
        r.principal.sigma_1 * 1e-6, r.principal.sigma_3 * 1e-6, r.principal.ratio(), z.size,
        z.mean_kmax, z.mean_kmin, m.slip, 100 * m.equilibrium,
        r.rev.rev_size ? fmt::format(", REV {:g} m", *r.rev.rev_size).c_str() : "");
  }
  std::printf("  results: %s/ (stress_states.csv, stress_domains.csv, stress.json)\n",
              outdir.c_str());
  if (command.plots) {
    if (run_plot_script("plot_rev_stress.py", outdir))
      std::printf("  plots: %s/rev_stress.png\n", outdir.c_str());
    else
      std::printf(
          "  plots: not made (needs python3 with matplotlib: scripts/plot_rev_stress.py)\n");
  }
  return 0;
}

}  // namespace

int rev_command(const RevCommand& command) {
  // 1. Read the study; every rank reads it (it is small). A rock-mass
  //    scene (network.type: scene) is read by the scene reader, relative
  //    to the study's folder.
  std::optional<StressStudyConfig> mechanics;
  flow::RevStudyReaders readers;
  readers.dfn = rev_dfn_source_factory();
  const std::filesystem::path folder = std::filesystem::path(command.study_file).parent_path();
  readers.scene = [&folder](
                      const ConfigNode& node,
                      const std::optional<Vec2>& centre) -> std::unique_ptr<flow::DomainSource> {
    const std::optional<std::string> file = node.string("a scene file");
    if (!file) return nullptr;
    auto scene = std::make_shared<const Scene>(read_scene(folder / *file));
    return std::make_unique<SceneRockMassSource>(std::move(scene), centre);
  };
  readers.mechanics = [&mechanics](const ConfigNode& node) {
    read_stress_study(node, mechanics.emplace());
  };
  flow::RevStudy study = flow::read_rev_study(command.study_file, readers);
  if (command.threads > 0) study.config.threads = command.threads;
  if (command.realizations > 0) study.config.realizations = command.realizations;
  if (!command.sizes.empty()) {
    // In increasing order, as the study's (its statistics and REV criterion
    // run along the sizes).
    std::vector<int> indices = command.sizes;
    std::ranges::sort(indices);
    indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
    study.config.sizes =
        chosen_items(study.config.sizes, indices, study.config.sizes_location, "--sizes", "size");
  }
  const bool chosen = !command.outdir.empty();
  const std::string outdir =
      chosen ? command.outdir : default_output_folder(command.study_file, "rev").string();
  const auto warning =
      check_output_folder(outdir, kRevRecord, command.study_file, study.config.name, chosen);

  // 2. Run it: threads here, and the other ranks when launched by mpirun.
  const flow::ParallelContext parallel = flow::mpi_context();
  if (!command.quiet && parallel.rank == 0)
    std::printf(
        "%s: %s\n  %zu sizes x %d realizations x %d rotations on %d rank(s), about %.3g network "
        "nodes\n",
        study.config.name.c_str(), study.source->describe().c_str(), study.config.sizes.size(),
        study.config.realizations, study.config.rotations, parallel.size,
        flow::expected_study_nodes(study.config, *study.source));
  if (warning && parallel.rank == 0) std::fprintf(stderr, "warning: %s\n", warning->c_str());
  if (mechanics) {
    if (!command.states.empty())
      mechanics->states =
          chosen_items(mechanics->states, command.states, mechanics->location, "--states", "state");
    return run_stress_stage(command, study, *mechanics, outdir, parallel);
  }
  flow::RevStudyResult r = flow::run_rev_study(study.config, *study.source, parallel);
  if (parallel.rank != 0) return 0;
  r.study_file = recorded_file_path(command.study_file);

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
  if (command.plots) {
    if (run_plot_script("plot_rev.py", outdir))
      std::printf("  plots: %s/rev_size.png, %s/rev_polar.png\n", outdir.c_str(), outdir.c_str());
    else
      std::printf("  plots: not made (needs python3 with matplotlib: scripts/plot_rev.py)\n");
  }
  return 0;
}

}  // namespace fissure
