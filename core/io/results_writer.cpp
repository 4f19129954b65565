#include "core/io/results_writer.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/base/errors.h"
#include "core/io/block_results.h"
#include "core/io/checkpoint.h"
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
  Impl(const std::filesystem::path& outdir, Hdf5File::Mode mode, TimeUnit time_unit)
      : h5(outdir / "results.h5", mode),
        xdmf(outdir / "results.xdmf", "results.h5", std::move(time_unit)) {}

  Hdf5File h5;
  XdmfIndex xdmf;
  BlockResults blocks;
  std::vector<ResultsPart*> parts;  ///< the blocks, then the modules' parts
  Hdf5Group frames;                 ///< /frames
  Hdf5Group mesh;                   ///< /mesh, from the first frame on
  bool mesh_written = false;        ///< every part wrote its share of /mesh
  int n_frames = 0;
  int next_group = 0;
  std::vector<std::string> frame_names;  ///< of the frames linked in /frames
  double last_time = -std::numeric_limits<double>::infinity();
};

ResultsWriter::ResultsWriter(const std::filesystem::path& outdir, std::vector<ResultsPart*> parts,
                             TimeUnit time_unit)
    : impl_(std::make_unique<Impl>(outdir, Hdf5File::Mode::Create, std::move(time_unit))) {
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

ResultsWriter::ResultsWriter(const std::filesystem::path& outdir, std::vector<ResultsPart*> parts,
                             CheckpointReader& checkpoint, const RockMass& first_state,
                             TimeUnit time_unit)
    : impl_(std::make_unique<Impl>(outdir, Hdf5File::Mode::Append, std::move(time_unit))) {
  Impl& w = *impl_;
  const std::string file = w.h5.path().string();
  w.parts.push_back(&w.blocks);
  w.parts.insert(w.parts.end(), parts.begin(), parts.end());
  checkpoint("frames", w.n_frames);
  checkpoint("next_group", w.next_group);
  checkpoint("last_time", w.last_time);
  checkpoint("frame_names", w.frame_names);
  std::string frames_xml;
  checkpoint("xdmf_frames", frames_xml);

  Hdf5Group root = w.h5.root();
  FISSURE_CHECK(w.h5.exists(root, "frames") && w.h5.exists(root, "mesh"), IoError,
                file << ": not the results of the checkpointed run (no /frames or /mesh)");
  w.frames = w.h5.open_group(root, "frames");
  w.mesh = w.h5.open_group(root, "mesh");
  // Frames written after the checkpoint go; those before must all be there.
  std::vector<std::string> present = w.h5.links(w.frames);
  for (const std::string& name : w.frame_names)
    FISSURE_CHECK(
        std::find(present.begin(), present.end(), name) != present.end(), IoError,
        file << ": frame /frames/" << name
             << " of the checkpoint is missing (the results are not the checkpointed run's)");
  for (const std::string& name : present)
    if (std::find(w.frame_names.begin(), w.frame_names.end(), name) == w.frame_names.end())
      w.h5.unlink(w.frames, name);
  for (ResultsPart* part : w.parts) part->restore_mesh(first_state);
  w.mesh_written = true;
  w.h5.flush();
  w.xdmf.restore(std::move(frames_xml));
  w.xdmf.write();
}

void ResultsWriter::save(CheckpointWriter& checkpoint) const {
  const Impl& w = *impl_;
  checkpoint("frames", w.n_frames);
  checkpoint("next_group", w.next_group);
  checkpoint("last_time", w.last_time);
  checkpoint("frame_names", w.frame_names);
  checkpoint("xdmf_frames", w.xdmf.frames_xml());
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
  w.frame_names.push_back(name);
  w.h5.flush();
  w.xdmf.add_frame(t, group.path, frame.grids());
  w.last_time = t;
  ++w.n_frames;
}

int ResultsWriter::n_frames() const {
  return impl_->n_frames;
}

}  // namespace fissure
