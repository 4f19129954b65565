// The flow's fields that the others read, as the iterated scheme tests and
// relaxes them (SectionReader::exchanges, Process::exchanged_values): the
// pressures on the block walls (the mechanics), the segments' fluxes and
// apertures at both ends (the fracture water's heat). Not the node
// pressures: a transient update starts from them.
#pragma once

#include "core/scene/exchanged_field.h"
#include "flow/cubic_law/read_flow_settings.h"
#include "rockmass/fields/fracture_flow.h"
#include "rockmass/fields/pressure_loads.h"

namespace fissure::flow {

enum ExchangedFlowField : std::size_t { kWallPressure, kSegmentFlux, kSegmentAperture };

inline constexpr ExchangedFieldKind kExchangedFields[] = {
    {kPressureLoads.name, &quantity::stress},
    {"fracture_flow.flux", &quantity::flow_rate},
    {"fracture_flow.aperture", &quantity::length},
};

}  // namespace fissure::flow
