// The two halves of check_polygon (polygon_checks.h): checks of each loop on
// its own, then checks between edges (self-intersection, holes against the
// outer loop and against each other). Internal to core/geometry.
#pragma once

#include <vector>

#include "core/geometry/polygon.h"
#include "core/geometry/polygon_checks.h"

namespace fissure {

/// A loop with consecutive duplicate vertices merged.
struct CleanLoop {
  std::vector<int> vertices;  ///< global vertex indices, no two consecutive within tol
  bool finite = true;         ///< all coordinates finite
  bool usable = false;        ///< finite and at least 3 distinct vertices
  double area = 0;            ///< signed area (finite loops with >= 3 vertices)
  double perimeter = 0;
};

/// True when two vertices count as duplicates: closer than tol, or identical.
bool coincide(const Vec2& a, const Vec2& b, double tol);

/// Per-loop checks: vertex count, non-finite coordinates, duplicate
/// consecutive vertices, zero area (per loop and net), edges folding back.
/// Appends to `problems`; returns the cleaned loops for check_crossings.
std::vector<CleanLoop> check_loops(const Polygon& polygon, double tol,
                                   std::vector<PolygonProblem>& problems);

/// Edge-pair checks over the usable loops: non-adjacent edges closer than tol
/// (within a loop or across loops), holes outside the outer loop, holes
/// inside other holes. Grid broad phase over edge boxes: O(n + candidates).
void check_crossings(const Polygon& polygon, const std::vector<CleanLoop>& loops, double tol,
                     std::vector<PolygonProblem>& problems);

}  // namespace fissure
