// A checkpoint held in memory (the archives of core/io/checkpoint.h over a
// tree of named groups and vectors): the coordinator saves the processes'
// inner state into one before a coupling step and restores it to repeat the
// step (a retry, a pass of the iterated staggered scheme;
// docs/architecture.md "Coupling"). The same save()/restore() as the
// checkpoint files, so that a repeated step starts from what a restart
// would, to the bit. Not an HDF5 file in memory (the core driver): that
// costs about 20 us per dataset, 3-5 ms for the 157 datasets of an 80-block
// HM scene, more than its DDA step; this tree copies the numbers only.
#pragma once

#include <memory>

#include "core/io/checkpoint.h"

namespace fissure {

class MemoryCheckpoint {
 public:
  /// An empty checkpoint.
  MemoryCheckpoint();

  /// Writes into the root (sections are created, not replaced).
  CheckpointWriter writer();
  /// Reads what the writer wrote (as often as needed).
  CheckpointReader reader();

 private:
  std::shared_ptr<CheckpointNode> root_;
};

}  // namespace fissure
