// 2D vector type and the few exact-enough primitives every module uses.
#pragma once

#include <Eigen/Core>

namespace fissure {

using Vec2 = Eigen::Vector2d;

/// z-component of a x b.
inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// Twice the signed area of triangle (a, b, c); > 0 when counter-clockwise.
inline double orient(const Vec2& a, const Vec2& b, const Vec2& c) { return cross(b - a, c - a); }

/// Counter-clockwise rotation by 90 degrees.
inline Vec2 perp(const Vec2& a) { return Vec2(-a.y(), a.x()); }

}  // namespace fissure
