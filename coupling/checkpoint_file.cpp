#include "coupling/checkpoint_file.h"

#include <fmt/format.h>

#include <cstdint>
#include <fstream>
#include <iterator>

#include "core/base/errors.h"

namespace fissure {

namespace fs = std::filesystem;

namespace {

constexpr const char* kFormat = "fissure-checkpoint";
constexpr int kFormatVersion = 2;  // 2: the coupling's sub-steps, own intervals, passes

}  // namespace

std::string scene_digest(const Scene& scene) {
  std::uint64_t h = 14695981039346656037ull;  // FNV-1a, 64 bits
  std::ifstream in(scene.source, std::ios::binary);
  for (std::istreambuf_iterator<char> it(in), end; it != end; ++it) {
    h ^= static_cast<unsigned char>(*it);
    h *= 1099511628211ull;
  }
  return fmt::format("{:016x}", h);
}

void write_checkpoint_file(const fs::path& file, const Scene& scene,
                           const std::function<void(CheckpointWriter&)>& fill) {
  const fs::path temporary = fs::path(file).concat(".tmp");
  {
    Hdf5File h5(temporary);
    Hdf5Group root = h5.root();
    h5.write_attribute(root, "format", std::string(kFormat));
    h5.write_attribute(root, "format_version", kFormatVersion);
    h5.write_attribute(root, "scene", scene.name);
    h5.write_attribute(root, "scene_digest", scene_digest(scene));
    CheckpointWriter writer(h5, h5.root());
    fill(writer);
    h5.write_attribute(root, "complete", 1);
    h5.flush();
  }
  std::error_code ec;
  fs::rename(temporary, file, ec);
  FISSURE_CHECK(!ec, IoError,
                file.string() << ": cannot replace the checkpoint (" << ec.message() << ")");
}

CheckpointFile::CheckpointFile(const fs::path& file, const Scene& scene) {
  const std::string name = file.string();
  try {
    file_ = std::make_unique<Hdf5File>(file, Hdf5File::Mode::Read);
  } catch (const IoError& e) {
    throw IoError(name +
                  ": not a readable checkpoint (truncated or not an HDF5 file): " + e.what());
  }
  Hdf5Group root = file_->root();
  auto attribute = [&](const char* key) {
    try {
      return file_->read_string_attribute(root, key);
    } catch (const IoError&) {
      return std::string();
    }
  };
  FISSURE_CHECK(attribute("format") == kFormat, IoError,
                name << ": not a Fissure checkpoint (no format \"" << kFormat << "\")");
  double version = 0, complete = 0;
  try {
    version = file_->read_double_attribute(root, "format_version");
    complete = file_->read_double_attribute(root, "complete");
  } catch (const IoError&) {
  }
  FISSURE_CHECK(version == kFormatVersion, IoError,
                name << ": checkpoint format version " << version << ", this Fissure reads "
                     << kFormatVersion);
  FISSURE_CHECK(complete == 1, IoError,
                name << ": the checkpoint is incomplete (its writing was interrupted)");
  const std::string of_scene = attribute("scene"), digest = attribute("scene_digest");
  FISSURE_CHECK(of_scene == scene.name && digest == scene_digest(scene), IoError,
                name << ": the checkpoint is of scene '" << of_scene << "' (file digest " << digest
                     << "), not of " << scene.source.string() << " ('" << scene.name << "', digest "
                     << scene_digest(scene)
                     << "): restart a run with the scene file it was started with, unchanged");
}

CheckpointReader CheckpointFile::root() {
  return CheckpointReader(*file_, file_->root());
}

}  // namespace fissure
