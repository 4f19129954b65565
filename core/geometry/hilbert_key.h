// A point's place along a Hilbert curve: points close on the curve are
// close in the plane, so that a run of points sorted by it is a compact
// part of the domain (the rows and elements each MPI rank owns).
#pragma once

#include <span>
#include <vector>

#include "core/geometry/vec2.h"

namespace fissure {

/// The key of (x, y) along the Hilbert curve of 2^16 x 2^16 cells over the
/// box [x_lo, x_hi] x [y_lo, y_hi] (points outside it are clamped).
double hilbert_key(double x, double y, double x_lo, double y_lo, double x_hi, double y_hi);

/// The indices of `points` in their order along the Hilbert curve over the
/// box [lo, hi] (hilbert_key), points of the same key in their given order.
std::vector<int> hilbert_order(std::span<const Vec2> points, const Vec2& lo, const Vec2& hi);

}  // namespace fissure
