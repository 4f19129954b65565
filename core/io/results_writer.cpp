#include "core/io/results_writer.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "core/base/errors.h"
#include "core/io/block_results.h"
#include "core/io/xdmf_index.h"

namespace fissure {

namespace {

constexpr int kFormatVersion = 1;
/// Room reserved for frame names in /frames: 8 bytes per name ("000123"),
/// 8192 frames before the name heap has to grow.
constexpr std::size_t kFrameNameBytes = 8 * 8192;
/// The metadata of a frame's ~30 objects, on top of its arrays.
constexpr std::size_t kFrameMetadataBytes = 1 << 20;

}  // namespace

struct ResultsWriter::Impl {
  explicit Impl(const std::filesystem::path& outdir)
      : h5(outdir / "results.h5"), xdmf(outdir / "results.xdmf", "results.h5") {}

  Hdf5File h5;
  XdmfIndex xdmf;
  BlockResults blocks;
  std::vector<ResultsPart*> parts;  ///< the blocks, then the modules' parts
  Hdf5Group frames;                 ///< /frames
  Hdf5Group mesh;                   ///< /mesh, from the first frame on
  bool mesh_written = false;        ///< every part wrote its share of /mesh
  int n_frames = 0;
  int next_group = 0;
  double last_time = -std::numeric_limits<double>::infinity();
};

ResultsWriter::ResultsWriter(const std::filesystem::path& outdir, std::vector<ResultsPart*> parts)
    : impl_(std::make_unique<Impl>(outdir)) {
  Impl& w = *impl_;
  w.parts.push_back(&w.blocks);
  w.parts.insert(w.parts.end(), parts.begin(), parts.end());
  Hdf5Group root = w.h5.root();
  w.h5.write_attribute(root, "format", std::string("fissure-results"));
  w.h5.write_attribute(root, "format_version", kFormatVersion);
  w.frames = w.h5.create_growing_group(root, "frames", kFrameNameBytes);
  w.h5.flush();
  w.xdmf.write();
}

ResultsWriter::~ResultsWriter() = default;

void ResultsWriter::write_frame(const RockMass& state, double t) {
  Impl& w = *impl_;
  const std::string file = w.h5.path().string();
  FISSURE_CHECK(std::isfinite(t), IoError, file << ": cannot write a frame at time t = " << t);
  FISSURE_CHECK(
      t > w.last_time, IoError,
      file << ": frame times must increase (t = " << t << " s after t = " << w.last_time << " s)");

  // 1. What is fixed for the whole run (the block topology, the fracture
  // graph), once, with the first frame.
  if (w.mesh.path.empty()) {
    Hdf5Group root = w.h5.root();
    w.mesh = w.h5.create_group(root, "mesh");
  }
  FrameWriter frame(w.h5, "results.h5", t, w.mesh);
  if (!w.mesh_written) {
    for (ResultsPart* part : w.parts) part->write_mesh(frame, state);
    w.mesh_written = true;
  }

  // 2. The frame, built in a group that nothing links to yet and flushed: a
  // kill now leaves the file as it was after the previous frame.
  std::size_t bytes = kFrameMetadataBytes;
  for (const ResultsPart* part : w.parts) bytes += part->frame_bytes(state);
  w.h5.reserve(bytes);
  const std::string name = fmt::format("{:06d}", w.next_group++);
  const Hdf5Group group = w.h5.create_detached_group(w.frames.path + "/" + name);
  frame.set_frame(group);
  w.h5.write_attribute(group, "time", t);
  for (ResultsPart* part : w.parts) part->write_frame(frame, state);
  w.h5.flush();

  // 3. Link it and flush again (a failed attempt leaves no link, and the next
  // attempt uses a new name). Then list it: the index never names a frame
  // that is not complete on disk.
  w.h5.link(group, w.frames, name);
  w.h5.flush();
  w.xdmf.add_frame(t, group.path, frame.grids());
  w.last_time = t;
  ++w.n_frames;
}

int ResultsWriter::n_frames() const {
  return impl_->n_frames;
}

}  // namespace fissure
