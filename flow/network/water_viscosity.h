// The viscosity of liquid water as a function of temperature, for the
// cubic-law conductance of a fracture whose water is heated (theory.md 6.3,
// T -> H: the conductance is proportional to 1/mu).
//
// Correlation: Kestin, Sokolov & Wakeham (1978), "Viscosity of liquid water
// in the range -8 C to 150 C", J. Phys. Chem. Ref. Data 7(3), 941-948, at
// atmospheric pressure (the saturation pressure above 100 C):
//   log10(mu(t) / mu(20 C)) = (20 - t) / (t + 96)
//       * [1.2378 - 1.303e-3 (20 - t) + 3.06e-6 (20 - t)^2 + 2.55e-8 (20 - t)^3],
// t in degC, with mu(20 C) = 1.0016 mPa s (ISO/TR 3666:1998, the value the
// IAPWS 2008 formulation gives). Against the tabulated values of 0-100 C
// (tests/unit/test_water_viscosity.cpp) it is within 0.3 %. Pressure is
// neglected: below 100 C and 30 MPa it changes water's viscosity by less
// than about 1 % per 10 MPa.
//
// Where water stops being the liquid the correlation describes, at the
// fracture's pressure: below 0 C (supercooled, down to -8 C, still in the
// correlation's range), above the boiling point (the saturation pressure of
// IAPWS-IF97, equation 30, rises above the absolute pressure), the value is
// still computed and the flow warns; outside -8..150 C, or a temperature that
// is not finite, there is no value.
#pragma once

namespace fissure::flow {

inline constexpr double kWaterViscosityAt20C = 1.0016e-3;  ///< Pa s
/// The correlation's range (degC).
inline constexpr double kWaterViscosityLowest = -8, kWaterViscosityHighest = 150;
/// Absolute pressure of the atmosphere (Pa): Fissure's pressures are gauge
/// pressures (0 = atmospheric, docs/flow.md).
inline constexpr double kAtmosphericPressure = 101325;

/// mu(t) of Kestin et al. (Pa s) for t in [kWaterViscosityLowest,
/// kWaterViscosityHighest] degC; NaN outside (the caller reports it).
double water_viscosity(double celsius);

/// Saturation (boiling) pressure of water at t degC (Pa), IAPWS-IF97
/// equation 30, for 0.01 C <= t <= 373.946 C (the critical point).
double water_saturation_pressure(double celsius);

/// What water at temperature t (degC) and absolute pressure p (Pa) is, for
/// the viscosity correlation.
enum class WaterState {
  Liquid,              ///< in the correlation's range and liquid
  Supercooled,         ///< below 0 C: the correlation holds, but water may freeze
  Boiling,             ///< above the boiling point at p: steam, not the correlation's liquid
  OutsideCorrelation,  ///< outside -8..150 C or not finite: no viscosity
};
WaterState water_state(double celsius, double absolute_pressure);

}  // namespace fissure::flow
