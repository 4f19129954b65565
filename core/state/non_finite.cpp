#include "core/state/non_finite.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace fissure {

std::string non_finite_block(const RockMass& state) {
  for (std::size_t b = 0; b < state.blocks.size(); ++b) {
    const Block& block = state.blocks[b];
    const std::vector<Vec2>& vertices = block.polygon.vertices;
    const char* what = !block.velocity.allFinite()      ? "velocity"
                       : !block.stress.allFinite()      ? "stress"
                       : !block.strain.allFinite()      ? "strain"
                       : !std::isfinite(block.rotation) ? "rotation"
                       : !std::all_of(vertices.begin(), vertices.end(),
                                      [](const Vec2& v) { return v.allFinite(); })
                           ? "vertex coordinates"
                           : nullptr;
    if (what) return fmt::format("block '{}' ({}) has a non-finite {}", block.name, b, what);
  }
  return {};
}

}  // namespace fissure
