// Validity checks for block polygons and block systems (docs/scene-reference.md section 9,
// issue "Bad input"): too few vertices, non-finite coordinates, duplicate
// consecutive vertices, zero area, self-intersection, holes outside the outer
// loop or overlapping each other, and blocks that overlap at the start.
// `tolerance` is an absolute length (the scene uses 1e-9 x model size).
//
// Tolerance rule (one rule everywhere, see segment_predicates.h):
//  * two points coincide when their distance is < tol (or exactly 0);
//  * a point is on an edge when its distance to the segment is <= tol, so
//    orientation tests compare orient(a, b, c) with tol x |b - a|;
//  * two edges meet (intersect or touch) when the distance between the
//    segments is <= tol;
//  * a loop has zero area when |area| <= tol x perimeter.
// Results are reliable when tol exceeds a few 1e-16 x the largest coordinate
// (1e-9 x model size is far above that, also 1e6 m from the origin).
//
// Cost: edge pairs come from a BoxGrid over edge boxes (inflated by tol), so
// the checks are O(n + candidate pairs), not O(n^2); polygons of 1e5 vertices
// with short edges take milliseconds. Loop orientation is not a problem here
// (orient_loops fixes it); every check is orientation-independent.
#pragma once

#include <limits>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/geometry/polygon.h"

namespace fissure {

struct PolygonProblem {
  int loop = 0;      ///< loop index (0 = outer)
  int vertex = -1;   ///< vertex index within the loop, -1 if not vertex-specific
  std::string what;  ///< e.g. "loop 0: edges 2-3 and 5-6 intersect at (1.5, 0.25)"
};

/// All problems that make `polygon` unusable as a block; empty when valid.
/// Per loop, in loop order: fewer than 3 vertices; non-finite coordinates (the
/// loop is then excluded from the geometric checks); duplicate consecutive
/// vertices, last-first included (merged before the edge checks so that they
/// are not reported again as touching edges); zero area; adjacent edges that
/// fold back over each other (a zero-width spike). Then: zero net area (outer
/// minus holes); non-adjacent edges that intersect or touch, within a loop or
/// across loops (named as self-intersection, hole against outer loop, or hole
/// against hole, with the meeting point; one report per point, at most 100
/// listed plus a count of the rest); holes outside the outer loop; holes
/// inside other holes. Malformed loop_offsets or a negative tolerance give a
/// single problem.
std::vector<PolygonProblem> check_polygon(const Polygon& polygon, double tolerance);

/// Orients loop 0 counter-clockwise and every further loop clockwise. A loop
/// is reversed in place keeping its first vertex first (vertex indices of
/// that loop change; the loop structure does not).
void orient_loops(Polygon& polygon);

/// +1 strictly inside, 0 on the boundary (within tolerance), -1 outside.
/// Holes are respected (even-odd rule, whatever the loop orientation). For
/// many queries on one polygon, build a PolygonLocator (polygon_locator.h).
int locate_point(const Polygon& polygon, const Vec2& p, double tolerance);

/// Pairs (i < j) of polygons whose interiors overlap (touching along edges or
/// at vertices is not an overlap). Uses a grid broad phase, not all pairs.
/// Sorted. Overlap means one polygon penetrates the other by more than the
/// tolerance: some point of one (vertex, edge point or interior point) lies
/// inside the other farther than tolerance from its boundary. So identical
/// polygons, containment (also with shared boundary) and partial overlaps are
/// reported; touching, gaps, and penetrations up to the tolerance are not; a
/// block inside another block's hole is not. Polygons with fewer than 3
/// vertices or non-finite coordinates are skipped (check_polygon reports
/// them). Stops after `max_pairs` pairs (a report of a bounded size: 10,000
/// copies of one block are 5e7 pairs). Details in polygon_overlap.cpp.
std::vector<std::pair<int, int>> find_overlapping_pairs(
    std::span<const Polygon> polygons, double tolerance,
    std::size_t max_pairs = std::numeric_limits<std::size_t>::max());

}  // namespace fissure
