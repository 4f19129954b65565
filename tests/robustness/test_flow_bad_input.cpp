// Bad input to the flow module gives one clear message, never a crash or a
// singular matrix: non-physical fluid or apertures, heads without gravity,
// boundaries that name no fracture, wells off the network, networks that do
// not connect the pressure boundaries, injection into a cluster that no
// pressure boundary reaches.
#include <gtest/gtest.h>

#include <string>

#include "core/base/errors.h"
#include "core/scene/parse_scene.h"
#include "flow/network/fluid.h"
#include "tests/support/flow_networks.h"
#include "tests/support/run_scene.h"

namespace fissure {
namespace {

const char* kScene = R"(
name: bad_flow
physics: [flow]
gravity: [0, -9.81]
materials:
  - {name: rock, density: 2700, young_modulus: 10 GPa, poisson_ratio: 0.25}
blocks:
  - {name: domain, vertices: [[0, 0], [10, 0], [10, 10], [0, 10]]}
time: {end: 1}
flow:
%s
)";

std::string scene_with(const std::string& flow) {
  std::string text = kScene;
  text.replace(text.find("%s"), 2, flow);
  return text;
}

std::string parse_error(const std::string& flow) {
  try {
    parse_scene_text(scene_with(flow), "bad.yaml");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(flow_bad_input, SceneErrors) {
  EXPECT_NE(parse_error("  fluid: {viscosity: 0}").find(
                "flow.fluid.viscosity: found '0'; expected a viscosity > 0"),
            std::string::npos);
  EXPECT_NE(parse_error("  fluid: {viscosity: -1e-3 Pa*s}").find("expected a viscosity > 0"),
            std::string::npos);
  EXPECT_NE(parse_error("  network:\n    traces: [{from: [0, 1], to: [10, 1], aperture: -1 um}]")
                .find("flow.network.traces[0].aperture: found '-1 um'; expected a length > 0"),
            std::string::npos);
  EXPECT_NE(parse_error("  network:\n    traces: [{from: [0, 1], to: [10, 1], aperture: 0}]")
                .find("expected a length > 0"),
            std::string::npos);
  EXPECT_NE(parse_error("  apertures: {residual: 0}").find("flow.apertures.residual"),
            std::string::npos);
  EXPECT_NE(parse_error("  gravity: false\n  conditions: [{boundary: left, head: 10 m}]")
                .find("found a head with gravity off"),
            std::string::npos);
  EXPECT_NE(parse_error("  conditions: [{boundary: left, pressure: 1 MPa, flux: 1e-6}]")
                .find("expected exactly one"),
            std::string::npos);
  EXPECT_NE(parse_error("  fluid: {viscosty: 1e-3}").find("did you mean 'viscosity'"),
            std::string::npos);
  EXPECT_NE(parse_error("  hm: {normal_stiffness: 1 GPa/m}").find("physics does not list mechanics"),
            std::string::npos);
  // And the API refuses a non-physical fluid too.
  EXPECT_THROW(flow::check_fluid({1000, 0, 2.2e9}), SceneError);
  EXPECT_THROW(flow::check_fluid({1000, -1, 2.2e9}), SceneError);
}

/// Runs the flow scene and returns the failure message ("" if it completed).
std::string run_message(const std::string& flow) {
  const Scene scene = parse_scene_text(scene_with(flow), "bad.yaml");
  const testing::RunResult r = testing::run_scene(scene, "flow_bad_input");
  return r.summary.status == "completed" ? "" : r.summary.message;
}

TEST(flow_bad_input, BoundaryThatNamesNoFracture) {
  const std::string m = run_message(
      "  network:\n    traces: [{from: [-1, 5], to: [11, 5]}]\n"
      "  conditions: [{boundary: left, pressure: 1 MPa}, {boundary: top, pressure: 0}]");
  EXPECT_NE(m.find("bad.yaml:"), std::string::npos) << m;
  EXPECT_NE(m.find("flow.conditions[1].boundary: found 'top', which holds no node of the fracture "
                   "network"),
            std::string::npos)
      << m;
  EXPECT_NE(m.find("left (1 nodes)"), std::string::npos) << m;
}

TEST(flow_bad_input, WellOffTheNetwork) {
  const std::string m = run_message(
      "  network:\n    traces: [{from: [-1, 5], to: [11, 5]}]\n"
      "  conditions: [{boundary: left, pressure: 0}]\n"
      "  wells: [{name: w1, point: [5, 6], rate: 1e-6}]");
  EXPECT_NE(m.find("flow.wells[0].point: found (5, 6)"), std::string::npos) << m;
  EXPECT_NE(m.find("expected a point on a fracture"), std::string::npos) << m;
}

TEST(flow_bad_input, NetworkThatDoesNotConnectThePressureBoundaries) {
  // Two fractures, one from the left side, one from the right: they never meet.
  const std::string m = run_message(
      "  network:\n    traces: [{from: [-1, 3], to: [4, 3]}, {from: [6, 7], to: [11, 7]}]\n"
      "  conditions: [{boundary: left, pressure: 1 MPa}, {boundary: right, pressure: 0}]");
  EXPECT_NE(m.find("does not connect the pressure boundaries 'left'"), std::string::npos) << m;
  EXPECT_NE(m.find("and 'right'"), std::string::npos) << m;
}

TEST(flow_bad_input, InjectionIntoAnIsolatedCluster) {
  const std::string m = run_message(
      "  network:\n    traces: [{from: [-1, 3], to: [11, 3]}, {from: [4, 7], to: [6, 7]}]\n"
      "  conditions: [{boundary: left, pressure: 0}]\n"
      "  wells: [{name: w1, point: [5, 7], rate: 1e-6}]");
  EXPECT_NE(m.find("no steady state"), std::string::npos) << m;
  EXPECT_NE(m.find("no fixed-pressure boundary reaches"), std::string::npos) << m;
}

TEST(flow_bad_input, EmptyNetwork) {
  const std::string m =
      run_message("  network:\n    traces: [{from: [20, 3], to: [30, 3]}]\n"
                  "  conditions: [{boundary: left, pressure: 0}]");
  EXPECT_NE(m.find("the fracture network is empty"), std::string::npos) << m;
}

}  // namespace
}  // namespace fissure
