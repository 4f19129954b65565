// The keys the thermal and continuum sections share for the same things
// (docs/scene-reference.md sections 12 and 13): a condition's `heat_flux`
// and `heat_transfer: {coefficient, temperature}`, the initial
// `temperature_gradient` (and `decay` of sources and conditions,
// core/scene/time_history.h), and the range of a temperature. One reader
// each, so that a key means the same value, unit and range in both.
#pragma once

#include <string_view>

#include "core/scene/config_map.h"
#include "rockmass/physical_quantities.h"

namespace fissure::heat_keys {

/// The keys of a condition's `heat_transfer` map.
inline constexpr std::string_view kHeatTransfer[] = {"coefficient", "temperature"};

/// The absolute temperatures a scene may give, degC: above absolute zero
/// and below 1e4 degC.
Range temperature_range();

/// Reads `heat_transfer: {coefficient, temperature}` (a convective, Robin
/// condition; `table` is the map's, with the keys kHeatTransfer): the heat
/// transfer coefficient h >= 0 (W/m^2/K) and the ambient temperature (degC),
/// both required.
void read_heat_transfer(const ConfigNode& node, const KeyTable& table, double& coefficient,
                        double& temperature);

}  // namespace fissure::heat_keys
