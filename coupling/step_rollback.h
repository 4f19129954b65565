// What a coupling step starts from, to go back to it (docs/architecture.md
// "Coupling"): the shared state, and the inner state of the processes that
// advance in the step, saved with their own Process::save into an in-memory
// checkpoint (core/io/memory_checkpoint.h). A retry asked by a later process
// or a non-finite state after the step thus also undoes the earlier
// processes' inner state (the DDA's contacts, the flow's stored volumes),
// and the iterated scheme repeats the step from it. The processes' part is
// taken only when more than one process advances in the step or the step is
// repeated: a lone process's Retry leaves its state untouched by contract.
#pragma once

#include <memory>
#include <vector>

#include "core/io/memory_checkpoint.h"
#include "core/process/process.h"
#include "core/state/rock_mass.h"

namespace fissure {

class StepRollback {
 public:
  /// Takes the snapshot of `state` and, with `with_processes`, of the
  /// processes' inner state.
  StepRollback(const RockMass& state, std::vector<Process*> processes, bool with_processes);

  /// Puts the state back as it was at the snapshot, and the processes of
  /// `advanced` (which must be among those saved). A process that rejected
  /// its step left its inner state as it chose (its Retry contract) and is
  /// not touched.
  void restore(RockMass& state, const std::vector<Process*>& advanced);

 private:
  RockMass state_;
  std::vector<Process*> processes_;
  std::unique_ptr<MemoryCheckpoint> saved_;  ///< null: the state only
};

}  // namespace fissure
