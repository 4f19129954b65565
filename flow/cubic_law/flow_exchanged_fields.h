// The flow's fields that the others read, as the iterated scheme tests and
// relaxes them (SectionReader::exchanges, Process::exchanged_values): the
// pressures on the block walls (the mechanics), the segments' fluxes and
// apertures at both ends (the fracture water's heat), the flows its mouths
// give a continuum (flow_ties.h). Not the node pressures: a transient update
// starts from them.
#pragma once

#include "core/scene/exchanged_field.h"
#include "flow/cubic_law/read_flow_settings.h"
#include "rockmass/fields/fracture_flow.h"
#include "rockmass/fields/pressure_loads.h"

namespace fissure::flow {

enum ExchangedFlowField : std::size_t {
  kWallPressure,
  kSegmentFlux,
  kSegmentAperture,
  kTieFluidFlow
};

inline constexpr ExchangedFieldKind kExchangedFields[] = {
    {kPressureLoads.name, &quantity::stress},
    {"fracture_flow.flux", &quantity::flow_rate},
    {"fracture_flow.aperture", &quantity::length},
    {"continuum_interface_loads.fluid", &quantity::flow_rate},
};

}  // namespace fissure::flow
