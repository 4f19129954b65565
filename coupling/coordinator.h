// The coordinator owns time (docs/architecture.md 3): it builds the processes the
// scene activates (process_registry.h), runs the time loop with the scene's
// splitting scheme (splitting.h) and step cuts on retry, and writes the
// output contract (results.h5/.xdmf, monitors.csv, summary.json) from what
// each process declares it writes. Whatever happens, the output written so
// far is kept and summary.json says how the run ended. It writes
// checkpoints (checkpoint_file.h) when the scene asks and when SIGINT or
// SIGTERM stop the run, and continues a run from one. It names no physics.
#pragma once

#include <filesystem>
#include <memory>
#include <string_view>
#include <vector>

#include "core/io/summary_writer.h"
#include "core/process/process.h"
#include "core/scene/scene.h"
#include "core/state/rock_mass.h"
#include "coupling/checkpoint_file.h"
#include "coupling/splitting.h"

namespace fissure {

struct RunOptions {
  std::filesystem::path outdir;
  bool progress_bar = false;  ///< redraw a bar in place (terminal)
  bool quiet = false;         ///< no progress output at all
  /// A checkpoint to continue from (empty: start at t = 0). The output
  /// folder must hold the files of the checkpointed run.
  std::filesystem::path restart;
  /// False on the ranks other than 0 of a run under mpirun: they compute
  /// their share, rank 0 writes every file (docs/architecture.md 6).
  bool write_files = true;
};

class Coordinator {
 public:
  Coordinator(const Scene& scene, RunOptions options);
  ~Coordinator();

  /// Runs the scene to its end time; never throws for a failed run (the
  /// returned summary says why), only for failures to write output at all,
  /// and RestartRefused for a restart whose checkpoint or output folder is
  /// refused (then nothing was written).
  RunSummary run();

  /// What a run's start checks, without running: builds and initializes
  /// every process the scene activates (the fracture network and its
  /// boundaries, the thermal meshes, the contacts) and throws what they
  /// find (`fissure validate`). Writes nothing.
  void check();

  const RockMass& state() const { return state_; }
  /// The process of this name (its inner state, for tests), or null.
  const Process* process(std::string_view name) const;

 private:
  class Output;

  void start();
  /// Opens the output; a fresh run writes its first frame, a restarted one
  /// restores its state and continues its files.
  void begin(std::unique_ptr<Output>& output, double& next_output, CheckpointFile* checkpoint);
  void write_checkpoint(const Output& output, double next_output);
  /// The coordinator's counters, the initial stage's figures, the shared
  /// state and the splitting's, in or out of a checkpoint.
  template <class Archive>
  void checkpoint_run(Archive& root, double& next_output);
  bool checkpoint_due() const;
  /// The initial stage (CouplingSettings::initial_equilibrium), after every
  /// process is initialized: advances its processes alone until no block
  /// point moves faster than max_speed, initializes the other processes
  /// again at the settled state, resets the displacements and the time.
  /// Throws DivergenceError when max_time passes first; returns false when
  /// time.max_steps steps pass first (the stage counts its own steps).
  bool settle();
  double next_step_size(double next_output) const;
  bool output_due(long step, double next_output) const;
  void summarize(RunSummary& summary) const;

  const Scene& scene_;
  RunOptions options_;
  RockMass state_;
  std::vector<std::unique_ptr<Process>> processes_;  ///< in the order they advance
  std::unique_ptr<Splitting> splitting_;
  std::vector<std::unique_ptr<ResultsPart>> shared_results_;  ///< fields no process owns
  long steps_ = 0;
  long cuts_ = 0;
  long checkpoints_ = 0;
  double checkpoint_seconds_ = 0;  ///< spent writing them (this run)
  long last_checkpoint_step_ = 0;
  long restarted_at_ = 0;               ///< step of the checkpoint it was restarted from
  double last_checkpoint_wall_ = 0;     ///< s since the run started
  double wall_ = 0;                     ///< s since the run started, at the last step
  nlohmann::json initial_equilibrium_;  ///< the stage's figures, null without one
};

}  // namespace fissure
