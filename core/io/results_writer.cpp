#include "core/io/results_writer.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <optional>

#include "core/base/errors.h"
#include "core/io/fracture_output.h"
#include "core/io/frame_fields.h"
#include "core/io/hdf5_file.h"
#include "core/io/output_mesh.h"
#include "core/io/xdmf_index.h"

namespace fissure {

namespace {

constexpr int kFormatVersion = 1;
/// Room reserved for frame names in /frames: 8 bytes per name ("000123"),
/// 8192 frames before the name heap has to grow.
constexpr std::size_t kFrameNameBytes = 8 * 8192;

hsize_t size(int n) {
  return static_cast<hsize_t>(n);
}

/// An upper bound of the file space one frame takes: its arrays plus the
/// metadata of its ~30 objects.
std::size_t frame_bytes(const OutputMesh& mesh, std::size_t n_contacts,
                        const FractureGraph& fractures) {
  const std::size_t per_vertex = 8 * (2 + 3 + 3);
  const std::size_t per_triangle = 8 * 3 + 4;
  const std::size_t per_contact = 8 * (2 + 3 + 3) + 4 * 4;
  const std::size_t per_fracture_node = 8 * (2 + 2);
  const std::size_t per_fracture_segment = 4 * 2 + 8 * 4;
  return per_vertex * mesh.n_vertices() + per_triangle * mesh.n_triangles() +
         per_contact * n_contacts + per_fracture_node * fractures.nodes.size() +
         per_fracture_segment * fractures.segments.size() + (1 << 20);
}

}  // namespace

struct ResultsWriter::Impl {
  Impl(const std::filesystem::path& outdir, const HeadDefinition& head)
      : h5(outdir / "results.h5"), xdmf(outdir / "results.xdmf", "results.h5"), head(head) {}

  void write_mesh(const OutputMesh& m, const FractureGraph& fractures);
  /// Fills a frame group; returns its XDMF entry.
  XdmfFrame write_frame_group(const Hdf5Group& g, const RockMass& state, double t);

