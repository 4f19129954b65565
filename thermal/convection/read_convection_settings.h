// Internal to the thermal process's reader: thermal.convection
// (read_convection_settings.cpp), its key tables for the documentation check.
#pragma once

#include "core/scene/config_map.h"
#include "core/scene/scene_section.h"
#include "thermal/conduction/thermal_settings.h"

namespace fissure {

namespace thermal {
extern const KeyTable convection_table;  ///< thermal.convection
extern const KeyTable fluid_table;       ///< thermal.convection.fluid
extern const KeyTable inlet_table;       ///< thermal.convection.inlets[]
}  // namespace thermal

/// thermal.convection, when present (it needs the flow process).
void read_fracture_convection(ConfigMap& map, SectionContext& context, ThermalControls& c);

}  // namespace fissure
