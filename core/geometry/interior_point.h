// A point well inside a polygon with holes (for containment tests: "is block
// A inside block B?" when no boundary point decides it).
#pragma once

#include "core/geometry/polygon.h"

namespace fissure {

struct InteriorPoint {
  Vec2 point = Vec2::Zero();
  double depth = 0;  ///< lower bound on the distance from `point` to the boundary
};

/// Looks along horizontal lines halfway between consecutive vertex heights
/// (the widest such bands first); on such a line the polygon is a set of
/// intervals bounded by edges that span the whole band, so the midpoint of an
/// interval has a cheap, exact lower bound on its depth. Returns the deepest
/// candidate; depth 0 when the polygon has no interior (fewer than two
/// distinct vertex heights). Holes are respected whatever the loop
/// orientation (even-odd rule). Cost O(k n log n) with k <= 16 bands.
InteriorPoint interior_point(const Polygon& polygon);

}  // namespace fissure
