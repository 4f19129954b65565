// Bad input to the thermal process gives one clear, located message, never a
// crash: non-positive conductivity or capacity, a tensor that is not
// positive definite, two conditions on one boundary, a material without
// thermal properties, a source outline that crosses itself (all when the
// scene is read), a heat source outside the rock, source elements finer than
// 1e-4 of the others and a mesh above thermal.mesh.max_elements (when the
// run starts, before meshing; the message names the scene line); a
// non-positive thermal.max_temperature_change; a thermal expansion that is
// negative, beyond any solid or of another unit, and the old shared key
// materials[].thermal_expansion; a condition's history, decay or cycle that
// cannot be (a cycle on a flux, both a history and a decay, a non-positive
// period, a negative amplitude, times that go back); the spellings the
// section had before it took the continuum's (flux, transfer_coefficient,
// external_temperature, initial.gradient), refused with the new key; and
// temperatures in K, converted, or refused when they are no temperature.
#include <gtest/gtest.h>

#include <string>

#include "core/base/errors.h"
#include "coupling/process_registry.h"
#include "tests/support/bad_scene_checks.h"

namespace fissure {
namespace {

const char* kScene = R"(
name: bad_thermal
physics: [thermal]
gravity: [0, 0]
materials:
  - {name: rock, density: 2700, young_modulus: 10 GPa, poisson_ratio: 0.25}
blocks:
  - {name: a, vertices: [[0, 0], [10, 0], [10, 10], [0, 10]]}
  - {name: b, vertices: [[10, 0], [20, 0], [20, 10], [10, 10]]}
time: {end: 1 d}
thermal:
  time_step: 1 h
%s
)";

const std::string kMaterials =
    "  materials: [{name: rock, conductivity: 3, heat_capacity: 2.4e6}]\n";

std::string scene_with(const std::string& thermal) {
  const std::string text = kScene;
  const size_t at = text.find("%s");
  std::string out(text, 0, at);
  out.append(thermal).append(text, at + 2);
  return out;
}

std::string parse_error(const std::string& thermal) {
  return testing::parse_error(scene_with(thermal));
}

/// The message of the error the run's start throws (the process's
/// initialize), or "".
std::string start_error(const std::string& thermal) {
  return testing::start_error(scene_with(thermal));
}

using testing::expect_contains;

// A time step that is there but not usable is reported where it is, not
// as a missing key (issue 35).
TEST(thermal_bad_input, ATimeStepThatIsThereIsNotReportedMissing) {
  for (const std::string value : {".nan", "0", "-1 h"}) {
    std::string s = scene_with(kMaterials);
    s.replace(s.find("time_step: 1 h"), 14, "time_step: " + value);
    const std::string e = testing::parse_error(s);
    expect_contains(e, testing::at(s, "time_step: " + value, 11) + ": thermal.time_step: found '");
    EXPECT_EQ(e.find("key is missing"), std::string::npos) << e;
  }
}

TEST(thermal_bad_input, NonPositiveProperties) {
  const std::string zero = parse_error(
      "  materials: [{name: rock, conductivity: 0, "
      "heat_capacity: 2.4e6}]");
  expect_contains(zero, "bad.yaml:13:42: ");
  expect_contains(zero,
                  "thermal.materials[0].conductivity: found '0'; expected a thermal "
                  "conductivity > 0");
  expect_contains(parse_error("  materials: [{name: rock, conductivity: 3, "
                              "heat_capacity: -1}]"),
                  "thermal.materials[0].heat_capacity: found '-1'; expected a volumetric heat "
                  "capacity > 0");
  expect_contains(parse_error("  materials: [{name: rock, conductivity: 3, specific_heat: 0}]"),
                  "expected a specific heat > 0");
  expect_contains(parse_error("  materials: [{name: rock, conductivity: [1, 1, 2], "
                              "heat_capacity: 2.4e6}]"),
                  "expected a positive definite tensor");
  expect_contains(parse_error("  materials: []"),
                  "found no entry for material 'rock'; expected its conductivity and heat "
                  "capacity");
}

TEST(thermal_bad_input, TwoConditionsOnOneBoundary) {
  const std::string e = parse_error(kMaterials +
                                    "  conditions:\n"
                                    "    - {boundary: left, temperature: 20}\n"
                                    "    - {boundary: left, heat_flux: 5}\n");
  expect_contains(e,
                  "bad.yaml:16:18: thermal.conditions[1].boundary: found a second condition "
                  "on boundary 'left'");
  expect_contains(parse_error(kMaterials + "  conditions: [{boundary: left, temperature: 20, "
                                           "heat_flux: 5}]"),
                  "found 2 of temperature, heat_flux and heat_transfer; expected exactly one");
  // Overlapping named boundaries: left is part of the exterior.
  expect_contains(start_error(kMaterials + "  conditions:\n"
                                           "    - {boundary: exterior, temperature: 20}\n"
                                           "    - {boundary: left, heat_flux: 5}\n"),
                  "bad.yaml:16:7: thermal.conditions[1]: found boundary 'left', which shares "
                  "edges with boundary 'exterior'");
  // A name that no boundary has is refused as the scene is read (before,
  // at the start of the run, with a summary whose monitors had no
  // temperature yet: the fuzzer's case 623).
  expect_contains(parse_error(kMaterials + "  conditions: [{boundary: tunnel, temperature: 20}]"),
                  "bad.yaml:14:27: thermal.conditions[0].boundary: found 'tunnel', which names no "
                  "boundary; expected one of: left, right, bottom, top, exterior");
}

TEST(thermal_bad_input, HeaterOutsideTheRock) {
  const std::string e =
      start_error(kMaterials + "  sources: [{name: canister, point: [25, 5], power: 1 kW/m}]");
  expect_contains(e,
                  "bad.yaml:14:13: thermal.sources[0]: found the point (25, 5) outside the "
                  "rock");
  expect_contains(start_error(kMaterials + "  sources: [{name: heater, line: [[5, 5], [15, 5]], "
                                           "power: 100}]"),
                  "found points in blocks 'a' and 'b'; expected a source inside one block");
}

TEST(thermal_bad_input, SourceOutlineCrossesItselfOrIsTooFine) {
  expect_contains(parse_error(kMaterials + "  sources: [{name: bow, polygon: [[2, 2], [4, 4], "
                                           "[4, 2], [2, 4]], power: 10}]"),
                  "bad.yaml:14:34: thermal.sources[0].polygon: ");
  expect_contains(parse_error(kMaterials + "  sources: [{name: bow, polygon: [[2, 2], [4, 4], "
                                           "[4, 2], [2, 4]], power: 10}]"),
                  "expected a simple polygon");
  expect_contains(start_error(kMaterials + "  mesh: {element_size: 1, source_element_size: 1 um}\n"
                                           "  sources: [{name: heater, point: [5, 5], power: 10}]"),
                  "bad.yaml:14:9: thermal.mesh: found elements of 1e-06 m at the sources and 1 m "
                  "elsewhere; expected source_element_size at least element_size / 10000");
}

TEST(thermal_bad_input, TooManyElementsBeforeMeshing) {
  const std::string e = start_error(kMaterials + "  mesh: {element_size: 1 mm}");
  expect_contains(e,
                  "bad.yaml:14:9: thermal.mesh: the block meshes would have about 1.18e+09 "
                  "triangles");
  expect_contains(e, "expected at most thermal.mesh.max_elements = 2e+06");
  // The estimate is an upper one: a mesh that fits is made.
  EXPECT_EQ(start_error(kMaterials + "  mesh: {element_size: 0.5, max_elements: 8000}"), "");
}

TEST(thermal_bad_input, NonPositiveTemperatureChangeLimit) {
  expect_contains(parse_error(kMaterials + "  max_temperature_change: 0"),
                  "bad.yaml:14:27: thermal.max_temperature_change: found '0'; expected a "
                  "temperature change > 0");
  expect_contains(parse_error(kMaterials + "  max_temperature_change: -2 K"),
                  "bad.yaml:14:27: thermal.max_temperature_change: found '-2 K'; expected a "
                  "temperature change > 0");
  EXPECT_EQ(parse_error(kMaterials + "  max_temperature_change: 2 K"), "");
}

TEST(thermal_bad_input, ConditionHistoriesAndCycles) {
  expect_contains(
      parse_error(kMaterials + "  conditions: [{boundary: left, heat_flux: 5, cycle: {amplitude: "
                               "2 K, period: 1 d}}]"),
      "bad.yaml:14:47: thermal.conditions[0].cycle: found a cycle on a heat_flux; "
      "expected it on a temperature or a heat_transfer's temperature");
  expect_contains(
      parse_error(kMaterials + "  conditions: [{boundary: left, heat_flux: 5, history: [[0, 1]], "
                               "decay: [[1, 1 yr]]}]"),
      "thermal.conditions[0].decay: found both history and decay; expected one "
      "of them");
  expect_contains(
      parse_error(kMaterials + "  conditions: [{boundary: left, temperature: 20, cycle: "
                               "{amplitude: 2 K, period: 0}}]"),
      "thermal.conditions[0].cycle.period: found '0'; expected a time > 0");
  expect_contains(
      parse_error(kMaterials + "  conditions: [{boundary: left, temperature: 20, cycle: "
                               "{amplitude: -2 K, period: 1 d}}]"),
      "thermal.conditions[0].cycle.amplitude: found '-2 K'; expected a "
      "temperature change >= 0");
  expect_contains(
      parse_error(kMaterials + "  conditions: [{boundary: left, temperature: 20, cycle: "
                               "{period: 1 d}}]"),
      "thermal.conditions[0].cycle.amplitude: key is missing; expected a "
      "temperature change >= 0 (K, degC)");
  expect_contains(
      parse_error(kMaterials + "  conditions: [{boundary: left, temperature: 20, history: "
                               "[[1 h, 1], [0, 2]]}]"),
      "thermal.conditions[0].history[1]: found t = 0 s after t = 3600 s; expected "
      "strictly increasing times");
  EXPECT_EQ(parse_error(kMaterials +
                        "  conditions: [{boundary: left, heat_transfer: {coefficient: 10, "
                        "temperature: 20}, cycle: {amplitude: 8 K, period: 1 d, peak: 14 h}}]"),
            "");
  expect_contains(parse_error(kMaterials + "  conditions: [{boundary: left, heat_transfer: "
                                           "{coefficient: 10}}]"),
                  "thermal.conditions[0].heat_transfer.temperature: key is missing; expected a "
                  "temperature in (-273.15, 10000) degC (degC, K)");
}

// The keys the thermal section shares with the continuum's (issue 34: the
// same keys for the same things): its old spellings are unknown keys whose
// message names the new one, at the old key.
TEST(thermal_bad_input, OldSpellingsNameTheNewKeys) {
  using testing::at, testing::errors, testing::expect_error;
  const std::string flux = scene_with(kMaterials + "  conditions: [{boundary: left, flux: 5}]");
  expect_error(errors(flux), at(flux, "flux: 5"), "thermal.conditions[0].flux",
               {"unknown key 'flux' (renamed: did you mean 'heat_flux'?)"});
  const std::string transfer =
      scene_with(kMaterials +
                 "  conditions: [{boundary: left, transfer_coefficient: 10, "
                 "external_temperature: 20}]");
  const std::vector<std::string> lines = errors(transfer);
  expect_error(lines, at(transfer, "transfer_coefficient"),
               "thermal.conditions[0].transfer_coefficient",
               {"unknown key 'transfer_coefficient' (renamed: did you mean 'heat_transfer: "
                "{coefficient: ...}'?)"});
  expect_error(lines, at(transfer, "external_temperature"),
               "thermal.conditions[0].external_temperature",
               {"unknown key 'external_temperature' (renamed: did you mean 'heat_transfer: "
                "{temperature: ...}'?)"});
  const std::string gradient = scene_with(kMaterials + "  initial: {gradient: [0, -0.03]}");
  expect_error(errors(gradient), at(gradient, "gradient"), "thermal.initial.gradient",
               {"unknown key 'gradient' (renamed: did you mean 'temperature_gradient'?)"});
  // The new spellings: a gradient per metre of y, or [gx, gy].
  EXPECT_EQ(parse_error(kMaterials + "  initial: {temperature_gradient: -30 K/km}"), "");
  EXPECT_EQ(parse_error(kMaterials + "  initial: {temperature_gradient: [0.01, -0.03]}"), "");
}

// Temperatures in K are converted to degC; a unit of no temperature, or a
// temperature below absolute zero, is a located error (issue 34).
TEST(thermal_bad_input, TemperaturesInKelvinOrNoTemperature) {
  using testing::at, testing::errors, testing::expect_error;
  EXPECT_EQ(parse_error(kMaterials + "  initial: {temperature: 283.15 K}"), "");
  EXPECT_EQ(parse_error(kMaterials + "  initial: {temperature: 10 degC}"), "");
  const std::string metres = scene_with(kMaterials + "  initial: {temperature: 10 m}");
  expect_error(errors(metres), at(metres, "10 m"), "thermal.initial.temperature",
               {"found '10 m', a length; expected a temperature (degC, K)"});
  const std::string cold =
      scene_with(kMaterials + "  conditions: [{boundary: top, temperature: -10 K}]");
  expect_error(errors(cold), at(cold, "-10 K"), "thermal.conditions[0].temperature",
               {"found '-10 K', below absolute zero"});
  const std::string colder = scene_with(kMaterials + "  initial: {temperature: -300}");
  expect_error(errors(colder), at(colder, "-300"), "thermal.initial.temperature",
               {"found '-300', below absolute zero"});
}

// thermal.materials[].thermal_expansion (1/K): >= 0 and at most 1e-2 1/K,
// each error at its value.
TEST(thermal_bad_input, ThermalExpansionNegativeBeyondPhysicsOrOfAnotherUnit) {
  using testing::at, testing::errors, testing::expect_error;
  const std::string key = "thermal_expansion: ";
  const auto with = [&](const std::string& value) {
    return scene_with("  materials: [{name: rock, conductivity: 3, heat_capacity: 2.4e6, " + key +
                      value + "}]\n");
  };
  const std::string path = "thermal.materials[0].thermal_expansion";
  for (const std::string value : {"-1e-5", "-1e-5 1/K"}) {
    const std::string yaml = with(value);
    expect_error(errors(yaml), at(yaml, key + value, key.size()), path,
                 {"found '" + value + "'", "expected a thermal expansion coefficient >= 0"});
  }
  const std::string huge = with("0.5 1/K");
  expect_error(errors(huge), at(huge, "0.5 1/K"), path, {"found '0.5 1/K'", "at most 0.01 1/K"});
  const std::string unit = with("1e-5 1/s");
  expect_error(errors(unit), at(unit, "1e-5 1/s"), path,
               {"expected a thermal expansion coefficient (1/K)"});
  EXPECT_EQ(parse_error("  materials: [{name: rock, conductivity: 3, heat_capacity: 2.4e6, " + key +
                        "1e-5 1/K}]"),
            "");
  EXPECT_EQ(parse_error("  materials: [{name: rock, conductivity: 3, heat_capacity: 2.4e6, " + key +
                        "0}]"),
            "");
}

// The thermal process owns the expansion: the old key of the shared
// materials is unknown there, and the message says where it went.
TEST(thermal_bad_input, ThermalExpansionOfTheSharedMaterialsMoved) {
  using testing::at, testing::errors, testing::expect_error;
  const std::string yaml = testing::replace(scene_with(kMaterials), "poisson_ratio: 0.25}",
                                            "poisson_ratio: 0.25, thermal_expansion: 1e-5}");
  expect_error(errors(yaml), at(yaml, "thermal_expansion"), "materials[0].thermal_expansion",
               {"unknown key 'thermal_expansion' (moved to thermal.materials[].thermal_expansion)",
                "expected one of: name, density, young_modulus, poisson_ratio"});
}

}  // namespace
}  // namespace fissure
