// Fluid pressure on the fracture walls as loads on the blocks (theory.md 3.5,
// 6.3 H -> M): both walls of every segment are loaded by the linear pressure
// between its end nodes, each along the block's outward normal (from its wall
// into the fracture). The springs of the mechanics then carry the effective
// stress sigma_n' = sigma_n - p. Walls of fixed blocks, and segments inside
// one block (dangling fracture ends: the two loads cancel), are skipped.
#pragma once

#include <vector>

#include "core/state/rock_mass.h"
#include "flow/hm/fracture_walls.h"
#include "rockmass/fields/pressure_loads.h"
#include "rockmass/fracture_graph.h"

namespace fissure::flow {

/// Loads for the current wall positions and node pressures (Pa).
std::vector<EdgePressureLoad> wall_pressure_loads(const FractureGraph& graph,
                                                  const std::vector<SegmentWalls>& walls,
                                                  const std::vector<double>& pressure,
                                                  const std::vector<Block>& blocks);

}  // namespace fissure::flow
