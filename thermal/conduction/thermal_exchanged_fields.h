// The thermal fields that the others read, as the iterated scheme tests and
// relaxes them (SectionReader::exchanges, Process::exchanged_values): the
// blocks' thermal strains (the mechanics), the fracture water's segment
// temperatures (the flow's viscosity), and with ties to a continuum the heat
// flows it gives it (thermal_ties.h). Not the node temperatures: the next
// step starts from them.
#pragma once

#include "core/scene/exchanged_field.h"
#include "rockmass/fields/block_thermal_strain.h"
#include "rockmass/fields/fracture_temperature.h"
#include "rockmass/physical_quantities.h"
#include "thermal/conduction/thermal_ties.h"

namespace fissure::thermal {

enum ExchangedThermalField : std::size_t { kStrain, kFluidTemperature, kTieHeatFlow };

inline constexpr ExchangedFieldKind kExchangedFields[] = {
    {kBlockThermalStrain.name, &quantity::dimensionless},
    {kFractureFluidTemperature.name, &quantity::temperature_change},
    kTieHeatFlows,
};

}  // namespace fissure::thermal
