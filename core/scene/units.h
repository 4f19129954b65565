// Physical units in scene files (docs/scene-reference.md, "Units").
//
// A value is either a plain number, read in the key's SI unit (degrees for
// angles), or a string "NUMBER UNIT" such as "50 GPa", "2650 kg/m^3", "1 ms".
// A unit expression is a product or quotient of known units, each with an
// optional integer power: "kg/m^3", "N/m", "m/s^2", "W/m/K", "kg*m/s^2".
// Every scene key expects one kind of quantity (a stress, a length, ...); a
// unit of another dimension is an error that names what was expected.
// Kinds on a scale with an origin of its own (the Celsius scale) convert a
// value given in K to that scale; "K" and "degC" are the same step in every
// other unit ("W/m/K", "1/degC").
#pragma once

#include <limits>
#include <string>
#include <string_view>

#include "core/base/errors.h"

namespace fissure {

/// Exponents of the SI base units kg, m, s, K (the kelvin) and of the radian.
/// Plane angle is kept as a dimension of its own so that "30 deg" cannot be
/// given where a plain ratio is expected.
struct Dimension {
  int mass = 0;
  int length = 0;
  int time = 0;
  int kelvin = 0;
  int angle = 0;

  friend constexpr bool operator==(const Dimension&, const Dimension&) = default;
};

constexpr Dimension operator*(const Dimension& a, const Dimension& b) {
  return {a.mass + b.mass, a.length + b.length, a.time + b.time, a.kelvin + b.kelvin,
          a.angle + b.angle};
}

constexpr Dimension raise(const Dimension& a, int n) {
  return {a.mass * n, a.length * n, a.time * n, a.kelvin * n, a.angle * n};
}

/// A parsed unit expression: a number in this unit times `factor` is in SI.
struct Unit {
  double factor = 1;
  Dimension dimension;
};

/// What a scene key expects. `plain_scale` converts a plain number (no unit)
/// to SI: 1 for every kind except angles, where a plain number is in degrees.
struct QuantityKind {
  std::string_view name;        ///< "density"
  Dimension dimension;          ///< SI base exponents
  std::string_view examples;    ///< units to suggest in messages: "Pa, kPa, MPa, GPa"
  std::string_view plain_unit;  ///< unit of a plain number: "Pa"; "deg" for angles; "" if none
  double plain_scale = 1;       ///< SI value of the plain number 1
  /// The largest magnitude (SI) a scene may give: beyond it a value is
  /// outside physics (a typo, a unit slip), and would only overflow later
  /// (docs/scene-reference.md, "Limits").
  double largest = std::numeric_limits<double>::infinity();
  /// Values on the Celsius scale (absolute temperatures; Fissure's scale):
  /// a plain number and "degC" are degrees Celsius, a value in "K" is
  /// converted (283.15 K is 10 degC), any other unit is an error, and a
  /// value below absolute zero (-273.15 degC, 0 K) is refused.
  bool celsius = false;
};

/// Absolute zero on the Celsius scale, degC.
inline constexpr double kAbsoluteZeroCelsius = -273.15;

/// The smallest non-zero magnitude (SI) of any quantity a scene may give:
/// below it a value is no physics of rock at any scale (a unit slip), and a
/// process dividing by it overflows (1e-320 GPa as a Young's modulus made the
/// strain energy infinite; issue 22).
inline constexpr double kSmallestMagnitude = 1e-50;

/// The kinds of quantity scene keys expect.
namespace quantity {
inline constexpr double kDegree = 3.14159265358979323846 / 180;

inline constexpr QuantityKind dimensionless{"number", {}, "", "", 1, 1e12};
inline constexpr QuantityKind length{"length", {0, 1, 0, 0, 0}, "m, cm, mm, km", "m", 1, 1e7};
inline constexpr QuantityKind mass{"mass", {1, 0, 0, 0, 0}, "kg, g, t", "kg", 1, 1e18};
inline constexpr QuantityKind time{"time", {0, 0, 1, 0, 0}, "s, ms, min, h, d, yr", "s", 1, 1e15};
inline constexpr QuantityKind angle{"angle", {0, 0, 0, 0, 1}, "deg, rad", "deg", kDegree, 1e3};
inline constexpr QuantityKind velocity{"velocity", {0, 1, -1, 0, 0}, "m/s, mm/s, m/yr", "m/s", 1,
                                       1e4};
inline constexpr QuantityKind angular_velocity{
    "angular velocity", {0, 0, -1, 0, 1}, "rad/s, deg/s", "rad/s", 1, 1e4};
inline constexpr QuantityKind acceleration{
    "acceleration", {0, 1, -2, 0, 0}, "m/s^2", "m/s^2", 1, 1e5};
inline constexpr QuantityKind force{"force", {1, 1, -2, 0, 0}, "N, kN, MN", "N", 1, 1e15};
/// Stresses, moduli, strengths: messages name them by the word users know for
/// Pa (scene-reference.md section 2); modules alias it for their own fields.
inline constexpr QuantityKind stress{"pressure", {1, -1, -2, 0, 0}, "Pa, kPa, MPa, GPa", "Pa", 1,
                                     1e12};
inline constexpr QuantityKind density{
    "density", {1, -3, 0, 0, 0}, "kg/m^3, g/cm^3, t/m^3", "kg/m^3", 1, 1e5};
inline constexpr QuantityKind stiffness{"stiffness", {1, 0, -2, 0, 0}, "N/m, kN/m, MN/m", "N/m", 1,
                                        1e18};
inline constexpr QuantityKind energy{"energy", {1, 2, -2, 0, 0}, "J, kJ, MJ", "J", 1, 1e20};
inline constexpr QuantityKind power{"power", {1, 2, -3, 0, 0}, "W, kW, MW", "W", 1, 1e12};
}  // namespace quantity

/// A malformed number or unit, or a unit of the wrong dimension. The message
/// reads "what was found; expected what".
class UnitError : public Error {
 public:
  using Error::Error;
};

/// A unit of time the output names times in (docs/output.md, "Time"): its
/// name as the scene wrote it and its length in seconds.
struct TimeUnit {
  std::string name = "s";
  double seconds = 1;
};

/// The unit of a scene's time value `text` ("1000 yr": yr), or, for a plain
/// number (seconds) or text that is not a time, the largest of yr, d, h and
/// min of which `seconds` (the value in SI) holds two, else s.
TimeUnit time_unit_of(std::string_view text, double seconds);

/// Parses a unit expression ("kg/m^3"). Throws UnitError.
Unit parse_unit(std::string_view expression);

/// Converts a scene value ("50 GPa", "-9.81", "30") to SI for `kind` (to
/// degC for a `celsius` kind). The unit may follow the number without a
/// space ("30d", "50GPa"), as on the command line. Throws UnitError for text
/// that is not a number, an unknown unit, a unit of another dimension, a
/// non-finite number, or a `celsius` value below absolute zero.
double to_si(std::string_view text, const QuantityKind& kind);

/// "a density (kg/m^3, g/cm^3, t/m^3)", "a number" (dimensionless).
std::string describe(const QuantityKind& kind);

/// The name of a dimension with its article ("a density") when it is one of
/// the kinds above, otherwise its SI base units ("kg*s").
std::string describe(const Dimension& dimension);

}  // namespace fissure
