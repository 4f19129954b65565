#include "core/io/memory_checkpoint.h"

#include <atomic>
#include <string>

namespace fissure {

namespace {

/// HDF5 tells open files apart by name, also in memory: each gets its own.
std::string unique_memory_name() {
  static std::atomic<unsigned long> count{0};
  return "memory-checkpoint-" + std::to_string(++count);
}

}  // namespace

MemoryCheckpoint::MemoryCheckpoint()
    : file_(std::make_unique<Hdf5File>(unique_memory_name(), Hdf5File::Mode::Memory)) {}

CheckpointWriter MemoryCheckpoint::writer() {
  return CheckpointWriter(*file_, file_->root());
}

CheckpointReader MemoryCheckpoint::reader() {
  return CheckpointReader(*file_, file_->root());
}

}  // namespace fissure
