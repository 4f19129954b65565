// The nodes a mesh puts along a boundary piece: equal parts no longer than
// the smallest element size along it, placed from the piece's
// lexicographically smaller end, so that two blocks sharing the piece
// (thermal meshes) or meeting along it get the same points to the bit.
#pragma once

#include <vector>

#include "core/geometry/polygon_mesher.h"

namespace fissure {

/// The interior division points of the piece a -> b (not a, not b), in the
/// order from a to b: n equal parts, n = ceil(|b - a| / h) with h the
/// smallest of `size` at nine points along the piece.
std::vector<Vec2> divide_edge(const Vec2& a, const Vec2& b, const SizeFunction& size);

}  // namespace fissure
