// The blocks of the block sources (the rock mass), generated after every
// section was read and appended to the blocks read from `blocks`, so that
// fixed points, loads and monitors can be attached to them and every
// geometry check sees them.
#include <fmt/format.h>

#include "core/base/errors.h"
#include "core/scene/scene_draft.h"

namespace fissure {

void generate_blocks(SceneDraft& draft, Diagnostics& diagnostics) {
  Scene& scene = draft.scene;
  for (const PendingBlockSource& source : draft.pending_block_sources) {
    const std::string key(source.reader->key);
    SectionContext context(draft);
    std::vector<BlockSpec> generated;
    try {
      generated = source.reader->generate(context, static_cast<int>(scene.blocks.size()));
    } catch (const Error& e) {
      diagnostics.error(source.key_at, key, e.what());
      continue;
    }
    // A name that clashes with a block of `blocks` is reported at the source.
    const ConfigNode at = ConfigNode::absent(key, source.key_at, diagnostics);
    for (size_t b = 0; b < generated.size(); ++b) {
      BlockSpec& block = generated[b];
      block.location = source.key_at;
      BlockSource where;
      where.path = fmt::format("{} (generated block {}, '{}')", key, b, block.name);
      where.vertices_at = source.key_at;
      where.holes_at = source.key_at;
      where.geometry_read = true;
      draft.blocks.add(block.name, at);
      scene.blocks.push_back(std::move(block));
      draft.block_sources.push_back(std::move(where));
    }
  }
}

}  // namespace fissure