  Hdf5File h5;
  XdmfIndex xdmf;
  HeadDefinition head;
  Hdf5Group frames;  ///< /frames
  std::optional<OutputMesh> mesh;
  /// The graph in /mesh/fractures (empty: none). The flow process keeps its
  /// graph for the whole run, but a graph that differs in a frame (rebuilt,
  /// or moved) gets its own geometry in that frame instead of a wrong picture.
  FractureFields mesh_fractures;
  int n_frames = 0;
  int next_group = 0;
  double last_time = -std::numeric_limits<double>::infinity();
};

void ResultsWriter::Impl::write_mesh(const OutputMesh& m, const FractureGraph& fractures) {
  const hsize_t nb = size(m.n_blocks());
  Hdf5Group root = h5.root();
  const Hdf5Group g = h5.create_group(root, "mesh");
  h5.write_strings(g, "block_names", m.block_names);
  h5.write(g, "block_material", m.block_material, {nb});
  h5.write(g, "block_fixed", m.block_fixed, {nb});
  h5.write(g, "block_vertex_offsets", m.block_vertex_offsets, {nb + 1});
  h5.write(g, "block_loop_offsets", m.block_loop_offsets, {nb + 1});
  h5.write(g, "loop_offsets", m.loop_offsets, {m.loop_offsets.size()});
  h5.write(g, "initial_vertices", m.initial_vertices, {size(m.n_vertices()), 2});
  h5.write(g, "triangles", m.triangles, {size(m.n_triangles()), 3});
  h5.write(g, "triangle_block", m.triangle_block, {size(m.n_triangles())});
  if (fractures.n_segments() > 0) {
    write_fracture_mesh(h5, g, fractures);
    mesh_fractures = gather_fracture_geometry(fractures);
  }
}

XdmfFrame ResultsWriter::Impl::write_frame_group(const Hdf5Group& g, const RockMass& state,
                                                 double t) {
  const FrameFields f = gather_frame_fields(*mesh, state);
  const hsize_t nv = size(mesh->n_vertices());
  const hsize_t nt = size(mesh->n_triangles());
  h5.write_attribute(g, "time", t);
  h5.write(g, "vertices", f.vertices, {nv, 2});
  h5.write(g, "displacement", f.displacement, {nv, 3});
  h5.write(g, "velocity", f.velocity, {nv, 3});
  h5.write(g, "sxx", f.sxx, {nt});
  h5.write(g, "syy", f.syy, {nt});
  h5.write(g, "sxy", f.sxy, {nt});
  h5.write(g, "block_id", f.block_id, {nt});

  const ContactFields c = gather_contact_fields(state);
  if (c.size() > 0) {
    const hsize_t nc = size(c.size());
    const Hdf5Group cg = h5.create_group(g, "contacts");
    h5.write(cg, "points", c.points, {nc, 2});
    h5.write(cg, "normal", c.normal, {nc, 3});
    h5.write(cg, "state", c.state, {nc});
    h5.write(cg, "gap", c.gap, {nc});
    h5.write(cg, "normal_force", c.normal_force, {nc});
    h5.write(cg, "shear_force", c.shear_force, {nc});
    h5.write(cg, "block_i", c.block_i, {nc});
    h5.write(cg, "block_j", c.block_j, {nc});
    h5.write(cg, "cells", c.cells, {nc});
  }

  const FractureFields fractures = gather_fracture_fields(state, head);
  const bool same_graph = mesh_fractures.n_segments() > 0 &&
                          fractures.nodes == mesh_fractures.nodes &&
                          fractures.segments == mesh_fractures.segments;
  return XdmfFrame{t, g.path, c.size(),
                   write_fracture_frame(h5, g, fractures, same_graph ? "/mesh/fractures" : "")};
}

ResultsWriter::ResultsWriter(const std::filesystem::path& outdir, HeadDefinition head)
    : impl_(std::make_unique<Impl>(outdir, head)) {
  Hdf5File& h5 = impl_->h5;
  Hdf5Group root = h5.root();
  h5.write_attribute(root, "format", std::string("fissure-results"));
  h5.write_attribute(root, "format_version", kFormatVersion);
  impl_->frames = h5.create_growing_group(root, "frames", kFrameNameBytes);
  h5.flush();
  impl_->xdmf.write();
}

ResultsWriter::~ResultsWriter() = default;

void ResultsWriter::write_frame(const RockMass& state, double t) {
  Impl& w = *impl_;
  const std::string file = w.h5.path().string();
  FISSURE_CHECK(std::isfinite(t), IoError, file << ": cannot write a frame at time t = " << t);
  FISSURE_CHECK(
      t > w.last_time, IoError,
      file << ": frame times must increase (t = " << t << " s after t = " << w.last_time << " s)");

  // 1. The block topology, once: it is fixed for the whole run.
  if (!w.mesh) {
    OutputMesh mesh;
    try {
      mesh = build_output_mesh(state);
    } catch (const IoError& e) {
      throw IoError(file + ": " + e.what());
    }
    w.write_mesh(mesh, state.fractures);
    w.xdmf.set_mesh(mesh.n_vertices(), mesh.n_triangles());
    w.mesh = std::move(mesh);
  } else {
    const std::string change = topology_mismatch(*w.mesh, state);
    FISSURE_CHECK(change.empty(), IoError,
                  file << ": cannot write the frame at t = " << t << " s: " << change
                       << " (the output mesh is fixed at the first frame)");
  }

  // 2. The frame, built in a group that nothing links to yet and flushed: a
  // kill now leaves the file as it was after the previous frame.
  w.h5.reserve(frame_bytes(*w.mesh, state.contacts.size(), state.fractures));
  const std::string name = fmt::format("{:06d}", w.next_group++);
  const Hdf5Group group = w.h5.create_detached_group(w.frames.path + "/" + name);
  const XdmfFrame entry = w.write_frame_group(group, state, t);
  w.h5.flush();

  // 3. Link it and flush again (a failed attempt leaves no link, and the next
  // attempt uses a new name). Then list it: the index never names a frame
  // that is not complete on disk.
  w.h5.link(group, w.frames, name);
  w.h5.flush();
  w.xdmf.add_frame(entry);
  w.last_time = t;
  ++w.n_frames;
}

int ResultsWriter::n_frames() const {
  return impl_->n_frames;
}

}  // namespace fissure
