// Checks shared by the block-cutting tests: the blocks tile the rock (areas,
// validity, no overlaps) and the fracture graph is consistent with them.
#pragma once

#include <string>
#include <vector>

#include "core/geometry/polygon.h"
#include "rockmass/fracture_graph.h"

namespace fissure::testing {

/// Sum of the blocks' areas (outer loop minus holes).
double total_area(const std::vector<Polygon>& blocks);

/// Problems of the block system, one line each, at most `max_lines`: blocks
/// that fail check_polygon at `tolerance`, are not oriented (outer loop
/// counter-clockwise, holes clockwise), or overlap another block.
std::vector<std::string> block_system_problems(const std::vector<Polygon>& blocks, double tolerance,
                                               size_t max_lines = 10);

/// Problems of a fracture graph against its blocks: node indices, zero-length
/// segments, block faces out of range, a face's edge that is not the segment
/// (its end points differ from the block's edge by more than `tolerance`).
std::vector<std::string> fracture_graph_problems(const FractureGraph& graph,
                                                 const std::vector<Polygon>& blocks,
                                                 double tolerance, size_t max_lines = 10);

}  // namespace fissure::testing
