#include "coupling/rev_command.h"

#include <cstdio>
#include <filesystem>

#include "core/io/summary_writer.h"
#include "coupling/output_folder.h"
#include "coupling/plot_script.h"
#include "flow/rev/read_rev_study.h"
#include "flow/rev/rev_dfn_source.h"
#include "flow/rev/rev_mpi.h"
#include "flow/rev/rev_output.h"
#include "flow/rev/rev_study.h"

namespace fissure {

int rev_command(const RevCommand& command) {
  // 1. Read the study; every rank reads it (it is small).
  flow::RevStudy study = flow::read_rev_study(command.study_file, rev_dfn_source_factory());
  if (command.threads > 0) study.config.threads = command.threads;
  if (command.realizations > 0) study.config.realizations = command.realizations;
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
