// The quantity kinds of the physics' scene keys (core/scene/units.h holds
// the framework's): fluid pressure and viscosity, temperatures and heat,
// joint stiffness. Shared by the modules that read them (flow, thermal,
// continuum, the joint laws), so that a key means the same unit and range
// in every section.
#pragma once

#include "core/scene/units.h"

namespace fissure::quantity {
/// Fluid pressures: the quantity of a stress (Pa), named "pressure".
inline constexpr const QuantityKind& pressure = stress;
inline constexpr QuantityKind viscosity{"viscosity", {1, -1, -1, 0, 0}, "Pa*s", "Pa*s", 1, 1e10};
/// Temperatures are on the Celsius scale (Fissure's scale of temperatures):
/// a plain number or "degC" is degC, a value in K is converted (283.15 K is
/// 10 degC); below absolute zero is an error (units.h, QuantityKind::celsius).
inline constexpr QuantityKind temperature{"temperature", {0, 0, 0, 1, 0}, "degC, K", "degC", 1, 1e4,
                                          true};
/// Differences, gradients and the units of heat: K and degC are the same step.
inline constexpr QuantityKind temperature_change{
    "temperature change", {0, 0, 0, 1, 0}, "K, degC", "K", 1, 1e4};
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
/// Intrinsic permeability k (m^2): rocks span 1e-23 (intact salt) to 1e-7
/// (gravel).
inline constexpr QuantityKind permeability{"permeability", {0, 2, 0, 0, 0}, "m^2", "m^2", 1, 1e-3};
/// How fast a property falls with stress: the beta of exp(-beta sigma)
/// (a permeability's stress law, 1/Pa). 1e-3 1/Pa is e-fold per kPa.
inline constexpr QuantityKind stress_sensitivity{
    "stress sensitivity", {-1, 1, 2, 0, 0}, "1/Pa, 1/MPa", "1/Pa", 1, 1e-3};
/// A joint's stiffness: stress per unit of relative wall displacement
/// (normal: the flow's hm.normal_stiffness and joints[]; shear: joints[]).
inline constexpr QuantityKind joint_normal_stiffness{
    "joint normal stiffness", {1, -2, -2, 0, 0}, "Pa/m, MPa/m, GPa/m", "Pa/m", 1, 1e16};
inline constexpr QuantityKind joint_shear_stiffness{
    "joint shear stiffness", {1, -2, -2, 0, 0}, "Pa/m, MPa/m, GPa/m", "Pa/m", 1, 1e16};
/// A force per unit thickness (a plate's resultant in plane strain).
inline constexpr QuantityKind linear_force{
    "force per unit thickness", {1, 0, -2, 0, 0}, "N/m, kN/m, MN/m", "N/m", 1, 1e15};
}  // namespace fissure::quantity
