// The fracture network of a block system (theory.md 3.3 "DDA, every step"):
// wherever two blocks' edges touch (collinear, opposite directions, with an
// overlap longer than the tolerance) the overlap is a fracture segment, with
// the two block faces it separates (BlockFace: block and polygon edge).
// Overlaps are split where another overlap ends on them (T-junctions), and
// coincident end points are one node. Named boundaries:
//   left, right, bottom, top  nodes on the sides of the blocks' bounding box;
//   exterior                  nodes on a stretch of block edge that touches
//                             no other block (where fractures open to the
//                             model's outer surface or to a hole).
#pragma once

#include <vector>

#include "core/state/rock_mass.h"
#include "rockmass/fracture_graph.h"

namespace fissure::flow {

/// Builds the network of `blocks` (current geometry); every segment gets
/// aperture e0 and the joint of its left face's edge. `tolerance` is an
/// absolute length (the scene's geometric tolerance).
FractureGraph network_from_blocks(const std::vector<Block>& blocks, double initial_aperture,
                                  double tolerance);

/// The scene's geometric tolerance: 1e-9 x the largest extent of the blocks'
/// bounding box (docs/scene-reference.md section 9).
double block_tolerance(const std::vector<Block>& blocks);

}  // namespace fissure::flow
