// Internal to the thermal process's reader: the parts of the `thermal`
// section (read_thermal_settings.cpp, read_thermal_conditions.cpp).
#pragma once

#include <string>

#include "core/scene/config_map.h"
#include "rockmass/physical_quantities.h"
#include "thermal/conduction/thermal_settings.h"

namespace fissure {

namespace thermal {
extern const KeyTable condition_table;      ///< thermal.conditions[]
extern const KeyTable heat_transfer_table;  ///< thermal.conditions[].heat_transfer
extern const KeyTable source_table;         ///< thermal.sources[]
extern const KeyTable cycle_table;          ///< thermal.conditions[].cycle
}  // namespace thermal

/// thermal.conditions and thermal.sources.
/// `boundaries`: the names a condition may name (the domain's sides,
/// `exterior` and the rock mass's excavations).
void read_thermal_conditions(ConfigMap& map, ThermalControls& c,
                             const std::vector<std::string>& boundaries);

}  // namespace fissure
