// How a block has moved since a reference geometry (theory.md 6.3): a DDA
// block moves and deforms affinely (rigid motion plus constant strain,
// theory.md 1.1), so the map from a block's reference to its current
// vertices, x = A X + c, is exact for any material point; it is recovered by
// least squares over the block's vertices. Used by the flow (fracture walls)
// and the thermal process (its block meshes).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/state/rock_mass.h"

namespace fissure {

struct BlockMap {
  Eigen::Matrix2d a = Eigen::Matrix2d::Identity();
  Vec2 c = Vec2::Zero();
  Vec2 operator()(const Vec2& x) const { return a * x + c; }
};

/// Per block, the vertices the walls are followed from.
using BlockReference = std::vector<std::vector<Vec2>>;

/// The blocks' initial vertices (Block::initial_vertices) as a reference.
BlockReference initial_geometry(const std::vector<Block>& blocks);

/// Reference -> current map of every block (identity for fixed blocks).
std::vector<BlockMap> block_maps(const std::vector<Block>& blocks, const BlockReference& reference);

}  // namespace fissure
