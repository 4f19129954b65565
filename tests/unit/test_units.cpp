// Units in scene files (core/scene/units.h, docs/scene-reference.md section 2):
// conversion of every listed unit to SI, unit expressions, the degree
// convention for plain angles, the Celsius scale of absolute temperatures
// (a value in K converted, not read as degC), numbers glued to their unit as
// the command line takes them, and the messages for malformed numbers,
// unknown units and units of the wrong dimension.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/scene/units.h"
// The physics' kinds (none is in the framework): the machinery must read
// their units all the same.
#include "rockmass/physical_quantities.h"

namespace fissure {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// The UnitError message for `text` read as `kind` ("" when it converts).
std::string error_of(const std::string& text, const QuantityKind& kind) {
  try {
    to_si(text, kind);
  } catch (const UnitError& e) {
    return e.what();
  }
  return "";
}

TEST(units, PlainNumbersAreSi) {
  EXPECT_DOUBLE_EQ(to_si("2650", quantity::density), 2650);
  EXPECT_DOUBLE_EQ(to_si("50e9", quantity::pressure), 50e9);
  EXPECT_DOUBLE_EQ(to_si("-9.81", quantity::acceleration), -9.81);
  EXPECT_DOUBLE_EQ(to_si("+1.5", quantity::length), 1.5);
  EXPECT_DOUBLE_EQ(to_si("  0.25 ", quantity::dimensionless), 0.25);
  EXPECT_DOUBLE_EQ(to_si(".5", quantity::time), 0.5);
  EXPECT_DOUBLE_EQ(to_si("1E-3", quantity::time), 1e-3);
  EXPECT_DOUBLE_EQ(to_si("0.1", quantity::angular_velocity), 0.1);  // rad/s, not deg/s
}

TEST(units, PlainAnglesAreDegrees) {
  EXPECT_DOUBLE_EQ(to_si("30", quantity::angle), kPi / 6);
  EXPECT_DOUBLE_EQ(to_si("30 deg", quantity::angle), kPi / 6);
  EXPECT_DOUBLE_EQ(to_si("0.5 rad", quantity::angle), 0.5);
  EXPECT_DOUBLE_EQ(to_si("0", quantity::angle), 0);
}

TEST(units, EveryListedUnitConverts) {
  struct Case {
    const char* text;
    const QuantityKind* kind;
    double si;
  };
  const Case cases[] = {
      {"1 m", &quantity::length, 1},          {"1 cm", &quantity::length, 1e-2},
      {"1 mm", &quantity::length, 1e-3},      {"1 um", &quantity::length, 1e-6},
      {"1 \u00b5m", &quantity::length, 1e-6}, {"1 km", &quantity::length, 1e3},
      {"1 kg", &quantity::mass, 1},           {"1 g", &quantity::mass, 1e-3},
      {"1 t", &quantity::mass, 1e3},          {"1 s", &quantity::time, 1},
      {"1 ms", &quantity::time, 1e-3},        {"1 us", &quantity::time, 1e-6},
      {"1 min", &quantity::time, 60},         {"1 h", &quantity::time, 3600},
      {"1 d", &quantity::time, 86400},        {"1 yr", &quantity::time, 365.25 * 86400},
      {"1 Pa", &quantity::pressure, 1},       {"1 kPa", &quantity::pressure, 1e3},
      {"1 MPa", &quantity::pressure, 1e6},    {"1 GPa", &quantity::pressure, 1e9},
      {"1 N", &quantity::force, 1},           {"1 kN", &quantity::force, 1e3},
      {"1 MN", &quantity::force, 1e6},        {"1 J", &quantity::energy, 1},
      {"1 kJ", &quantity::energy, 1e3},       {"1 W", &quantity::power, 1},
      {"1 MW", &quantity::power, 1e6},        {"1 K", &quantity::temperature_change, 1},
      {"1 deg", &quantity::angle, kPi / 180}, {"1 rad", &quantity::angle, 1},
  };
  for (const Case& c : cases) EXPECT_DOUBLE_EQ(to_si(c.text, *c.kind), c.si) << c.text;
}

TEST(units, ExamplesFromTheSchema) {
  EXPECT_DOUBLE_EQ(to_si("50 GPa", quantity::pressure), 50e9);
  EXPECT_DOUBLE_EQ(to_si("2650 kg/m^3", quantity::density), 2650);
  EXPECT_DOUBLE_EQ(to_si("1 ms", quantity::time), 1e-3);
  EXPECT_DOUBLE_EQ(to_si("9.81 m/s^2", quantity::acceleration), 9.81);
  EXPECT_DOUBLE_EQ(to_si("-1 MN", quantity::force), -1e6);
  EXPECT_DOUBLE_EQ(to_si("50GPa", quantity::pressure), 50e9);  // the space is optional
}

TEST(units, ExpressionsCombineUnits) {
  EXPECT_DOUBLE_EQ(to_si("2.65 g/cm^3", quantity::density), 2650);
  EXPECT_DOUBLE_EQ(to_si("2.65 t/m^3", quantity::density), 2650);
  EXPECT_DOUBLE_EQ(to_si("1 kg*m/s^2", quantity::force), 1);
  EXPECT_DOUBLE_EQ(to_si("1 kg * m / s^2", quantity::force), 1);
  EXPECT_DOUBLE_EQ(to_si("3 W/m/K", quantity::conductivity), 3);
  EXPECT_DOUBLE_EQ(to_si("2 MN/m", quantity::stiffness), 2e6);
  EXPECT_DOUBLE_EQ(to_si("1 N/m^2", quantity::pressure), 1);
  EXPECT_DOUBLE_EQ(to_si("5 mm/s", quantity::velocity), 5e-3);
  EXPECT_DOUBLE_EQ(to_si("1 m/yr", quantity::velocity), 1 / (365.25 * 86400));
  EXPECT_DOUBLE_EQ(to_si("180 deg/s", quantity::angular_velocity), kPi);
  EXPECT_DOUBLE_EQ(to_si("1 kg*m^2/s^3", quantity::power), 1);
  EXPECT_DOUBLE_EQ(to_si("1 m*s^-2", quantity::acceleration), 1);
  EXPECT_DOUBLE_EQ(to_si("2 m/m", quantity::dimensionless), 2);

  const Unit per_second = parse_unit("1/s");
  EXPECT_DOUBLE_EQ(per_second.factor, 1);
  EXPECT_EQ(per_second.dimension, (Dimension{0, 0, -1, 0, 0}));
  const Unit kpa = parse_unit("kN/m^2");
  EXPECT_DOUBLE_EQ(kpa.factor, 1e3);
  EXPECT_EQ(kpa.dimension, quantity::pressure.dimension);
}

TEST(units, WrongDimensionNamesWhatWasExpected) {
  EXPECT_EQ(error_of("2650 kg/m^3", quantity::pressure),
            "found '2650 kg/m^3', a density; expected a pressure (Pa, kPa, MPa, GPa)");
  EXPECT_EQ(error_of("1 m", quantity::time),
            "found '1 m', a length; expected a time (s, ms, min, h, d, yr)");
  EXPECT_EQ(error_of("30 deg", quantity::dimensionless),
            "found '30 deg', an angle; expected a number");
  EXPECT_EQ(error_of("1 N", quantity::stiffness),
            "found '1 N', a force; expected a stiffness (N/m, kN/m, MN/m)");
  // A dimension without a name is spelt in base units.
  EXPECT_EQ(error_of("1 kg*s", quantity::mass),
            "found '1 kg*s', a quantity in kg*s; expected a mass (kg, g, t)");
  EXPECT_EQ(error_of("1 m/kg^2", quantity::length),
            "found '1 m/kg^2', a quantity in m/kg^2; expected a length (m, cm, mm, km)");
}

TEST(units, UnknownUnitsAreSuggested) {
  EXPECT_EQ(error_of("50 GPA", quantity::pressure),
            "found '50 GPA' with unknown unit 'GPA' (did you mean 'GPa'?); expected a pressure "
            "(Pa, kPa, MPa, GPa)");
  EXPECT_EQ(
      error_of("3 kgs", quantity::mass),
      "found '3 kgs' with unknown unit 'kgs' (did you mean 'kg'?); expected a mass (kg, g, t)");
  EXPECT_EQ(error_of("3 furlongs", quantity::length),
            "found '3 furlongs' with unknown unit 'furlongs'; expected a length (m, cm, mm, km)");
}

TEST(units, MalformedTextIsAnError) {
  EXPECT_NE(error_of("heavy", quantity::density).find("found 'heavy', which is not a number"),
            std::string::npos);
  EXPECT_NE(error_of("", quantity::density).find("found an empty string"), std::string::npos);
  EXPECT_NE(error_of("--5", quantity::length).find("not a number"), std::string::npos);
  EXPECT_NE(error_of("1 kg/", quantity::density).find("malformed unit"), std::string::npos);
  EXPECT_NE(error_of("1 m^", quantity::length).find("malformed power"), std::string::npos);
  EXPECT_NE(error_of("1 m^x", quantity::length).find("malformed power"), std::string::npos);
  EXPECT_NE(error_of("1 kg m", quantity::force).find("unexpected 'm'"), std::string::npos);
  EXPECT_NE(error_of("1,5 m", quantity::length).find("unexpected ','"), std::string::npos);
  for (const char* text : {"nan", ".nan", ".NaN", ".inf", "-.inf", "+.inf", "inf", "-Infinity"})
    EXPECT_NE(error_of(text, quantity::length).find("which is not a finite number"),
              std::string::npos)
        << text;
  EXPECT_NE(error_of("1e999", quantity::length).find("out of the range"), std::string::npos);
  EXPECT_NE(error_of("1e300 GPa", quantity::pressure).find("overflows"), std::string::npos);
  // Every message ends with what was expected.
  EXPECT_NE(error_of("heavy", quantity::density).find("; expected a density"), std::string::npos);
}

// An absolute temperature in K is converted to Fissure's Celsius scale
// (issue 34: `initial: {temperature: 283.15 K}` started the rock at 283
// degC); a plain number keeps its meaning, degC; nothing below absolute zero.
TEST(units, AbsoluteTemperaturesAreOnTheCelsiusScale) {
  EXPECT_EQ(to_si("283.15 K", quantity::temperature), 10);
  EXPECT_EQ(to_si("283.15K", quantity::temperature), 10);
  EXPECT_DOUBLE_EQ(to_si("373.15 K", quantity::temperature), 100);
  EXPECT_DOUBLE_EQ(to_si("0 K", quantity::temperature), -273.15);
  EXPECT_DOUBLE_EQ(to_si("10", quantity::temperature), 10);
  EXPECT_DOUBLE_EQ(to_si("-5", quantity::temperature), -5);
  EXPECT_DOUBLE_EQ(to_si("10 degC", quantity::temperature), 10);
  EXPECT_DOUBLE_EQ(to_si("10 \u00b0C", quantity::temperature), 10);
  EXPECT_DOUBLE_EQ(to_si("-40 degC", quantity::temperature), -40);

  EXPECT_EQ(error_of("10 m", quantity::temperature),
            "found '10 m', a length; expected a temperature (degC, K)");
  EXPECT_EQ(error_of("-5 K", quantity::temperature),
            "found '-5 K', below absolute zero (-273.15 degC, 0 K); expected a temperature "
            "(degC, K)");
  EXPECT_NE(error_of("-300", quantity::temperature).find("below absolute zero"), std::string::npos);
  EXPECT_NE(error_of("-273.2 degC", quantity::temperature).find("below absolute zero"),
            std::string::npos);
  // Only a scale's own unit says where its zero is.
  EXPECT_EQ(error_of("300 K*m/m", quantity::temperature),
            "found '300 K*m/m', whose unit 'K*m/m' is not degC or K alone; expected a "
            "temperature (degC, K)");
  EXPECT_NE(error_of("300 K^1", quantity::temperature).find("is not degC or K alone"),
            std::string::npos);
  EXPECT_NE(error_of("300 degF", quantity::temperature).find("unknown unit 'degF'"),
            std::string::npos);
}

// A temperature difference, a gradient and the units of heat: K and degC are
// the same step, with no offset.
TEST(units, TemperatureDifferencesTakeKOrDegC) {
  EXPECT_DOUBLE_EQ(to_si("10 K", quantity::temperature_change), 10);
  EXPECT_DOUBLE_EQ(to_si("10 degC", quantity::temperature_change), 10);
  EXPECT_DOUBLE_EQ(to_si("10", quantity::temperature_change), 10);
  EXPECT_DOUBLE_EQ(to_si("0.03 K/m", quantity::temperature_gradient), 0.03);
  EXPECT_DOUBLE_EQ(to_si("30 K/km", quantity::temperature_gradient), 0.03);
  EXPECT_DOUBLE_EQ(to_si("30 degC/km", quantity::temperature_gradient), 0.03);
  EXPECT_DOUBLE_EQ(to_si("3 W/m/degC", quantity::conductivity), 3);
  EXPECT_DOUBLE_EQ(to_si("3 W/m/K", quantity::conductivity), 3);
  EXPECT_DOUBLE_EQ(to_si("1e-5 1/degC", quantity::thermal_expansion), 1e-5);
  EXPECT_DOUBLE_EQ(to_si("2.4 MJ/m^3/K", quantity::heat_capacity), 2.4e6);
  EXPECT_DOUBLE_EQ(to_si("-2 K", quantity::temperature_change), -2);  // a change may be negative
  EXPECT_EQ(error_of("10 m", quantity::temperature_change),
            "found '10 m', a length; expected a temperature change (K, degC)");
}

// The command line's times (`fissure run --end 1 yr`, `--end 30d`) are read
// by to_si: the unit may follow the number with or without a space.
TEST(units, NumbersGluedToTheirUnit) {
  EXPECT_DOUBLE_EQ(to_si("30d", quantity::time), 30 * 86400.0);
  EXPECT_DOUBLE_EQ(to_si("30 d", quantity::time), 30 * 86400.0);
  EXPECT_DOUBLE_EQ(to_si("1 yr", quantity::time), 365.25 * 86400);
  EXPECT_DOUBLE_EQ(to_si("1yr", quantity::time), 365.25 * 86400);
  EXPECT_DOUBLE_EQ(to_si("1e4 s", quantity::time), 1e4);
  EXPECT_DOUBLE_EQ(to_si("1e4s", quantity::time), 1e4);
  EXPECT_DOUBLE_EQ(to_si("2.5h", quantity::time), 9000);
  EXPECT_DOUBLE_EQ(to_si("68400", quantity::time), 68400);
  EXPECT_EQ(error_of("3 fortnights", quantity::time),
            "found '3 fortnights' with unknown unit 'fortnights'; expected a time (s, ms, min, "
            "h, d, yr)");
}

TEST(units, ParseUnitRejectsUnknownUnits) {
  EXPECT_THROW(parse_unit("furlong"), UnitError);
  EXPECT_THROW(parse_unit(""), UnitError);
  EXPECT_THROW(parse_unit("mPa"), UnitError);  // no automatic prefixes; case matters
}

// The output names times in the unit the scene wrote time.end in
// (docs/output.md, "Time"); a plain number of seconds gets the largest unit
// its length holds twice.
TEST(units, TimeUnitIsTheScenesOrChosenByTheDuration) {
  const auto unit = [](const char* text) {
    const TimeUnit u = time_unit_of(text, to_si(text, quantity::time));
    return u.name + " " + std::to_string(u.seconds);
  };
  EXPECT_EQ(unit("1000 yr"), "yr 31557600.000000");
  EXPECT_EQ(unit(" 120 d "), "d 86400.000000");
  EXPECT_EQ(unit("1e5 s"), "s 1.000000");
  EXPECT_EQ(unit("90 min"), "min 60.000000");
  EXPECT_EQ(unit("0.5"), "s 1.000000");
  EXPECT_EQ(unit("600"), "min 60.000000");
  EXPECT_EQ(unit("172800"), "d 86400.000000");
  EXPECT_EQ(unit("1e9"), "yr 31557600.000000");
  EXPECT_EQ(time_unit_of("3 m", 3).name, "s");  // not a time: by the duration
}

TEST(units, DescriptionsForMessages) {
  EXPECT_EQ(describe(quantity::pressure), "a pressure (Pa, kPa, MPa, GPa)");
  EXPECT_EQ(describe(quantity::angle), "an angle (deg, rad)");
  EXPECT_EQ(describe(quantity::dimensionless), "a number");
  EXPECT_EQ(describe(quantity::density.dimension), "a density");
  EXPECT_EQ(describe(Dimension{1, 0, 1, 0, 0}), "a quantity in kg*s");
}

}  // namespace
}  // namespace fissure
