#include "coupling/step_rollback.h"

#include <algorithm>

#include "core/base/errors.h"

namespace fissure {

StepRollback::StepRollback(const RockMass& state, std::vector<Process*> processes,
                           bool with_processes)
    : state_(state), processes_(std::move(processes)) {
  if (!with_processes || processes_.empty()) return;
  saved_ = std::make_unique<MemoryCheckpoint>();
  CheckpointWriter root = saved_->writer();
  for (const Process* p : processes_) {
    CheckpointWriter section = root.section(p->name());
    p->save(section, state_);
  }
}

void StepRollback::restore(RockMass& state, const std::vector<Process*>& advanced) {
  state = state_;
  if (advanced.empty()) return;
  FISSURE_CHECK(saved_, std::logic_error,
                "a process advanced in a step taken without its snapshot");
  CheckpointReader root = saved_->reader();
  for (Process* p : advanced) {
    FISSURE_CHECK(std::find(processes_.begin(), processes_.end(), p) != processes_.end(),
                  std::logic_error, p->name() << " advanced in a step it was not saved for");
    CheckpointReader section = root.section(p->name());
    p->restore(section, state);
  }
  // A process's restore may publish its fields again from its inner state,
  // from the blocks as they are now; the step starts from the snapshot's, to
  // the bit.
  state = state_;
}

}  // namespace fissure
