// The water temperature in the fractures, as the shared field
// "fracture_fluid_temperature" (written by the thermal process's fracture
// convection, read by the flow for the viscosity mu(T) of the cubic law;
// theory.md 6.3, T -> H).
#pragma once

#include <vector>

#include "core/base/named_values.h"

namespace fissure {

/// Per fracture-graph segment (rockmass/fracture_graph.h indexing, as the
/// per-segment arrays of FractureFlowState): the water temperature (degC).
/// Absent: the flow's constant viscosity.
inline constexpr Key<std::vector<double>> kFractureFluidTemperature{"fracture_fluid_temperature"};

}  // namespace fissure
