#include "flow/hm/fracture_walls.h"

#include <Eigen/Dense>

namespace fissure::flow {

std::vector<SegmentWalls> segment_walls(const FractureGraph& g, const std::vector<Vec2>& reference,
                                        const std::vector<BlockMap>& maps) {
  std::vector<SegmentWalls> walls(g.n_segments());
  for (int s = 0; s < g.n_segments(); ++s) {
    const FractureSegment& seg = g.segments[s];
    const Vec2 a = reference[seg.node_a], b = reference[seg.node_b];
    SegmentWalls& w = walls[s];
    const int l = seg.left.block, r = seg.right.block;
    w.left_a = l >= 0 ? maps[l](a) : a;
    w.left_b = l >= 0 ? maps[l](b) : b;
    w.right_a = r >= 0 ? maps[r](a) : a;
    w.right_b = r >= 0 ? maps[r](b) : b;
    w.mechanical = l >= 0 && r >= 0 && l != r;
  }
  return walls;
}

}  // namespace fissure::flow
