// Internal to the flow process's reader: the parts of the `flow` section
// (read_flow_settings.cpp, read_flow_conditions.cpp) and the quantity kinds
// only flow keys use.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/scene/config_map.h"
#include "flow/cubic_law/flow_controls.h"

namespace fissure {

namespace quantity {
inline constexpr QuantityKind flow_rate{
    "flow rate per unit thickness", {0, 2, -1, 0, 0}, "m^2/s", "m^2/s", 1, 1e3};
}  // namespace quantity

namespace flow {
extern const KeyTable region_table;     ///< flow.regions[]
extern const KeyTable condition_table;  ///< flow.conditions[]
extern const KeyTable well_table;       ///< flow.wells[]
}  // namespace flow

/// flow.regions, flow.conditions, flow.wells, flow.initial_pressure / initial_head.
void read_flow_conditions(ConfigMap& map, FlowControls& flow, bool gravity_on);

}  // namespace fissure
