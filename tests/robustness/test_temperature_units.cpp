// Temperatures a user types in K are converted, never read as degC (issue
// 34: `initial: {temperature: 283.15 K}` validated and started the rock at
// 283 degC): the thermal and the continuum sections start the rock at 10
// degC from 283.15 K, as from 10 and from 10 degC, read back from a short
// run's monitors; every absolute temperature key takes the same units
// (rockmass/physical_quantities.h, quantity::temperature), and the shared
// keys' new spellings (heat_transfer, decay in the continuum) run.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "continuum/poroelasticity/continuum_settings.h"
#include "coupling/process_registry.h"
#include "tests/support/bad_scene_checks.h"
#include "tests/support/run_scene.h"
#include "thermal/conduction/thermal_settings.h"

namespace fissure {
namespace {

using testing::replace;

// Blocks without sources or conditions: the rock stays at its initial
// temperature, which the monitor reads after two steps.
const std::string kThermal = R"(name: kelvin_thermal
physics: [thermal]
gravity: [0, 0]
materials:
  - {name: rock, density: 2700, young_modulus: 10 GPa, poisson_ratio: 0.25}
blocks:
  - {name: a, vertices: [[0, 0], [10, 0], [10, 10], [0, 10]]}
monitors:
  - {name: m, point: [5, 5]}
time: {end: 2 h}
thermal:
  materials: [{name: rock, conductivity: 3, heat_capacity: 2.4e6}]
  mesh: {element_size: 2}
  time_step: 1 h
  initial: {temperature: TEMPERATURE}
)";

// A column held at its initial temperature on top (the heat equation on).
const std::string kContinuum = R"(name: kelvin_continuum
physics: [continuum]
gravity: [0, 0]
materials:
  - {name: clay, density: 2000, young_modulus: 1 GPa, poisson_ratio: 0.25}
monitors:
  - {name: m, point: [0.5, 5]}
time: {end: 200 s}
continuum:
  domain: [[0, 0], [1, 0], [1, 10], [0, 10]]
  mesh: {divisions: [1, 10]}
  materials:
    - {name: clay, biot_modulus: 10 GPa, permeability: 1e-15 m^2}
  initial: {temperature: TEMPERATURE}
  conditions:
    - {boundary: left, displacement: [0, free]}
    - {boundary: bottom, displacement: [0, 0]}
    - {boundary: top, temperature: TEMPERATURE}
  time_step: 100 s
)";

/// `text` with every TEMPERATURE replaced by `temperature`.
std::string with_temperature(std::string text, const std::string& temperature) {
  const std::string key = "TEMPERATURE";
  for (size_t at = text.find(key); at != std::string::npos; at = text.find(key))
    text.replace(at, key.size(), temperature);
  return text;
}

/// The monitor's temperature at the end of the scene `text` at `temperature`.
double monitored_temperature(const std::string& text, const std::string& temperature,
                             const std::string& name) {
  const testing::RunResult r = testing::run_scene(
      read_scene_text(with_temperature(text, temperature), name + ".yaml"), name);
  EXPECT_EQ(r.summary.status, "completed") << r.summary.message;
  return r.summary.monitors["m"]["T"].get<double>();
}

TEST(temperature_units, ThermalRockStartsAt283KelvinAsAt10Celsius) {
  const Scene scene = read_scene_text(with_temperature(kThermal, "283.15 K"), "k.yaml");
  EXPECT_EQ(thermal_controls(scene).initial_temperature, 10);
  EXPECT_NEAR(monitored_temperature(kThermal, "283.15 K", "kelvin_thermal"), 10, 1e-12);
  EXPECT_NEAR(monitored_temperature(kThermal, "10 degC", "celsius_thermal"), 10, 1e-12);
  EXPECT_NEAR(monitored_temperature(kThermal, "10", "plain_thermal"), 10, 1e-12);
}

TEST(temperature_units, ContinuumStartsAt283KelvinAsAt10Celsius) {
  const Scene scene = read_scene_text(with_temperature(kContinuum, "283.15 K"), "k.yaml");
  const ContinuumControls& c = continuum_controls(scene);
  EXPECT_EQ(c.initial_temperature, 10);
  ASSERT_EQ(c.conditions.size(), 3u);
  EXPECT_EQ(c.conditions[2].value, 10);
  EXPECT_NEAR(monitored_temperature(kContinuum, "283.15 K", "kelvin_continuum"), 10, 1e-9);
  EXPECT_NEAR(monitored_temperature(kContinuum, "10 degC", "celsius_continuum"), 10, 1e-9);
}

// Every key of an absolute temperature converts K: the thermal conditions'
// temperature and heat_transfer temperature, the convection inlets'; the
// continuum's heat_transfer temperature.
TEST(temperature_units, EveryAbsoluteTemperatureKeyConvertsKelvin) {
  const std::string conditions = replace(
      kThermal, "  initial: {temperature: TEMPERATURE}\n",
      "  conditions:\n"
      "    - {boundary: top, temperature: 293.15 K}\n"
      "    - {boundary: bottom, heat_transfer: {coefficient: 5 W/m^2/K, temperature: 273.15 K}}\n");
  const Scene thermal = read_scene_text(conditions, "k.yaml");
  const ThermalControls& t = thermal_controls(thermal);
  ASSERT_EQ(t.conditions.size(), 2u);
  EXPECT_EQ(t.conditions[0].value, 20);
  EXPECT_EQ(t.conditions[1].value, 5);
  EXPECT_EQ(t.conditions[1].external_temperature, 0);

  const std::string transfer =
      replace(kContinuum, "{boundary: top, temperature: TEMPERATURE}",
              "{boundary: top, heat_transfer: {coefficient: 10, temperature: 303.15 K}}");
  const Scene continuum = read_scene_text(with_temperature(transfer, "20"), "k.yaml");
  const ContinuumControls& c = continuum_controls(continuum);
  EXPECT_EQ(c.conditions[2].value, 30);
  EXPECT_EQ(c.conditions[2].coefficient, 10);
}

// The continuum's sources and conditions take the thermal section's `decay`
// (a sum of exponentials, the decay heat of spent fuel) as well as a history.
TEST(temperature_units, ContinuumTakesDecay) {
  const std::string yaml =
      with_temperature(kContinuum, "10") +
      "  sources:\n"
      "    - {name: heater, point: [0.5, 5], power: 100 W/m, decay: [[0.7, 30 yr], [0.3, 300 "
      "yr]]}\n";
  const Scene scene = read_scene_text(yaml, "k.yaml");
  const ContinuumControls& c = continuum_controls(scene);
  ASSERT_EQ(c.sources.size(), 1u);
  EXPECT_DOUBLE_EQ(c.sources[0].time_factor.at(0), 1);
  EXPECT_DOUBLE_EQ(c.sources[0].time_factor.at(30 * 365.25 * 86400),
                   0.7 * std::exp(-1) + 0.3 * std::exp(-0.1));
  testing::expect_contains(
      testing::parse_error(yaml + "    - {name: two, point: [0.5, 4], power: 1, history: [[0, "
                                  "1]], decay: [[1, 1 yr]]}\n"),
      "continuum.sources[1].decay: found both history and decay; expected one of them");
}

}  // namespace
}  // namespace fissure
