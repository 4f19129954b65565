// Names of the sides of a rock domain, shared by the scene parser (which
// checks `fixed_blocks.boundaries`) and the block generator (which lists the
// fracture-graph nodes on each named boundary). docs/rock-mass.md,
// "Named boundaries".
#pragma once

#include <span>
#include <string>
#include <vector>

#include "core/geometry/vec2.h"

namespace fissure {

/// Per edge i -> i+1 of a domain loop, its side names: "left" when the edge
/// is vertical at the smallest x of the loop, "right" at the largest x,
/// "bottom" when horizontal at the smallest y, "top" at the largest y; none
/// otherwise. Comparisons are exact (the domain's own coordinates). O(n).
std::vector<std::vector<std::string>> domain_side_names(std::span<const Vec2> loop);

/// The names that some edge of the loop has, in the order left, right,
/// bottom, top.
std::vector<std::string> domain_sides(std::span<const Vec2> loop);

/// The vertices of a regular polygon inscribed in a circle, counter-clockwise,
/// the first at angle 0: centre + radius (cos 2 pi k / n, sin 2 pi k / n).
std::vector<Vec2> regular_polygon(const Vec2& centre, double radius, int n);

}  // namespace fissure
