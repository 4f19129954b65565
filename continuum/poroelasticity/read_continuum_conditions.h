// The entries of the continuum section's `conditions` and `sources`
// (read_continuum_conditions.cpp), for the section's reader
// (read_continuum_settings.cpp).
#pragma once

#include <string>
#include <vector>

#include "continuum/poroelasticity/continuum_settings.h"
#include "core/scene/config_map.h"
#include "core/scene/config_node.h"

namespace fissure::continuum {

/// Their key tables (the section's reader lists them for the documentation
/// check and the suggestions).
extern const KeyTable kConditionTable, kPlateTable, kHeatTransferTable, kSourceTable;

/// Reads one entry of continuum.conditions on one of `boundaries` into
/// c.conditions; errors are reported at the entry's keys.
void read_condition(const ConfigNode& item, const std::vector<std::string>& boundaries,
                    ContinuumControls& c);

/// Reads one entry of continuum.sources (a point in c.domain) into c.sources.
void read_source(const ConfigNode& item, ContinuumControls& c);

}  // namespace fissure::continuum
