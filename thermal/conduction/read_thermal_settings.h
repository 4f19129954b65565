// Internal to the thermal process's reader: the parts of the `thermal`
// section (read_thermal_settings.cpp, read_thermal_conditions.cpp) and the
// quantity kinds only thermal keys use.
#pragma once

#include <string>

#include "core/scene/config_map.h"
#include "thermal/conduction/thermal_settings.h"

namespace fissure {

namespace quantity {
/// Temperatures are in degC; a plain number is degC, a unit K a difference.
inline constexpr QuantityKind temperature{
    "temperature", {0, 0, 0, 1, 0}, "a plain number in degC", "degC", 1, 1e4};
inline constexpr QuantityKind temperature_change{
    "temperature change", {0, 0, 0, 1, 0}, "K", "K", 1, 1e4};
inline constexpr QuantityKind temperature_gradient{
    "temperature gradient", {0, -1, 0, 1, 0}, "K/m, K/km", "K/m", 1, 1e6};
inline constexpr QuantityKind conductivity{
    "thermal conductivity", {1, 1, -3, -1, 0}, "W/m/K", "W/m/K", 1, 1e5};
/// Linear thermal expansion: a strain per kelvin. Rocks lie near 1e-5 1/K;
/// 1e-2 1/K (a strain of 1 per 100 K) is beyond any solid.
inline constexpr QuantityKind thermal_expansion{
    "thermal expansion coefficient", {0, 0, 0, -1, 0}, "1/K", "1/K", 1, 1e-2};
inline constexpr QuantityKind heat_capacity{
    "volumetric heat capacity", {1, -1, -2, -1, 0}, "J/m^3/K, MJ/m^3/K", "J/m^3/K", 1, 1e9};
inline constexpr QuantityKind specific_heat{
    "specific heat", {0, 2, -2, -1, 0}, "J/kg/K, kJ/kg/K", "J/kg/K", 1, 1e6};
inline constexpr QuantityKind heat_flux{"heat flux", {1, 0, -3, 0, 0}, "W/m^2", "W/m^2", 1, 1e9};
inline constexpr QuantityKind transfer_coefficient{
    "heat transfer coefficient", {1, 0, -3, -1, 0}, "W/m^2/K", "W/m^2/K", 1, 1e12};
inline constexpr QuantityKind linear_power{
    "power per unit thickness", {1, 1, -3, 0, 0}, "W/m, kW/m", "W/m", 1, 1e12};
}  // namespace quantity

namespace thermal {
extern const KeyTable condition_table;  ///< thermal.conditions[]
extern const KeyTable source_table;     ///< thermal.sources[]
extern const KeyTable cycle_table;      ///< thermal.conditions[].cycle
}  // namespace thermal

/// thermal.conditions and thermal.sources.
/// `boundaries`: the names a condition may name (the domain's sides,
/// `exterior` and the rock mass's excavations).
void read_thermal_conditions(ConfigMap& map, ThermalControls& c,
                             const std::vector<std::string>& boundaries);

}  // namespace fissure
