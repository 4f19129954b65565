// The checkpoint file of a run (docs/output.md "Checkpoint and restart"):
// OUTDIR/checkpoint.h5, written atomically (a temporary file, marked
// complete as its last write, then renamed over the previous checkpoint), so
// that a run killed at any moment leaves the last complete checkpoint. It
// names the scene it belongs to (its name and a digest of its file), and
// begins with an integrity record: its length and the digest of all its
// other bytes. A restart refuses a checkpoint that is corrupted, truncated,
// incomplete, of another format version or of another scene, before HDF5
// reads any of it.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "core/io/checkpoint.h"
#include "core/scene/scene.h"

namespace fissure {

/// A restart refused before anything was restored or written: the
/// checkpoint (or the output folder it continues) is not that of this run.
class RestartRefused : public IoError {
 public:
  using IoError::IoError;
};

/// FNV-1a digest (hex) of the scene file's bytes.
std::string scene_digest(const Scene& scene);

/// Writes `file`: `fill` writes the sections into the root.
void write_checkpoint_file(const std::filesystem::path& file, const Scene& scene,
                           const std::function<void(CheckpointWriter&)>& fill);

/// A checkpoint opened for a restart of `scene`, its every byte checked;
/// throws IoError saying what is wrong with it.
class CheckpointFile {
 public:
  CheckpointFile(const std::filesystem::path& file, const Scene& scene);
  CheckpointReader root();

 private:
  std::unique_ptr<Hdf5File> file_;
};

}  // namespace fissure
