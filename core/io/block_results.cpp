#include "core/io/block_results.h"

#include "core/base/errors.h"
#include "core/io/frame_fields.h"

namespace fissure {

namespace {

hsize_t size(int n) {
  return static_cast<hsize_t>(n);
}

}  // namespace

void BlockResults::restore_mesh(const RockMass& state) {
  mesh_ = build_output_mesh(state);
}

void BlockResults::write_mesh(FrameWriter& frame, const RockMass& state) {
  Hdf5File& h5 = frame.h5();
  OutputMesh m;
  try {
    m = build_output_mesh(state);
  } catch (const IoError& e) {
    throw IoError(h5.path().string() + ": " + e.what());
  }
  const hsize_t nb = size(m.n_blocks());
  const Hdf5Group& g = frame.mesh();
  h5.write_strings(g, "block_names", m.block_names);
  h5.write(g, "block_material", m.block_material, {nb});
  h5.write(g, "block_fixed", m.block_fixed, {nb});
  h5.write(g, "block_vertex_offsets", m.block_vertex_offsets, {nb + 1});
  h5.write(g, "block_loop_offsets", m.block_loop_offsets, {nb + 1});
  h5.write(g, "loop_offsets", m.loop_offsets, {m.loop_offsets.size()});
  h5.write(g, "initial_vertices", m.initial_vertices, {size(m.n_vertices()), 2});
  h5.write(g, "triangles", m.triangles, {size(m.n_triangles()), 3});
  h5.write(g, "triangle_block", m.triangle_block, {size(m.n_triangles())});
  mesh_ = std::move(m);
}

std::size_t BlockResults::frame_bytes(const RockMass&) const {
  const std::size_t per_vertex = 8 * (2 + 3 + 3);
  const std::size_t per_triangle = 8 * 3 + 4;
  return mesh_ ? per_vertex * mesh_->n_vertices() + per_triangle * mesh_->n_triangles() : 0;
}

void BlockResults::write_frame(FrameWriter& frame, const RockMass& state) {
  Hdf5File& h5 = frame.h5();
  FISSURE_CHECK(mesh_, IoError, h5.path().string() << ": the block mesh was not written");
  const std::string change = topology_mismatch(*mesh_, state);
  FISSURE_CHECK(change.empty(), IoError,
                h5.path().string() << ": cannot write the frame at t = " << frame.time() << " s: "
                                   << change << " (the output mesh is fixed at the first frame)");

  const FrameFields f = gather_frame_fields(*mesh_, state);
  const hsize_t nv = size(mesh_->n_vertices());
  const hsize_t nt = size(mesh_->n_triangles());
  const Hdf5Group& g = frame.frame();
  h5.write(g, "vertices", f.vertices, {nv, 2});
  h5.write(g, "displacement", f.displacement, {nv, 3});
  h5.write(g, "velocity", f.velocity, {nv, 3});
  h5.write(g, "sxx", f.sxx, {nt});
  h5.write(g, "syy", f.syy, {nt});
  h5.write(g, "sxy", f.sxy, {nt});
  h5.write(g, "block_id", f.block_id, {nt});

  // The "blocks" grid: triangles of /mesh on the frame's vertices.
  XdmfGrid& grid = frame.grid("blocks");
  const std::string at = g.path + "/";
  const std::string nodes = std::to_string(nv);
  const std::string cells = std::to_string(nt);
  constexpr auto Float = XdmfNumber::Float64;
  grid.topology_type = "Triangle";
  grid.n_elements = static_cast<int>(nt);
  grid.connectivity =
      xdmf_data_item(cells + " 3", XdmfNumber::Int32, frame.xdmf_path("/mesh/triangles"));
  grid.geometry = xdmf_data_item(nodes + " 2", Float, frame.xdmf_path(at + "vertices"));
  grid.frame_attributes.push_back(xdmf_attribute("displacement", "Vector", "Node", nodes + " 3",
                                                 Float, frame.xdmf_path(at + "displacement"), "m"));
  grid.frame_attributes.push_back(xdmf_attribute("velocity", "Vector", "Node", nodes + " 3", Float,
                                                 frame.xdmf_path(at + "velocity"), "m/s"));
  for (const char* s : {"sxx", "syy", "sxy"})
    grid.frame_attributes.push_back(
        xdmf_attribute(s, "Scalar", "Cell", cells, Float, frame.xdmf_path(at + s), "Pa"));
  grid.frame_attributes.push_back(xdmf_attribute("block_id", "Scalar", "Cell", cells,
                                                 XdmfNumber::Int32,
                                                 frame.xdmf_path(at + "block_id"), "-"));
}

}  // namespace fissure
