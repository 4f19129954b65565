// Where the two walls of every fracture segment are now (theory.md 6.3,
// M -> H). A DDA block moves and deforms affinely (rigid motion plus constant
// strain, theory.md 1.1), so the map from a block's initial to its current
// vertices, x = A X + c, is exact for any material point; it is recovered by
// least squares over the block's vertices. Each segment end, a point of both
// walls at t = 0, is then followed on either wall.
#pragma once

#include <vector>

#include "core/state/rock_mass.h"
#include "rockmass/fracture_graph.h"

namespace fissure::flow {

struct BlockMap {
  Eigen::Matrix2d a = Eigen::Matrix2d::Identity();
  Vec2 c = Vec2::Zero();
  Vec2 operator()(const Vec2& x) const { return a * x + c; }
};

/// Initial -> current map of every block (identity for fixed blocks).
std::vector<BlockMap> block_maps(const std::vector<Block>& blocks);

/// Current wall positions of one segment: the ends on the left and right wall.
struct SegmentWalls {
  Vec2 left_a, left_b, right_a, right_b;
  bool mechanical = false;  ///< both faces are (different) blocks: walls can move apart
};

/// `reference` are the node positions at t = 0. A side without a block
/// stays at the reference position.
std::vector<SegmentWalls> segment_walls(const FractureGraph& graph,
                                        const std::vector<Vec2>& reference,
                                        const std::vector<BlockMap>& maps);

}  // namespace fissure::flow
