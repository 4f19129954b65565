// Bad input to the fracture convection (thermal.convection, docs/thermal.md
// 7) gives one clear, located message: a Nusselt number <= 0 or a word other
// than wall_temperature, fluid properties <= 0, convection without the flow
// process (when the scene is read), an inlet on a boundary without fracture
// nodes (when the run starts: the flow builds its network then).
#include <gtest/gtest.h>

#include <string>

#include "core/base/errors.h"
#include "coupling/process_registry.h"
#include "tests/support/bad_scene_checks.h"

namespace fissure {
namespace {

std::string scene(const std::string& physics, const std::string& convection) {
  return R"(name: bad_convection
physics: )" +
         physics +
         R"(
materials:
  - {name: rock, density: 2700, young_modulus: 10 GPa, poisson_ratio: 0.25}
blocks:
  - {name: a, vertices: [[0, 0], [10, 0], [10, 10], [0, 10]]}
  - {name: b, vertices: [[10, 0], [20, 0], [20, 10], [10, 10]]}
time: {end: 1 d}
flow:
  conditions: [{boundary: bottom, pressure: 1 kPa}, {boundary: top, pressure: 0}]
thermal:
  time_step: 1 h
  materials: [{name: rock, conductivity: 3, heat_capacity: 2.4e6}]
  convection:
)" + convection;
}

using testing::expect_contains;
using testing::parse_error;
using testing::start_error;

TEST(fracture_convection_bad_input, NonPositiveNusselt) {
  for (const char* nu : {"0", "-8"}) {
    const std::string e = parse_error(scene("[flow, thermal]", std::string("    nusselt: ") + nu));
    expect_contains(e, "bad.yaml:15:14: thermal.convection.nusselt: found '" + std::string(nu) +
                           "'; expected a number > 0");
  }
  expect_contains(parse_error(scene("[flow, thermal]", "    nusselt: wall")),
                  "thermal.convection.nusselt: found 'wall'");
  expect_contains(
      parse_error(scene("[flow, thermal]", "    fluid: {specific_heat: 0}")),
      "thermal.convection.fluid.specific_heat: found '0'; expected a specific heat > 0");
}

TEST(fracture_convection_bad_input, ConvectionWithoutFlow) {
  std::string text = scene("[thermal]", "    nusselt: 8");
  text.replace(text.find("flow:\n"), 79, "");
  expect_contains(parse_error(text),
                  "bad.yaml:13:3: thermal.convection: found thermal.convection without the flow "
                  "process; expected `flow` in physics");
}

TEST(fracture_convection_bad_input, InletOnAnUnknownBoundary) {
  const std::string e =
      start_error(scene("[flow, thermal]", "    inlets: [{boundary: tunnel, temperature: 80}]"));
  expect_contains(e,
                  "bad.yaml:15:14: thermal.convection.inlets[0]: found boundary 'tunnel', which "
                  "has no node of the fracture network; expected one of: ");
  expect_contains(e, "bottom");
}

// PETSc options PETSc accepts but whose solver stops at the first solve,
// with a message PETSc continues on a second line (the long fuzz run of
// issue 35, case 9144): one located line, the second joined to it.
TEST(fracture_convection_bad_input, PetscsTwoLineRefusalIsOneLocatedLine) {
  const std::string text = R"(physics: [flow, thermal]
materials:
  - {name: rock, density: 2760 kg/m^3, young_modulus: 50 GPa, poisson_ratio: 0.25}
rock_mass:
  domain: [[0, 0], [10, 0], [10, 10], [0, 10]]
  fractures:
    - {from: [0, 6.5], to: [10, 4.0]}
    - {from: [2.0, 0], to: [4.5, 10]}
    - {from: [6.0, 10], to: [8.0, 0]}
flow:
  network: {source: rock_mass}
  conditions: [{boundary: left, pressure: 10 MPa}, {boundary: right, pressure: 0 Pa}]
  solver: {type: petsc, petsc_options: -ksp_type preonly -pc_type none}
thermal:
  materials: [{name: rock, conductivity: 3 W/m/K, specific_heat: 900 J/kg/K}]
  convection:
    inlets: [{boundary: left, temperature: 100}]
time: {end: 2 d}
)";
  const std::string e = start_error(text);
  expect_contains(e, "bad.yaml:13:11: flow.solver: PETSc error");
  expect_contains(e,
                  "doesn't make sense with nonzero initial guess; you probably want a KSP type "
                  "of Richardson");
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;
}

}  // namespace
}  // namespace fissure
