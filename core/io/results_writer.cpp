#include "core/io/results_writer.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <optional>

#include "core/base/errors.h"
#include "core/io/frame_fields.h"
#include "core/io/hdf5_file.h"
#include "core/io/output_mesh.h"
#include "core/io/xdmf_index.h"

namespace fissure {

namespace {

constexpr int kFormatVersion = 1;

hsize_t size(int n) { return static_cast<hsize_t>(n); }

}  // namespace

struct ResultsWriter::Impl {
  explicit Impl(const std::filesystem::path& outdir)
      : h5(outdir / "results.h5"), xdmf(outdir / "results.xdmf", "results.h5") {}

  void write_mesh(const OutputMesh& m);
  /// Writes one frame group; returns the number of contacts written.
  int write_frame_group(const std::string& group, const RockMass& state, double t);

  Hdf5File h5;
  XdmfIndex xdmf;
  std::optional<OutputMesh> mesh;
  int n_frames = 0;
  int next_group = 0;
  double last_time = -std::numeric_limits<double>::infinity();
};

void ResultsWriter::Impl::write_mesh(const OutputMesh& m) {
  const hsize_t nb = size(m.n_blocks());
  h5.create_group("/mesh");
  h5.write_strings("/mesh/block_names", m.block_names);
  h5.write("/mesh/block_material", m.block_material, {nb});
  h5.write("/mesh/block_fixed", m.block_fixed, {nb});
  h5.write("/mesh/block_vertex_offsets", m.block_vertex_offsets, {nb + 1});
  h5.write("/mesh/block_loop_offsets", m.block_loop_offsets, {nb + 1});
  h5.write("/mesh/loop_offsets", m.loop_offsets, {m.loop_offsets.size()});
  h5.write("/mesh/initial_vertices", m.initial_vertices, {size(m.n_vertices()), 2});
  h5.write("/mesh/triangles", m.triangles, {size(m.n_triangles()), 3});
  h5.write("/mesh/triangle_block", m.triangle_block, {size(m.n_triangles())});
}

int ResultsWriter::Impl::write_frame_group(const std::string& group, const RockMass& state,
                                           double t) {
  const FrameFields f = gather_frame_fields(*mesh, state);
  const hsize_t nv = size(mesh->n_vertices());
  const hsize_t nt = size(mesh->n_triangles());
  h5.create_group(group);
  h5.write(group + "/vertices", f.vertices, {nv, 2});
  h5.write(group + "/displacement", f.displacement, {nv, 3});
  h5.write(group + "/velocity", f.velocity, {nv, 3});
  h5.write(group + "/sxx", f.sxx, {nt});
  h5.write(group + "/syy", f.syy, {nt});
  h5.write(group + "/sxy", f.sxy, {nt});
  h5.write(group + "/block_id", f.block_id, {nt});

  const ContactFields c = gather_contact_fields(state);
  if (c.size() > 0) {
    const std::string g = group + "/contacts";
    const hsize_t nc = size(c.size());
    h5.create_group(g);
    h5.write(g + "/points", c.points, {nc, 2});
    h5.write(g + "/normal", c.normal, {nc, 3});
    h5.write(g + "/state", c.state, {nc});
    h5.write(g + "/gap", c.gap, {nc});
    h5.write(g + "/normal_force", c.normal_force, {nc});
    h5.write(g + "/shear_force", c.shear_force, {nc});
    h5.write(g + "/block_i", c.block_i, {nc});
    h5.write(g + "/block_j", c.block_j, {nc});
    h5.write(g + "/cells", c.cells, {nc});
  }
  // Written last: a group with a time attribute is a complete frame.
  h5.write_attribute(group, "time", t);
  return c.size();
}

ResultsWriter::ResultsWriter(const std::filesystem::path& outdir)
    : impl_(std::make_unique<Impl>(outdir)) {
  Hdf5File& h5 = impl_->h5;
  h5.write_attribute("/", "format", std::string("fissure-results"));
  h5.write_attribute("/", "format_version", kFormatVersion);
  h5.create_group("/frames");
  h5.flush();
  impl_->xdmf.write();
}

ResultsWriter::~ResultsWriter() = default;

void ResultsWriter::write_frame(const RockMass& state, double t) {
  Impl& w = *impl_;
  const std::string file = w.h5.path().string();
  FISSURE_CHECK(std::isfinite(t), IoError, file << ": cannot write a frame at time t = " << t);
  FISSURE_CHECK(t > w.last_time, IoError,
                file << ": frame times must increase (t = " << t << " s after t = "
                     << w.last_time << " s)");

  // 1. The block topology, once: it is fixed for the whole run.
  if (!w.mesh) {
    OutputMesh mesh;
    try {
      mesh = build_output_mesh(state);
    } catch (const IoError& e) {
      throw IoError(file + ": " + e.what());
    }
    w.write_mesh(mesh);
    w.xdmf.set_mesh(mesh.n_vertices(), mesh.n_triangles());
    w.mesh = std::move(mesh);
  } else {
    const std::string change = topology_mismatch(*w.mesh, state);
    FISSURE_CHECK(change.empty(), IoError,
                  file << ": cannot write the frame at t = " << t << " s: " << change
                       << " (the output mesh is fixed at the first frame)");
  }

  // 2. The frame's fields. A failed attempt leaves an incomplete group (no
  // time attribute) that no index refers to; the next attempt uses a new name.
  const std::string group = fmt::format("/frames/{:06d}", w.next_group++);
  const int n_contacts = w.write_frame_group(group, state, t);

  // 3. Make it durable, then list it: the index never names a frame that is
  // not complete on disk.
  w.h5.flush();
  w.xdmf.add_frame(XdmfFrame{t, group, n_contacts});
  w.last_time = t;
  ++w.n_frames;
}

int ResultsWriter::n_frames() const { return impl_->n_frames; }

}  // namespace fissure
