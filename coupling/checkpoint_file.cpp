#include "coupling/checkpoint_file.h"

#include <fmt/format.h>

#include <cstdint>
#include <fstream>
#include <span>
#include <vector>

#include "core/base/digest.h"
#include "core/base/errors.h"

namespace fissure {

namespace fs = std::filesystem;

namespace {

constexpr const char* kFormat = "fissure-checkpoint";
// 2: the coupling's sub-steps, own intervals, passes; 3: the integrity record;
// 4: the thermal energy balance's BDF2 correction (docs/thermal.md 5); 5: the
// frozen-step count; 6: the DDA contacts' joint-law states.
constexpr int kFormatVersion = 6;
// The file's first bytes, which HDF5 leaves to us (a user block): the
// integrity record, "fissure-checkpoint 4\nbytes N\nfnv1a64 D\n" and zeros,
// where N is the file's length and D the digest of every byte after the
// block (every dataset, attribute and HDF5 structure of the file).
constexpr std::size_t kRecordBytes = 512;
constexpr char kHdf5Signature[] = "\x89HDF\r\n\x1a\n";

/// The digest of the file's bytes from `from` to its end, read in chunks.
std::string digest_from(const fs::path& file, std::size_t from) {
  std::ifstream in(file, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(from));
  Fnv1a64 digest;
  std::vector<char> chunk(1 << 20);
  while (in) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    digest.add(std::span<const char>(chunk.data(), static_cast<std::size_t>(in.gcount())));
  }
  return digest.hex();
}

std::string integrity_record(std::uintmax_t bytes, const std::string& digest) {
  return fmt::format("{} {}\nbytes {}\nfnv1a64 {}\n", kFormat, kFormatVersion, bytes, digest);
}

/// Refuses the file unless its bytes are those it was written with: before
/// HDF5 reads any of it, and so before any state is restored.
void check_integrity(const fs::path& file) {
  const std::string name = file.string();
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(file, ec);
  FISSURE_CHECK(!ec, IoError, name << ": cannot read the checkpoint (" << ec.message() << ")");
  std::string block(kRecordBytes, '\0');
  std::ifstream in(file, std::ios::binary);
  in.read(block.data(), static_cast<std::streamsize>(block.size()));
  const std::string signature = std::string(kFormat) + " ";
  if (block.compare(0, signature.size(), signature) != 0) {
    const bool hdf5 = block.compare(0, sizeof kHdf5Signature - 1, kHdf5Signature) == 0;
    FISSURE_CHECK(!hdf5, IoError,
                  name << ": not a Fissure checkpoint of format version " << kFormatVersion
                       << " (an HDF5 file without its integrity record: another program's "
                          "file, or a checkpoint of an older Fissure)");
    FISSURE_CHECK(
        false, IoError,
        name << ": not a Fissure checkpoint (it does not begin with \"" << kFormat << "\")");
  }
  const std::string damaged = fmt::format(
      "{}: the checkpoint's integrity record (its first {} bytes) is damaged; the checkpoint is "
      "refused whole",
      name, kRecordBytes);
  int version = 0;
  std::uintmax_t bytes = 0;
  char digest[17] = {};
  const int read = std::sscanf(block.c_str() + signature.size(),
                               "%d\nbytes %ju\nfnv1a64 %16[0-9a-f]", &version, &bytes, digest);
  FISSURE_CHECK(read >= 1, IoError, damaged);
  FISSURE_CHECK(version == kFormatVersion, IoError,
                name << ": checkpoint format version " << version << ", this Fissure reads "
                     << kFormatVersion);
  // The record, and zeros after it: a changed byte anywhere in the block is found.
  const std::string record = read == 3 ? integrity_record(bytes, digest) : std::string();
  const bool whole = read == 3 && block.compare(0, record.size(), record) == 0 &&
                     block.find_first_not_of('\0', record.size()) == std::string::npos;
  FISSURE_CHECK(whole, IoError, damaged);
  FISSURE_CHECK(size == bytes, IoError,
                name << ": the checkpoint has " << size << " bytes, it was written with " << bytes
                     << (size < bytes ? " (truncated)" : " (bytes were appended)")
                     << "; the checkpoint is refused whole");
  const std::string actual = digest_from(file, kRecordBytes);
  FISSURE_CHECK(actual == digest, IoError,
                name << ": the checkpoint is corrupted: the FNV-1a digest of its bytes is "
                     << actual << ", it was written with " << digest
                     << "; the checkpoint is refused whole");
}

}  // namespace

std::string scene_digest(const Scene& scene) {
  return digest_from(scene.source, 0);
}

void write_checkpoint_file(const fs::path& file, const Scene& scene,
                           const std::function<void(CheckpointWriter&)>& fill) {
  const fs::path temporary = fs::path(file).concat(".tmp");
  {
    Hdf5File h5(temporary, Hdf5File::Mode::Create, kRecordBytes);
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
  // Sealed after HDF5 has closed the file: its length and digest, in the
  // user block HDF5 left free.
  std::error_code ec;
  const std::uintmax_t bytes = fs::file_size(temporary, ec);
  FISSURE_CHECK(!ec, IoError,
                temporary.string() << ": cannot seal the checkpoint (" << ec.message() << ")");
  const std::string record = integrity_record(bytes, digest_from(temporary, kRecordBytes));
  {
    std::fstream out(temporary, std::ios::binary | std::ios::in | std::ios::out);
    out.write(record.data(), static_cast<std::streamsize>(record.size()));
    out.flush();
    FISSURE_CHECK(out.good(), IoError, temporary.string() << ": cannot seal the checkpoint");
  }
  fs::rename(temporary, file, ec);
  FISSURE_CHECK(!ec, IoError,
                file.string() << ": cannot replace the checkpoint (" << ec.message() << ")");
}

CheckpointFile::CheckpointFile(const fs::path& file, const Scene& scene) {
  const std::string name = file.string();
  check_integrity(file);
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
