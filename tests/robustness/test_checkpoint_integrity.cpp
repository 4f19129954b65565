// A checkpoint is restored only if every one of its bytes is the one it was
// written with (issue 35, item 1; docs/output.md "Checkpoint and restart"):
// its first 512 bytes record its length and the FNV-1a digest of the rest,
// checked before HDF5 reads the file, so before any state is restored. A
// flipped byte anywhere (the integrity record, HDF5's superblock and object
// headers, every dataset), 4 kB scrambled, a truncated, extended, foreign or
// older file is refused whole, with what is wrong, and the output folder of
// the checkpointed run is left as it was, summary.json included.
#include <hdf5.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "core/base/errors.h"
#include "coupling/checkpoint_file.h"
#include "coupling/process_registry.h"
#include "tests/support/fissure_command.h"
#include "tests/support/run_scene.h"

namespace fissure::testing {
namespace {

namespace fs = std::filesystem;

/// `config` run for `steps` steps into `dir`/run with a checkpoint every
/// `steps`; returns the scene file written for it.
fs::path run_with_checkpoint(const fs::path& dir, const std::string& config, int steps) {
  const fs::path scene = dir / config;
  std::string text = file_bytes(FISSURE_SOURCE_DIR "/configs/" + config);
  text = text.substr(0, text.find("output:\n")) +
         "output:\n  every_steps: 1\n  checkpoint_steps: " + std::to_string(steps) + "\n";
  std::ofstream(scene) << text;
  std::string err;
  const std::string args = "run " + scene.filename().string() +
                           " -q --no-plots -o run --max-steps " + std::to_string(steps);
  EXPECT_EQ(run_fissure(args, dir, err), 0) << err;
  EXPECT_TRUE(fs::exists(dir / "run" / "checkpoint.h5"));
  return scene;
}

/// The file offsets of every dataset's stored values (HDF5 lays checkpoint
/// datasets out contiguously) and their lengths.
std::vector<std::pair<haddr_t, hsize_t>> dataset_extents(const fs::path& file) {
  std::vector<std::pair<haddr_t, hsize_t>> extents;
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(f, 0);
  auto visit = [](hid_t root, const char* name, const H5O_info_t* info, void* data) -> herr_t {
    if (info->type != H5O_TYPE_DATASET) return 0;
    const hid_t d = H5Dopen2(root, name, H5P_DEFAULT);
    const haddr_t at = H5Dget_offset(d);
    const hsize_t bytes = H5Dget_storage_size(d);
    if (at != HADDR_UNDEF && bytes > 0)
      static_cast<std::vector<std::pair<haddr_t, hsize_t>>*>(data)->push_back({at, bytes});
    H5Dclose(d);
    return 0;
  };
  H5Ovisit(f, H5_INDEX_NAME, H5_ITER_NATIVE, visit, &extents);
  H5Fclose(f);
  return extents;
}

/// The message with which opening `file` as a checkpoint of `scene` is
/// refused, or "" when it is accepted.
std::string refusal(const fs::path& file, const Scene& scene) {
  try {
    CheckpointFile checkpoint(file, scene);
  } catch (const IoError& e) {
    return e.what();
  }
  return "";
}

/// The same, of `bytes` written to `file`.
std::string refusal(const std::string& bytes, const fs::path& file, const Scene& scene) {
  std::ofstream(file, std::ios::binary | std::ios::trunc).write(bytes.data(), bytes.size());
  return refusal(file, scene);
}

/// XORs the byte at `at` of `file` with `mask`, in place.
void flip(const fs::path& file, std::size_t at, unsigned char mask) {
  std::fstream f(file, std::ios::binary | std::ios::in | std::ios::out);
  f.seekg(static_cast<std::streamoff>(at));
  const char c = static_cast<char>(f.get() ^ mask);
  f.seekp(static_cast<std::streamoff>(at));
  f.put(c);
}

bool mentions(const std::string& message, const std::string& part) {
  return message.find(part) != std::string::npos;
}

TEST(CheckpointIntegrity, EveryChangedByteIsRefusedBeforeHdf5ReadsTheFile) {
  const fs::path dir = scratch_dir("checkpoint_integrity");
  const fs::path scene_file = run_with_checkpoint(dir, "flow_hm_injection.yaml", 6);
  const Scene scene = read_scene(scene_file);
  const fs::path original = dir / "run" / "checkpoint.h5", probe = dir / "probe.h5";
  const std::string bytes = file_bytes(original);
  ASSERT_GT(bytes.size(), 4096u);
  ASSERT_EQ(refusal(bytes, probe, scene), "") << "the checkpoint as written is accepted";

  // Where to flip a byte: every byte of the first 1 kB (the integrity
  // record, HDF5's superblock and the root group's header), the first, a
  // middle and the last byte of every dataset's values, and every 499th
  // byte of the file (object headers, heaps, B-trees, free space).
  std::set<std::size_t> offsets;
  for (std::size_t at = 0; at < 1024; ++at) offsets.insert(at);
  const auto extents = dataset_extents(original);
  EXPECT_GT(extents.size(), 50u) << "the datasets of a DDA and flow checkpoint";
  for (const auto& [at, length] : extents)
    for (const hsize_t k : {hsize_t{0}, length / 2, length - 1}) offsets.insert(at + k);
  for (std::size_t at = 0; at < bytes.size(); at += 499) offsets.insert(at);

  std::map<std::string, int> refusals;  // by the kind of message
  int accepted = 0;
  for (const std::size_t at : offsets) {
    ASSERT_LT(at, bytes.size());
    // The lowest bit and the highest bit, in turn.
    const unsigned char mask = at % 2 ? 0x80 : 0x01;
    flip(probe, at, mask);
    const std::string message = refusal(probe, scene);
    flip(probe, at, mask);
    if (message.empty()) {
      ++accepted;
      ADD_FAILURE() << "byte " << at << " ^ " << int(mask) << " was accepted";
    }
    ++refusals[message.substr(message.find(": ") + 2, 30)];
  }
  EXPECT_EQ(accepted, 0) << "of " << offsets.size() << " flipped bytes";
  EXPECT_EQ(refusal(probe, scene), "") << "the bytes flipped back are accepted";
  std::printf("%zu flipped bytes (%zu datasets) of a %zu-byte checkpoint, refused as:\n",
              offsets.size(), extents.size(), bytes.size());
  for (const auto& [kind, count] : refusals) std::printf("  %6d  %s...\n", count, kind.c_str());
}

TEST(CheckpointIntegrity, ScrambledTruncatedExtendedForeignAndOlderFilesAreRefused) {
  const fs::path dir = scratch_dir("checkpoint_integrity");
  const fs::path scene_file = run_with_checkpoint(dir, "flow_hm_injection.yaml", 4);
  const Scene scene = read_scene(scene_file);
  const fs::path probe = dir / "probe.h5";
  const std::string bytes = file_bytes(dir / "run" / "checkpoint.h5");

  // 4 kB of scrambled bytes (a fixed pseudo-random pattern) at 16 places.
  for (int k = 0; k < 16; ++k) {
    std::string changed = bytes;
    const std::size_t from = (bytes.size() - 4096) * k / 15;
    unsigned state = 12345u + k;
    for (std::size_t i = from; i < from + 4096; ++i) {
      state = state * 1103515245u + 12345u;
      changed[i] = static_cast<char>(state >> 16);
    }
    const std::string message = refusal(changed, probe, scene);
    EXPECT_FALSE(message.empty()) << "scrambled at " << from;
    if (from > 0) {
      EXPECT_TRUE(mentions(message, "is corrupted")) << "scrambled at " << from << ": " << message;
    }
  }
  // Truncated anywhere, or with bytes appended.
  for (const std::size_t length :
       {std::size_t{0}, std::size_t{100}, std::size_t{511}, std::size_t{512}, std::size_t{2048},
        bytes.size() / 2, bytes.size() - 1}) {
    const std::string message = refusal(bytes.substr(0, length), probe, scene);
    EXPECT_FALSE(message.empty()) << "truncated to " << length;
    if (length > 512) {
      EXPECT_TRUE(mentions(message, "(truncated)")) << message;
    }
  }
  EXPECT_TRUE(mentions(refusal(bytes + "x", probe, scene), "bytes were appended"));
  // Another program's HDF5 file, and not HDF5 at all.
  EXPECT_TRUE(mentions(refusal(file_bytes(dir / "run" / "results.h5"), probe, scene),
                       "without its integrity record"));
  EXPECT_TRUE(mentions(refusal(file_bytes(scene_file), probe, scene), "not a Fissure checkpoint"));
  // A checkpoint of an older format version (its record says 2).
  std::string older = bytes;
  older[older.find(' ') + 1] = '2';
  EXPECT_TRUE(mentions(refusal(older, probe, scene), "format version 2, this Fissure reads 6"));
  // Of another scene: the same file under another name.
  const fs::path other = dir / "other.yaml";
  std::string text = file_bytes(scene_file);
  text.replace(text.find("name: "), 6, "name: other_");
  std::ofstream(other) << text;
  EXPECT_TRUE(mentions(refusal(bytes, probe, read_scene(other)), "the checkpoint is of scene"));
}

/// Restarts `scene` from `folder`/checkpoint.h5 and expects it refused for
/// `reason`, exit code 1, with every file of `folder` as it was.
void expect_refused_restart(const fs::path& dir, const fs::path& scene, const std::string& folder,
                            const std::string& reason) {
  const std::vector<std::string> files = {"summary.json", "monitors.csv", "results.h5",
                                          "results.xdmf", "checkpoint.h5"};
  std::vector<std::string> before;
  for (const std::string& f : files) before.push_back(file_bytes(dir / folder / f));
  std::string err;
  EXPECT_EQ(run_fissure("run " + scene.filename().string() +
                            " -q --no-plots --max-steps 8 --restart " + folder + "/checkpoint.h5",
                        dir, err),
            1);
  EXPECT_TRUE(mentions(err, "the restart is refused, nothing was written")) << err;
  EXPECT_TRUE(mentions(err, reason)) << err;
  for (std::size_t k = 0; k < files.size(); ++k)
    EXPECT_TRUE(file_bytes(dir / folder / files[k]) == before[k]) << files[k] << " was touched";
}

// The case of the issue: 4 kB scrambled in the middle of a continuum
// repository checkpoint was restored and ran to ux = 2.4e179 m. Now the
// restart stops at once, exit code 1, and every file of the run is as it was.
TEST(CheckpointIntegrity, ARefusedRestartTouchesNoOutput) {
  const fs::path dir = scratch_dir("checkpoint_integrity");
  const fs::path scene = run_with_checkpoint(dir, "continuum_repository.yaml", 4);
  const fs::path checkpoint = dir / "run" / "checkpoint.h5";
  std::string bytes = file_bytes(checkpoint);
  for (std::size_t i = bytes.size() / 2; i < bytes.size() / 2 + 4096; ++i)
    bytes[i] = static_cast<char>(i * 7919);
  std::ofstream(checkpoint, std::ios::binary | std::ios::trunc).write(bytes.data(), bytes.size());

  expect_refused_restart(dir, scene, "run", "the checkpoint is corrupted");

  // An output folder that is not the checkpointed run's (monitors.csv
  // shorter than at the checkpoint) is refused the same way.
  std::string err;
  ASSERT_EQ(
      run_fissure("run " + scene.filename().string() + " -q --no-plots -o again --max-steps 4", dir,
                  err),
      0)
      << err;
  std::ofstream(dir / "again" / "monitors.csv", std::ios::trunc) << "t\n";
  expect_refused_restart(dir, scene, "again", "monitors.csv");
}

}  // namespace
}  // namespace fissure::testing
