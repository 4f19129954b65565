// Tolerance-aware predicates on points and segments, shared by the polygon
// checks, point location and overlap detection.
//
// Tolerance rule: `tol` is an absolute length. A point is "on" a line or a
// segment when its Euclidean distance to it is <= tol, so orientation tests
// compare orient(a, b, c) (twice the signed triangle area) with tol * |b - a|,
// never with a bare epsilon. orient() is evaluated relative to a, so its
// rounding error is about 1e-16 x |b - a| x |c - a|: the classification is
// reliable whenever tol exceeds a few 1e-16 x the coordinate magnitude (the
// scene's 1e-9 x model size is far above that, also 1e6 m from the origin).
#pragma once

#include "core/geometry/vec2.h"

namespace fissure {

/// Euclidean distance from p to the closed segment [a, b] (a == b allowed).
double point_segment_distance(const Vec2& p, const Vec2& a, const Vec2& b);

/// Parameter t in [0, 1] of the point of [a, b] closest to p.
double closest_parameter(const Vec2& p, const Vec2& a, const Vec2& b);

/// Side of c relative to the directed line a -> b: +1 left and -1 right by
/// more than tol, 0 within tol of the line (or when a == b).
int side_of_line(const Vec2& a, const Vec2& b, const Vec2& c, double tol);

/// True when [a, b] and [c, d] cross at a single interior point with each
/// segment's endpoints on opposite sides of the other's line by more than tol.
/// With tol = 0 this is the plain proper-crossing test.
bool segments_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, double tol);

/// Euclidean distance between the closed segments [a, b] and [c, d] (0 when
/// they cross).
double segment_distance(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);

/// Parameter s on [a, b] of the crossing with the line through c, d; only
/// meaningful when segments_cross(a, b, c, d, 0).
double crossing_parameter(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);

/// A point where [a, b] and [c, d] meet, or the midpoint of their closest
/// approach when they do not meet (used in messages).
Vec2 meeting_point(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);

}  // namespace fissure
