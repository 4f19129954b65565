// Top-level keys `materials`, `joints` and `default_joint`.
#include "core/scene/joint_models.h"
#include "core/scene/scene_draft.h"
#include "core/scene/scene_keys.h"

namespace fissure {

namespace {

/// Reads the required `name` of a list item into `registry`.
std::string read_item_name(ConfigMap& map, NameRegistry& registry, const std::string& what) {
  if (auto node = map.required("name", "a " + what + " name")) {
    if (auto name = node->string("a " + what + " name")) {
      registry.add(*name, *node);
      return *name;
    }
  }
  registry.add_unreadable();
  return {};
}

Material read_material(const ConfigNode& node, NameRegistry& registry) {
  ConfigMap map(node, scene_keys::material);
  Material m;
  m.name = read_item_name(map, registry, "material");
  map.read_required("density", m.density, quantity::density, Range::positive());
  map.read_required("young_modulus", m.young_modulus, quantity::stress, Range::positive());
  map.read_required("poisson_ratio", m.poisson_ratio, quantity::dimensionless,
                    Range::open(-1, 0.5));
  return m;
}

/// The name and the Coulomb keys; the model and its keys with the joint
/// laws' reader (joint_models.h).
JointProperties read_joint(const ConfigNode& node, NameRegistry& registry) {
  ConfigMap map(node, joint_entry_keys());
  JointProperties j;
  j.name = read_item_name(map, registry, "joint");
  map.read_required("friction_angle", j.friction_angle, quantity::angle,
                    Range::closed_open(0, 90 * quantity::kDegree));
  map.read("cohesion", j.cohesion, quantity::stress, Range::non_negative());
  map.read("tensile_strength", j.tensile_strength, quantity::stress, Range::non_negative());
  if (const JointModelReader* reader = joint_model_reader()) reader->read(map, j);
  return j;
}

}  // namespace

void read_materials(ConfigMap& top, SceneDraft& draft) {
  Scene& scene = draft.scene;

  if (auto node = top.required("materials", "a non-empty list of materials")) {
    if (auto items = node->list("materials", true))
      for (const ConfigNode& item : *items)
        scene.materials.push_back(read_material(item, draft.materials));
    else
      draft.materials.add_unreadable();
  } else {
    draft.materials.add_unreadable();
  }

  // Joints: the contact laws (a process that needs them says so).
  if (auto joints = top.optional("joints")) {
    if (auto items = joints->list("joints", false))
      for (const ConfigNode& item : *items) scene.joints.push_back(read_joint(item, draft.joints));
    else
      draft.joints.add_unreadable();
  }

  // default_joint: the joint of blocks that name none; default the first.
  if (auto node = top.optional("default_joint"))
    if (auto j = draft.joints.resolve(*node)) scene.default_joint = *j;
}

}  // namespace fissure
