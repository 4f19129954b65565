// Where the two walls of every fracture segment are now (theory.md 6.3,
// M -> H). A DDA block moves and deforms affinely (rigid motion plus constant
// strain, theory.md 1.1), so the map from a block's reference to its current
// vertices, x = A X + c, is exact for any material point; it is recovered by
// least squares over the block's vertices. The reference is the geometry the
// network was cut from (the blocks' initial vertices when the flow starts:
// as cut, also after an initial stage has settled the blocks, docs/flow.md 7).
// Each segment end, a point of both walls there, is then followed on either
// wall.
#pragma once

#include <vector>

#include "core/state/rock_mass.h"
#include "rockmass/block_motion.h"
#include "rockmass/fracture_graph.h"

namespace fissure::flow {

using fissure::block_maps;
using fissure::BlockMap;
using fissure::BlockReference;
using fissure::initial_geometry;

/// Current wall positions of one segment: the ends on the left and right wall.
struct SegmentWalls {
  Vec2 left_a, left_b, right_a, right_b;
  bool mechanical = false;  ///< both faces are (different) blocks: walls can move apart
};

/// `reference` are the node positions in the reference geometry. A side without a block
/// stays at the reference position.
std::vector<SegmentWalls> segment_walls(const FractureGraph& graph,
                                        const std::vector<Vec2>& reference,
                                        const std::vector<BlockMap>& maps);

}  // namespace fissure::flow
