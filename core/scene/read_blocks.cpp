// Top-level key `blocks`: names, material and joint references, polygons and
// initial conditions. The polygons are checked later (check_geometry.cpp),
// once the tolerance, which depends on all blocks, is known.
#include <fmt/format.h>

#include "core/scene/joint_models.h"
#include "core/scene/scene_draft.h"
#include "core/scene/scene_keys.h"

namespace fissure {

namespace {

void read_name(ConfigMap& map, int index, NameRegistry& registry, BlockSpec& block) {
  std::optional<ConfigNode> node = map.optional("name");
  if (!node) {
    block.name = fmt::format("block{}", index);
    registry.add(block.name, map.node());
    return;
  }
  const std::optional<std::string> name = node->string("a block name");
  if (!name) {
    registry.add_unreadable();
    return;
  }
  if (*name == "none")
    node->error(
        "found 'none', which is reserved (a monitor with `block: none` stays fixed in space); "
        "expected another block name");
  block.name = *name;
  registry.add(*name, *node);
}

void read_geometry(ConfigMap& map, BlockSpec& block, BlockSource& source) {
  std::optional<std::vector<Vec2>> outer;
  if (auto node = map.required("vertices", "a list of at least 3 vertices [x, y]")) {
    source.vertices_at = node->key_location();
    outer = node->points(quantity::length, false);
  } else {
    source.vertices_at = map.node().location();
  }
  source.holes_at = source.vertices_at;

  std::vector<std::vector<Vec2>> holes;
  bool holes_ok = true;
  if (auto node = map.optional("holes")) {
    source.holes_at = node->key_location();
    if (auto items = node->list("holes (each a list of vertices [x, y])", false)) {
      for (const ConfigNode& item : *items) {
        if (auto loop = item.points(quantity::length, false))
          holes.push_back(std::move(*loop));
        else
          holes_ok = false;
      }
    } else {
      holes_ok = false;
    }
  }

  if (!outer || !holes_ok) return;
  block.polygon = Polygon(std::move(*outer));
  for (const std::vector<Vec2>& hole : holes) block.polygon.add_loop(hole);
  source.geometry_read = true;
}

void read_initial_state(ConfigMap& map, BlockSpec& block, const Scene& scene) {
  map.read("fixed", block.fixed);

  if (auto node = map.optional("initial_stress")) {
    const QuantityKind* kinds[] = {&quantity::stress, &quantity::stress, &quantity::stress};
    if (auto s = node->numbers(kinds, "[sxx, syy, sxy]")) {
      block.initial_stress = Eigen::Vector3d((*s)[0], (*s)[1], (*s)[2]);
      // Its edges' joint must hold the stress (Barton-Bandis: below JCS).
      const int joint = block.joint >= 0 ? block.joint : scene.default_joint;
      if (joint >= 0 && joint < static_cast<int>(scene.joints.size()))
        check_joint_stress_limit(*node, block.initial_stress, scene.joints[joint]);
    }
  }

  if (auto node = map.optional("initial_velocity")) {
    const QuantityKind* kinds[] = {&quantity::velocity, &quantity::velocity,
                                   &quantity::angular_velocity};
    if (auto v = node->numbers(kinds, "[vx, vy, omega]")) {
      block.initial_velocity = Eigen::Vector3d((*v)[0], (*v)[1], (*v)[2]);
      if (block.fixed && !block.initial_velocity.isZero(0))
        node->error("found " + node->found() +
                    " on a fixed block; expected [0, 0, 0] or no initial_velocity (a fixed "
                    "block does not move), or fixed: false");
    }
  }
}

BlockSpec read_block(const ConfigNode& node, int index, SceneDraft& draft, BlockSource& source) {
  ConfigMap map(node, scene_keys::block);
  BlockSpec block;
  block.location = node.location();
  source.path = node.path();

  read_name(map, index, draft.blocks, block);

  // material: may be left out when the scene has a single material.
  if (auto m = map.optional("material")) {
    if (auto i = draft.materials.resolve(*m)) block.material = *i;
  } else if (draft.scene.materials.size() > 1) {
    map.report_missing("material",
                       "the name of a material (required when the scene has more than one)");
  }

  if (auto j = map.optional("joint"))
    if (auto i = draft.joints.resolve(*j)) block.joint = *i;

  read_geometry(map, block, source);
  read_initial_state(map, block, draft.scene);
  return block;
}

}  // namespace

void read_blocks(ConfigMap& top, SceneDraft& draft,
                 const std::vector<std::string_view>& other_sources) {
  // With a rock mass the blocks are generated, a meshed domain has its own
  // geometry; `blocks` may add more.
  const bool generated = !other_sources.empty();
  std::optional<ConfigNode> node =
      generated ? top.optional("blocks")
                : top.required("blocks", "a non-empty list of blocks (or a rock_mass section)");
  if (generated && !node) return;
  std::optional<ConfigList> items;
  if (node) items = node->list("blocks", !generated);
  if (!items) {
    draft.blocks.add_unreadable();  // references to blocks cannot be checked
    return;
  }
  for (const ConfigNode& item : *items) {
    BlockSource source;
    const int index = static_cast<int>(draft.scene.blocks.size());
    draft.scene.blocks.push_back(read_block(item, index, draft, source));
    draft.block_sources.push_back(std::move(source));
  }
}

}  // namespace fissure
