#include "core/io/output_mesh.h"

#include "core/base/errors.h"
#include "core/geometry/triangulate.h"

namespace fissure {

namespace {

std::string block_label(const RockMass& state, int b) {
  return "block " + std::to_string(b) + " ('" + state.blocks[b].name + "')";
}

}  // namespace

OutputMesh build_output_mesh(const RockMass& state) {
  OutputMesh mesh;
  mesh.block_vertex_offsets.push_back(0);
  mesh.block_loop_offsets.push_back(0);
  mesh.loop_offsets.push_back(0);
  for (int b = 0; b < static_cast<int>(state.blocks.size()); ++b) {
    const Block& block = state.blocks[b];
    const int n = block.polygon.n_vertices();
    FISSURE_CHECK(static_cast<int>(block.initial_vertices.size()) == n, IoError,
                  block_label(state, b) << " has " << n << " vertices but "
                                        << block.initial_vertices.size() << " initial vertices");
    FISSURE_CHECK(block.polygon.n_loops() >= 1 && block.polygon.loop_offsets.back() == n, IoError,
                  block_label(state, b) << " has inconsistent loop offsets");
    const int first = mesh.block_vertex_offsets.back();

    mesh.block_names.push_back(block.name);
    mesh.block_material.push_back(block.material);
    mesh.block_fixed.push_back(block.fixed ? 1 : 0);
    for (int k = 1; k <= block.polygon.n_loops(); ++k)
      mesh.loop_offsets.push_back(first + block.polygon.loop_offsets[k]);
    mesh.block_loop_offsets.push_back(static_cast<int>(mesh.loop_offsets.size()) - 1);
    mesh.block_vertex_offsets.push_back(first + n);
    for (const Vec2& p : block.initial_vertices) {
      mesh.initial_vertices.push_back(p.x());
      mesh.initial_vertices.push_back(p.y());
    }

    // Triangulate the initial shape: the current one may already be deformed,
    // and the triangles must be the same for every frame.
    Polygon initial;
    initial.vertices = block.initial_vertices;
    initial.loop_offsets = block.polygon.loop_offsets;
    std::vector<std::array<int, 3>> triangles;
    try {
      triangles = triangulate(initial);
    } catch (const std::exception& e) {
      throw IoError(block_label(state, b) + " cannot be triangulated for output: " + e.what());
    }
    for (const auto& t : triangles) {
      for (int corner : t) mesh.triangles.push_back(first + corner);
      mesh.triangle_block.push_back(b);
    }
  }
  return mesh;
}

std::string topology_mismatch(const OutputMesh& mesh, const RockMass& state) {
  if (static_cast<int>(state.blocks.size()) != mesh.n_blocks())
    return "the number of blocks changed from " + std::to_string(mesh.n_blocks()) + " to " +
           std::to_string(state.blocks.size());
  for (int b = 0; b < mesh.n_blocks(); ++b) {
    const Polygon& polygon = state.blocks[b].polygon;
    const int first_loop = mesh.block_loop_offsets[b];
    const int n_loops = mesh.block_loop_offsets[b + 1] - first_loop;
    bool same = polygon.n_loops() == n_loops;
    for (int k = 0; same && k <= n_loops; ++k)
      same = polygon.loop_offsets[k] ==
             mesh.loop_offsets[first_loop + k] - mesh.block_vertex_offsets[b];
    if (!same) return "the vertex loops of " + block_label(state, b) + " changed";
  }
  return {};
}

}  // namespace fissure
