#include "core/state/rock_mass.h"

namespace fissure {

RockMass RockMass::from_scene(const Scene& scene) {
  RockMass state;
  state.materials = scene.materials;
  state.joints = scene.joints;
  state.gravity = scene.gravity;
  state.blocks.reserve(scene.blocks.size());
  for (const BlockSpec& spec : scene.blocks) {
    Block b;
    b.name = spec.name;
    b.polygon = spec.polygon;
    b.initial_vertices = spec.polygon.vertices;
    // Per-edge joints (generated blocks: the joint of each edge's fracture),
    // where -1 means the block's joint.
    const int block_joint = spec.joint >= 0 ? spec.joint : scene.default_joint;
    b.edge_joint.assign(spec.polygon.vertices.size(), block_joint);
    if (spec.edge_joint.size() == spec.polygon.vertices.size())
      for (size_t v = 0; v < spec.edge_joint.size(); ++v)
        if (spec.edge_joint[v] >= 0) b.edge_joint[v] = spec.edge_joint[v];
    b.material = spec.material;
    b.fixed = spec.fixed;
    b.section = section_properties(b.polygon);
    b.initial_area = b.section.area;
    b.velocity << spec.initial_velocity(0), spec.initial_velocity(1), spec.initial_velocity(2), 0,
        0, 0;
    if (b.fixed) b.velocity.setZero();
    b.stress = spec.initial_stress;
    state.blocks.push_back(std::move(b));
  }
  state.fields = scene.initial_fields;
  auto add_point = [&state](int block, const Vec2& p) {
    state.points.push_back(MaterialPoint{block, p, p});
  };
  for (const Monitor& m : scene.monitors) add_point(m.block, m.point);
  state.first_fixed_point = static_cast<int>(state.points.size());
  for (const FixedPoint& f : scene.fixed_points) add_point(f.block, f.point);
  state.first_load_point = static_cast<int>(state.points.size());
  for (const PointLoad& l : scene.point_loads) add_point(l.block, l.point);
  return state;
}

}  // namespace fissure
