// The coordinator owns time (architecture.md 1): it builds the processes the
// scene activates (process_registry.h), runs the time loop with the scene's
// splitting scheme (splitting.h) and step cuts on retry, and writes the
// output contract (results.h5/.xdmf, monitors.csv, summary.json) from what
// each process declares it writes. Whatever happens, the output written so
// far is kept and summary.json says how the run ended. It names no physics.
#pragma once

#include <filesystem>
#include <memory>
#include <vector>

#include "core/io/summary_writer.h"
#include "core/process/process.h"
#include "core/scene/scene.h"
#include "core/state/rock_mass.h"
#include "coupling/splitting.h"

namespace fissure {

struct RunOptions {
  std::filesystem::path outdir;
  bool progress_bar = false;  ///< redraw a bar in place (terminal)
  bool quiet = false;         ///< no progress output at all
};

class Coordinator {
 public:
  Coordinator(const Scene& scene, RunOptions options);
  ~Coordinator();

  /// Runs the scene to its end time; never throws for a failed run (the
  /// returned summary says why), only for failures to write output at all.
  RunSummary run();

  const RockMass& state() const { return state_; }

 private:
  class Output;

  void start();
  void advance_one_step(double dt);
  double next_step_size(double next_output) const;
  bool output_due(long step, double next_output) const;
  void summarize(RunSummary& summary) const;

  const Scene& scene_;
  RunOptions options_;
  RockMass state_;
  std::vector<std::unique_ptr<Process>> processes_;  ///< in the order they advance
  std::unique_ptr<LieSplitting> splitting_;
  std::vector<std::unique_ptr<ResultsPart>> shared_results_;  ///< fields no process owns
  long steps_ = 0;
  long cuts_ = 0;
};

}  // namespace fissure
