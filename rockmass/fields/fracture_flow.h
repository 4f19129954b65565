// The flow state on the fracture graph, as the shared field "fracture_flow"
// (written by the flow process; read by its output and, later, by the heat
// transport in the fractures).
#pragma once

#include <vector>

#include "core/base/named_values.h"

namespace fissure {

/// Flow state on the fracture graph (rockmass/fracture_graph.h).
struct FractureFlowState {
  std::vector<double> pressure;    ///< per node, Pa
  std::vector<double> aperture_a;  ///< per segment: hydraulic aperture at node_a, m
  std::vector<double> aperture_b;  ///< per segment: hydraulic aperture at node_b, m
  std::vector<double> flux;        ///< per segment, node_a -> node_b, m^2/s (per unit thickness)
};

inline constexpr Key<FractureFlowState> kFractureFlow{"fracture_flow"};

}  // namespace fissure
