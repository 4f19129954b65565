#include "core/io/frame_fields.h"

#include "core/state/monitor_values.h"

namespace fissure {

FrameFields gather_frame_fields(const OutputMesh& mesh, const RockMass& state) {
  FrameFields f;
  const std::size_t n = mesh.n_vertices();
  f.vertices.reserve(2 * n);
  f.displacement.reserve(3 * n);
  f.velocity.reserve(3 * n);
  for (const Block& block : state.blocks) {
    for (std::size_t v = 0; v < block.polygon.vertices.size(); ++v) {
      const Vec2& x = block.polygon.vertices[v];
      const Vec2 u = x - block.initial_vertices[v];
      const Vec2 velocity = block_velocity_at(block, x);
      f.vertices.insert(f.vertices.end(), {x.x(), x.y()});
      f.displacement.insert(f.displacement.end(), {u.x(), u.y(), 0.0});
      f.velocity.insert(f.velocity.end(), {velocity.x(), velocity.y(), 0.0});
    }
  }
  const std::size_t n_triangles = mesh.n_triangles();
  f.sxx.reserve(n_triangles);
  f.syy.reserve(n_triangles);
  f.sxy.reserve(n_triangles);
  for (int b : mesh.triangle_block) {
    const Vector3& s = state.blocks[b].stress;
    f.sxx.push_back(s(0));
    f.syy.push_back(s(1));
    f.sxy.push_back(s(2));
  }
  f.block_id = mesh.triangle_block;
  return f;
}

}  // namespace fissure
