// The blocks and fracture graph of a rock mass, generated at parse time by the
// generator the caller passed in (parse_scene.h) and appended to the blocks
// read from `blocks`, so that fixed points, loads and monitors can be attached
// to them and every geometry check sees them.
#include <fmt/format.h>

#include "core/base/errors.h"
#include "core/scene/scene_draft.h"

namespace fissure {

void generate_rock_mass_blocks(SceneDraft& draft, const RockMassGenerator& generator,
                               Diagnostics& diagnostics) {
  Scene& scene = draft.scene;
  if (!scene.rock_mass || !draft.rock_mass_valid) return;
  if (!generator) {
    diagnostics.error(draft.rock_mass_at, "rock_mass",
                      "found a rock mass, but this program cannot generate blocks from one; "
                      "expected the fissure command line (parse_scene with scene_generators())");
    return;
  }

  GeneratedRockMass generated;
  try {
    generated = generator(*scene.rock_mass);
  } catch (const Error& e) {
    diagnostics.error(draft.rock_mass_at, "rock_mass", e.what());
    return;
  }

  const int offset = static_cast<int>(scene.blocks.size());
  // A name that clashes with a block of `blocks` is reported at the rock mass.
  const ConfigNode at =
      ConfigNode::root(YAML::Node(), diagnostics).child(YAML::Node(), "rock_mass", draft.rock_mass_at);
  for (size_t b = 0; b < generated.blocks.size(); ++b) {
    BlockSpec& block = generated.blocks[b];
    block.location = draft.rock_mass_at;
    BlockSource source;
    source.path = fmt::format("rock_mass (generated block {}, '{}')", b, block.name);
    source.vertices_at = draft.rock_mass_at;
    source.holes_at = draft.rock_mass_at;
    source.geometry_read = true;
    draft.blocks.add(block.name, at);
    scene.blocks.push_back(std::move(block));
    draft.block_sources.push_back(std::move(source));
  }
  for (FractureSegment& s : generated.fractures.segments) {
    for (BlockFace* face : {&s.left, &s.right})
      if (face->block >= 0) face->block += offset;
  }
  scene.fractures = std::move(generated.fractures);
  scene.rock_mass_statistics = generated.statistics;
}

}  // namespace fissure
