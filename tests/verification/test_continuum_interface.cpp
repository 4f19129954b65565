// The continuum's coupling interface (docs/continuum.md 4, "Interfaces"):
// the test plays the other process, writing tractions, pressures and
// temperatures into the shared field continuum_interface_loads and reading
// the displacements and fluxes back from continuum_interfaces, against
// closed forms: an elastic column
// under a uniform traction (uniaxial strain), and steady conduction and
// Darcy flow through a slab whose far face the interface holds.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "continuum/poroelasticity/continuum_process.h"
#include "core/base/errors.h"
#include "coupling/process_registry.h"
#include "rockmass/fields/continuum_interface.h"
#include "tests/support/bad_scene_checks.h"

namespace fissure {
namespace {

using continuum::ContinuumProcess;
using testing::at;
using testing::expect_contains;
using testing::parse_error;
using testing::replace;
using testing::start_error;

/// A rectangle [0, width] x [0, height] of `nx` x `ny` cells, E = 10 GPa,
/// nu = 0.25 (lambda + 2G = 12 GPa), no gravity, with `conditions`.
std::string box(double width, double height, int nx, int ny, double biot,
                const std::string& conditions) {
  char text[2048];
  std::snprintf(text, sizeof text, R"(name: interface
physics: [continuum]
gravity: [0, 0]
materials:
  - {name: rock, density: 2500, young_modulus: 10 GPa, poisson_ratio: 0.25}
time: {end: 1 s}
continuum:
  domain: [[0, 0], [%.17g, 0], [%.17g, %.17g], [0, %.17g]]
  mesh: {divisions: [%d, %d]}
  materials:
    - {name: rock, biot_coefficient: %.17g, biot_modulus: 10 GPa, permeability: 1e-15 m^2,
       conductivity: 2.5 W/m/K, heat_capacity: 2.5 MJ/m^3/K}
  initial: {temperature: 30, pressure: 0.5 MPa}
  conditions:
%s  scheme: monolithic
  time_step: 1 s
)",
                width, width, height, height, nx, ny, biot, conditions.c_str());
  return text;
}

/// The other process: the process, its state, and the shared field.
struct Coupled {
  explicit Coupled(const std::string& yaml)
      : process(read_scene_text(yaml, "interface.yaml")),
        state(RockMass::from_scene(read_scene_text(yaml, "interface.yaml"))) {
    process.initialize(state);
  }
  /// What the continuum publishes on the interface.
  ContinuumInterface& interface(const std::string& name) {
    ContinuumInterface* i = find_interface(state.fields.get(kContinuumInterfaces), name);
    if (!i) throw std::logic_error("no interface " + name);
    return *i;
  }
  /// What the test, as the other process, gives it there.
  ContinuumInterfaceLoad& load(const std::string& name) {
    auto& all = state.fields.get_or_add(kContinuumInterfaceLoads);
    if (ContinuumInterfaceLoad* x = find_interface(all, name)) return *x;
    all.push_back({});
    all.back().name = name;
    return all.back();
  }
  void advance(double dt, int steps) {
    for (int k = 0; k < steps; ++k, t += dt) process.advance(state, t, dt);
  }
  ContinuumProcess process;
  RockMass state;
  double t = 0;
};

constexpr double kConstrained = 12e9;  // lambda + 2G, Pa
const std::string kRollers =
    "    - {boundary: left, displacement: [0, free]}\n"
    "    - {boundary: right, displacement: [0, free]}\n"
    "    - {boundary: bottom, displacement: [free, 0]}\n";

// (a) A column of H = 2 m on rollers, loaded on its top interface by a
// uniform traction of -1 MPa (the fluid coupling switched off: alpha =
// 1e-9): uniaxial strain, u_y(top) = -sigma H / (lambda + 2G). P2 holds the
// linear displacement exactly, so the tolerance is round-off; the same load
// as a normal_pressure condition gives the same displacement field.
TEST(ContinuumInterface, TractionOnTheTopGivesTheUniaxialStrainDisplacement) {
  const double sigma = 1e6, height = 2;
  Coupled run(
      box(1, height, 2, 4, 1e-9, kRollers + "    - {boundary: top, interface: [traction]}\n"));
  EXPECT_EQ(run.process.reads(), std::vector<std::string>{"continuum_interface_loads"});
  EXPECT_EQ(run.process.writes(), std::vector<std::string>{"continuum_interfaces"});
  ContinuumInterface& top = run.interface("top");
  ASSERT_EQ(top.nodes.size(), 3u);  // the vertices of the two cells' top edges
  for (const Vec2& x : top.nodes) EXPECT_DOUBLE_EQ(x.y(), height);
  ASSERT_EQ(top.displacement.size(), 3u);
  run.load("top").traction.assign(top.nodes.size(), Vec2(0, -sigma));
  run.advance(1, 1);
  const double exact = -sigma * height / kConstrained;
  double largest = 0;
  for (const Vec2& u : run.interface("top").displacement) {
    largest = std::max(largest, std::abs(u.y() - exact) / std::abs(exact));
    EXPECT_NEAR(u.x(), 0, 1e-12 * std::abs(exact));
  }
  std::printf("uniaxial strain: largest relative error of u_y(top) %.3g\n", largest);
  EXPECT_LT(largest, 1e-12);
  // The exchanged values are the returned ones: 3 + 2 (midside)
  // displacements, 3 pressures, no temperature, 3 + 3 fluxes.
  const std::vector<ExchangedField> exchanged = run.process.exchanged_values(run.state);
  ASSERT_EQ(exchanged.size(), 5u);
  EXPECT_EQ(exchanged[0].values.size(), 10u);
  EXPECT_EQ(exchanged[1].values.size(), 3u);
  EXPECT_EQ(exchanged[2].values.size(), 0u);
  EXPECT_EQ(exchanged[3].values.size() + exchanged[4].values.size(), 6u);

  Coupled pressed(
      box(1, height, 2, 4, 1e-9, kRollers + "    - {boundary: top, normal_pressure: 1 MPa}\n"));
  pressed.advance(1, 1);
  const Eigen::VectorXd &a = run.process.fields().displacement,
                        &b = pressed.process.fields().displacement;
  const double difference = (a - b).lpNorm<Eigen::Infinity>() / b.lpNorm<Eigen::Infinity>();
  std::printf("interface traction against normal_pressure: %.3g\n", difference);
  EXPECT_LT(difference, 1e-12);
}

// The same traction given on pieces of the edges (traction_pieces: an edge
// of ContinuumInterface::edges, a part of it and the values at its ends;
// what a tied block region gives, rockmass/fields/interface_ties.h) loads
// the continuum as the nodal one, to round-off. The published trace: the displacement at each
// edge's midpoint is the field's there, the pressure at each node the
// field's, and a place on the interface samples them exactly (P2 along the
// edge: the linear field of uniaxial strain).
TEST(ContinuumInterface, PieceTractionsLoadAsNodalOnesAndTheTraceIsPublished) {
  const double sigma = 1e6, height = 2;
  const std::string yaml =
      box(1, height, 2, 4, 1e-9, kRollers + "    - {boundary: top, interface: [traction]}\n");
  Coupled nodal(yaml), per_edge(yaml);
  nodal.load("top").traction.assign(3, Vec2(0.3 * sigma, -sigma));
  const ContinuumInterface& top = per_edge.interface("top");
  ASSERT_EQ(top.edges.size(), 2u);
  // Each edge in two pieces, of 0.3 and 0.7 of it.
  for (int e = 0; e < 2; ++e)
    for (const auto& [s0, s1] : {std::pair{0.0, 0.3}, std::pair{0.3, 1.0}})
      per_edge.load("top").traction_pieces.push_back(
          {e, s0, s1, Vec2(0.3 * sigma, -sigma), Vec2(0.3 * sigma, -sigma)});
  nodal.advance(1, 1);
  per_edge.advance(1, 1);
  const Eigen::VectorXd &a = nodal.process.fields().displacement,
                        &b = per_edge.process.fields().displacement;
  EXPECT_LT((a - b).lpNorm<Eigen::Infinity>(), 1e-13 * b.lpNorm<Eigen::Infinity>());
  const ContinuumInterface& i = per_edge.interface("top");
  ASSERT_EQ(i.midside_displacement.size(), 2u);
  ASSERT_EQ(i.pressure.size(), 3u);
  EXPECT_TRUE(i.temperature.empty());
  EXPECT_TRUE(i.takes.traction && !i.takes.fluid_flow && !i.takes.heat_flow);
  // The impedance: 2G / R with R the interface's length over 2 pi.
  EXPECT_NEAR(i.impedance.stiffness, 2 * 4e9 / (1 / (2 * M_PI)), 1e-6 * i.impedance.stiffness);
  for (double x : {0.0, 0.1, 0.37, 0.5, 0.81, 1.0}) {
    const InterfacePlace place = locate_on_interface(i, Vec2(x, height));
    EXPECT_LT(place.distance, 1e-15);
    const continuum::ContinuumMesh::Place at = per_edge.process.mesh().locate(Vec2(x, height));
    const Vec2 u = per_edge.process.values_in(at.triangle, at.weights).displacement;
    EXPECT_LT((displacement_at(i, place) - u).norm(), 1e-12 * u.norm()) << x;
  }
}

// Fluid flowing in at points of an interface (what a fracture network's
// mouths give): the continuum takes it as nodal inflows with the edge's
// linear shape functions, so that at steady state the drained boundary
// gives it all back (mass balance to round-off), wherever the points lie.
TEST(ContinuumInterface, FluidFlowAtPointsIsConserved) {
  Coupled run(box(1, 1, 4, 4, 0.8,
                  kRollers + "    - {boundary: top, interface: [fluid_flow]}\n" +
                      "    - {boundary: bottom, pressure: 0.5 MPa}\n"));
  EXPECT_TRUE(run.interface("top").takes.fluid_flow);
  InterfacePointLoads<double>& fluid = run.load("top").fluid;
  fluid.points = {Vec2(0.1, 1), Vec2(0.33, 1), Vec2(0.5, 1), Vec2(0.9, 1)};
  fluid.values = {1e-9, 2e-9, 0.5e-9, 3e-9};  // m^3/s per m
  run.advance(1e10, 3);                       // to steady state
  // The drained bottom's reaction: the outflow there.
  const Eigen::VectorXd& reaction = run.process.solver().fluid_reaction();
  double outflow = 0;
  for (int v = 0; v < reaction.size(); ++v)
    if (std::abs(run.process.mesh().nodes[v].y()) < 1e-12) outflow -= reaction(v);
  std::printf("fluid at points: in %.6g, out %.6g m^3/s per m\n", 6.5e-9, outflow);
  EXPECT_NEAR(outflow, 6.5e-9, 1e-12 * 6.5e-9);
}

// Until the other side gives tractions (a block region gives its first
// after the continuum has started, and its undrained start has solved), an
// interface that takes them carries the in-situ stress, sigma_0 n: a box
// under its own initial stress of -5 MPa, whose right side is loaded by
// -5 MPa and whose top is an interface given nothing, stays where it is (to
// round-off, against the order of sigma H / E = 5e-4 m that a free top
// would move by).
TEST(ContinuumInterface, AnInterfaceGivenNothingCarriesTheInSituStress) {
  std::string yaml = box(1, 1, 4, 4, 0.8,
                         "    - {boundary: left, displacement: [0, free]}\n"
                         "    - {boundary: bottom, displacement: [free, 0]}\n"
                         "    - {boundary: right, traction: [-5 MPa, 0]}\n"
                         "    - {boundary: top, interface: [traction]}\n");
  yaml = replace(yaml, "initial: {temperature: 30, pressure: 0.5 MPa}",
                 "initial: {temperature: 30, pressure: 0.5 MPa, stress: [-5 MPa, -5 MPa, 0]}");
  Coupled run(yaml);
  double largest = run.process.fields().displacement.cwiseAbs().maxCoeff();  // the undrained start
  run.advance(1, 2);
  largest = std::max(largest, run.process.fields().displacement.cwiseAbs().maxCoeff());
  std::printf("in-situ stress held by an interface given nothing: largest |u| %.3g m\n", largest);
  EXPECT_LT(largest, 1e-12);
}

// The tractions are taken per node, in the nodes' order: a load growing
// with x settles the top more where x is larger.
TEST(ContinuumInterface, TractionsArePerNodeInTheInterfacesOrder) {
  Coupled run(box(1, 1, 4, 2, 1e-9, kRollers + "    - {boundary: top, interface: [traction]}\n"));
  ContinuumInterface& top = run.interface("top");
  for (const Vec2& x : top.nodes) run.load("top").traction.push_back(Vec2(0, -1e6 * x.x()));
  run.advance(1, 1);
  const std::vector<Vec2> nodes = run.interface("top").nodes;
  const std::vector<Vec2> u = run.interface("top").displacement;
  // More load where x is larger: u_y decreases with x.
  for (std::size_t i = 0; i < nodes.size(); ++i)
    for (std::size_t j = 0; j < nodes.size(); ++j)
      if (nodes[i].x() < nodes[j].x()) {
        EXPECT_GT(u[i].y(), u[j].y());
      }
}

// (b) Steady conduction through a slab of L = 1 m: 50 degC on the left,
// the interface on the right given 10 degC. The heat flux out of the
// continuum at the interface is lambda (50 - 10) / L = 100 W/m^2 at every
// node (P1 holds the linear profile exactly; three steps of 1e14 s leave
// round-off of the transient).
TEST(ContinuumInterface, GivenTemperatureReturnsTheConductedHeatFlux) {
  Coupled run(box(1, 0.1, 10, 1, 1,
                  "    - {boundary: left, displacement: [0, free]}\n"
                  "    - {boundary: bottom, displacement: [free, 0]}\n"
                  "    - {boundary: left, temperature: 50}\n"
                  "    - {boundary: right, interface: [temperature]}\n"));
  ASSERT_TRUE(run.process.controls().with_temperature());
  ContinuumInterface& right = run.interface("right");
  run.load("right").temperature.assign(right.nodes.size(), 10);
  run.advance(1e14, 3);
  const double exact = 2.5 * (50 - 10) / 1.0;
  double largest = 0;
  for (double q : run.interface("right").heat_flux)
    largest = std::max(largest, std::abs(q - exact) / exact);
  std::printf("heat flux: largest relative error %.3g\n", largest);
  EXPECT_LT(largest, 1e-10);
  for (double q : run.interface("right").fluid_flux) EXPECT_EQ(q, 0);  // pressure not given
}

// (b) Steady Darcy flow through the same slab: 1 MPa on the left, the
// interface on the right given 0: the fluid flux out is
// (k / mu) (p_left - p_right) / L = 1e-6 m/s.
TEST(ContinuumInterface, GivenPressureReturnsTheDarcyFlux) {
  Coupled run(box(1, 0.1, 10, 1, 1,
                  "    - {boundary: left, displacement: [0, free]}\n"
                  "    - {boundary: bottom, displacement: [free, 0]}\n"
                  "    - {boundary: left, pressure: 1 MPa}\n"
                  "    - {boundary: right, interface: [traction, pressure]}\n"));
  EXPECT_FALSE(run.process.controls().with_temperature());
  ContinuumInterface& right = run.interface("right");
  run.load("right").pressure.assign(right.nodes.size(), 0);
  run.advance(1e12, 3);
  const double exact = 1e-15 / 1e-3 * 1e6 / 1.0;
  double largest = 0;
  for (double q : run.interface("right").fluid_flux)
    largest = std::max(largest, std::abs(q - exact) / exact);
  std::printf("fluid flux: largest relative error %.3g\n", largest);
  EXPECT_LT(largest, 1e-10);
  // Not given: the pressure is held at its last given value.
  run.load("right").pressure.clear();
  run.advance(1e12, 1);
  for (double q : run.interface("right").fluid_flux) EXPECT_NEAR(q, exact, 1e-10 * exact);
}

// (c) Bad input: an interface on a boundary the domain does not have, an
// unknown quantity, two interfaces on one boundary, and a quantity the
// condition does not take, given at run time.
TEST(ContinuumInterface, BadInterfacesAreLocated) {
  const std::string valid =
      box(1, 1, 1, 1, 1, kRollers + "    - {boundary: top, interface: [traction]}\n");
  EXPECT_EQ(parse_error(valid), "");
  EXPECT_EQ(start_error(valid), "");

  std::string s = replace(valid, "{boundary: top, interface", "{boundary: lid, interface");
  std::string e = parse_error(s);
  expect_contains(e, at(s, "lid"));
  expect_contains(e, "continuum.conditions[3].boundary");

  s = replace(valid, "interface: [traction]", "interface: [traction, heat]");
  e = parse_error(s);
  expect_contains(e, at(s, "heat]"));
  expect_contains(e, "heat");

  s = replace(valid, "interface: [traction]}\n",
              "interface: [traction]}\n    - {boundary: top, interface: [pressure]}\n");
  e = parse_error(s);
  expect_contains(e, at(s, "interface: [pressure]"));
  expect_contains(e, "found a second interface on boundary 'top'");

  Coupled run(valid);
  ContinuumInterface& top = run.interface("top");
  run.load("top").pressure.assign(top.nodes.size(), 0);
  try {
    run.advance(1, 1);
    ADD_FAILURE() << "a pressure given to a traction interface was taken";
  } catch (const SolverError& error) {
    expect_contains(error.what(), "interface.yaml:");
    expect_contains(error.what(), "the interface 'top' was given pressure values");
  }
}

}  // namespace
}  // namespace fissure
