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

ContactFields gather_contact_fields(const RockMass& state) {
  ContactFields c;
  for (const ContactRecord& r : state.contacts) {
    c.cells.push_back(c.size());
    c.points.insert(c.points.end(), {r.point.x(), r.point.y()});
    c.normal.insert(c.normal.end(), {r.normal.x(), r.normal.y(), 0.0});
    c.state.push_back(static_cast<int>(r.state));
    c.gap.push_back(r.gap);
    c.normal_force.push_back(r.normal_force);
    c.shear_force.push_back(r.shear_force);
    c.block_i.push_back(r.block_i);
    c.block_j.push_back(r.block_j);
  }
  return c;
}

FractureFields gather_fracture_geometry(const FractureGraph& graph) {
  FractureFields f;
  f.nodes.reserve(2 * graph.nodes.size());
  for (const Vec2& p : graph.nodes) f.nodes.insert(f.nodes.end(), {p.x(), p.y()});
  f.segments.reserve(2 * graph.segments.size());
  for (const FractureSegment& s : graph.segments)
    f.segments.insert(f.segments.end(), {s.node_a, s.node_b});
  return f;
}

FractureFields gather_fracture_fields(const RockMass& state, const HeadDefinition& head) {
  const FractureGraph& g = state.fractures;
  const FractureFlowState& flow = state.flow;
  FractureFields f = gather_fracture_geometry(g);
  const std::size_t n = g.nodes.size(), m = g.segments.size();
  // A flow state of another size belongs to no graph we could draw it on.
  f.flow = m > 0 && flow.pressure.size() == n && flow.aperture_a.size() == m &&
           flow.aperture_b.size() == m && flow.flux.size() == m;
  if (!f.flow) return f;
  f.pressure = flow.pressure;
  if (head.active()) {
    f.head.reserve(n);
    for (std::size_t v = 0; v < n; ++v) f.head.push_back(head.head(flow.pressure[v], g.nodes[v]));
  }
  f.aperture_a = flow.aperture_a;
  f.aperture_b = flow.aperture_b;
  f.aperture_mean.reserve(m);
  for (std::size_t s = 0; s < m; ++s)
    f.aperture_mean.push_back(0.5 * (flow.aperture_a[s] + flow.aperture_b[s]));
  f.flux = flow.flux;
  return f;
}

}  // namespace fissure
