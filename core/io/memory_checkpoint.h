// A checkpoint held in memory (core/io/checkpoint.h's archives over an HDF5
// file of the core driver, H5Pset_fapl_core without a backing store): the
// coordinator saves the processes' inner state into one before a coupling
// step and restores it to repeat the step (a retry, an iteration of the
// iterated staggered scheme; docs/architecture.md "Coupling"). The same
// save()/restore() as the checkpoint files, so that what a repeated step
// starts from is what a restart starts from, to the bit.
#pragma once

#include <memory>

#include "core/io/checkpoint.h"
#include "core/io/hdf5_file.h"

namespace fissure {

class MemoryCheckpoint {
 public:
  /// An empty checkpoint; nothing is written to disk.
  MemoryCheckpoint();

  /// Writes into the root (once: sections are created, not replaced).
  CheckpointWriter writer();
  /// Reads what the writer wrote (as often as needed).
  CheckpointReader reader();

 private:
  std::unique_ptr<Hdf5File> file_;
};

}  // namespace fissure
