// Clipping a segment to an axis-aligned box (Liang and Barsky 1984, ACM
// Trans. Graph. 3:1): the flow's trace networks keep what lies in their
// domain, the block cutter what lies near its rock (rockmass/block_cutter.h).
#pragma once

#include "core/geometry/polygon.h"

namespace fissure {

/// Clips [a, b] to the box; false when nothing is left. Both ends are
/// recomputed from a + t (b - a), so an end inside the box may move by
/// round-off.
bool clip_to_box(Vec2& a, Vec2& b, const Box& box);

}  // namespace fissure
