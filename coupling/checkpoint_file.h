// The checkpoint file of a run (docs/output.md "Checkpoint and restart"):
// OUTDIR/checkpoint.h5, written atomically (a temporary file, marked
// complete as its last write, then renamed over the previous checkpoint), so
// that a run killed at any moment leaves the last complete checkpoint. It
// names the scene it belongs to (its name and a digest of its file), and a
// restart refuses a checkpoint that is truncated, incomplete, of another
// format version or of another scene.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "core/io/checkpoint.h"
#include "core/scene/scene.h"

namespace fissure {

/// FNV-1a digest (hex) of the scene file's bytes.
std::string scene_digest(const Scene& scene);

/// Writes `file`: `fill` writes the sections into the root.
void write_checkpoint_file(const std::filesystem::path& file, const Scene& scene,
                           const std::function<void(CheckpointWriter&)>& fill);

/// A checkpoint opened for a restart of `scene`; throws IoError saying what
/// is wrong with it.
class CheckpointFile {
 public:
  CheckpointFile(const std::filesystem::path& file, const Scene& scene);
  CheckpointReader root();

 private:
  std::unique_ptr<Hdf5File> file_;
};

}  // namespace fissure
