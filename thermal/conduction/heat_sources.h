// Heat sources on the block meshes (docs/thermal.md 4): where each source
// is (its block, found in the reference geometry: a source moves with its
// block) and how its power is spread over the mesh nodes. The mesh has a
// node at each point source and edges along line sources and area-source
// outlines (thermal_mesh.h), so the spreading is exact: the node of a point,
// int N_i ds / L along a line, int N_i dA / A over an area.
#pragma once

#include <utility>
#include <vector>

#include "core/state/rock_mass.h"
#include "thermal/conduction/thermal_mesh.h"
#include "thermal/conduction/thermal_settings.h"

namespace fissure::thermal {

/// Per source, the block that holds it. Throws fissure::Error, naming the
/// scene line, for a source outside the rock (in no block, or in a hole) or
/// across a block boundary.
std::vector<int> source_blocks(const std::vector<HeatSource>& sources,
                               const std::vector<Block>& blocks);

/// Per source, (node, weight) pairs with weights summing to 1.
using NodalWeights = std::vector<std::pair<int, double>>;
std::vector<NodalWeights> source_weights(const std::vector<HeatSource>& sources,
                                         const std::vector<int>& source_block,
                                         const ThermalMesh& mesh);

}  // namespace fissure::thermal
