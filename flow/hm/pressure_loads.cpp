#include "flow/hm/pressure_loads.h"

namespace fissure::flow {

std::vector<EdgePressureLoad> wall_pressure_loads(const FractureGraph& g,
                                                  const std::vector<SegmentWalls>& walls,
                                                  const std::vector<double>& pressure,
                                                  const std::vector<Block>& blocks) {
  std::vector<EdgePressureLoad> loads;
  for (int s = 0; s < g.n_segments(); ++s) {
    const FractureSegment& seg = g.segments[s];
    if (seg.left.block == seg.right.block) continue;
    const double pa = pressure[seg.node_a], pb = pressure[seg.node_b];
    if (pa == 0 && pb == 0) continue;
    const SegmentWalls& w = walls[s];
    // The left block lies left of a -> b: its outward normal is the right
    // perpendicular of its wall; the right block's is the opposite of its own.
    if (seg.left.block >= 0 && !blocks[seg.left.block].fixed) {
      const Vec2 t = (w.left_b - w.left_a).normalized();
      loads.push_back({seg.left.block, w.left_a, w.left_b, pa, pb, Vec2(t.y(), -t.x())});
    }
    if (seg.right.block >= 0 && !blocks[seg.right.block].fixed) {
      const Vec2 t = (w.right_b - w.right_a).normalized();
      loads.push_back({seg.right.block, w.right_a, w.right_b, pa, pb, Vec2(-t.y(), t.x())});
    }
  }
  return loads;
}

}  // namespace fissure::flow
