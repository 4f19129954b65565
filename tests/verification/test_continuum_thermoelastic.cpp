// The continuum's thermo-elasticity and axisymmetry against closed forms:
// the confined thermal stress (verification.md (m)), Lame's thick cylinder
// (o) as an axisymmetric ring in plane strain, and Booker and Savvidou's
// point heat source (l) with its pore pressure.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "coupling/process_registry.h"
#include "tests/support/continuum_runs.h"
#include "tests/support/poroelastic_solutions.h"

namespace fissure {
namespace {

using testing::ContinuumRun;

// Masada dolomite heated by 20 K (Hatzor 2015), drained (p = 0 on the
// boundary). Rollers on all four sides: sxx = syy = szz = -E aT dT / (1 - 2
// nu) = -13.608 MPa; with the top free: sxx = szz = -E aT dT / (1 - nu) =
// -10.539 MPa and eyy = (1 + nu) / (1 - nu) aT dT = 2.902e-4. The constraints
// are ideal, so the only error is the temperature's distance from 40 degC
// after a step of 1e12 s (below 1e-9).
std::string confined_block(bool top_free) {
  return std::string(R"(name: confined
physics: [continuum]
gravity: [0, 0]
materials:
  - {name: dolomite, density: 2700, young_modulus: 43 GPa, poisson_ratio: 0.184}
time: {end: 1e12 s}
continuum:
  domain: [[0, 0], [1, 0], [1, 1], [0, 1]]
  mesh: {divisions: [3, 3]}
  materials:
    - {name: dolomite, biot_modulus: 20 GPa, permeability: 1e-18 m^2, thermal_expansion: 1e-5,
       conductivity: 3, heat_capacity: 2.5e6}
  initial: {temperature: 20}
  conditions:
    - {boundary: left, displacement: [0, free]}
    - {boundary: right, displacement: [0, free]}
    - {boundary: bottom, displacement: [free, 0]}
)") + (top_free ? "" : "    - {boundary: top, displacement: [free, 0]}\n") +
         R"(    - {boundary: exterior, temperature: 40}
    - {boundary: exterior, pressure: 0}
  time_step: 1e12 s
)";
}

TEST(ContinuumThermoelastic, ConfinedBlockCarriesTheThermalStress) {
  ContinuumRun run(read_scene_text(confined_block(false), "confined.yaml"));
  run.advance_to(1e12, 1e12);
  const Eigen::Vector4d s = run.at({0.3, 0.6}).stress;
  const double exact = -43e9 * 1e-5 * 20 / (1 - 2 * 0.184);  // -13.608 MPa
  for (int i : {0, 1, 3}) EXPECT_NEAR(s(i) / exact, 1, 1e-6) << "component " << i;
  EXPECT_NEAR(s(2), 0, 1e-6 * std::abs(exact));
}

TEST(ContinuumThermoelastic, BlockFreeAtTheTopExpandsUpwards) {
  ContinuumRun run(read_scene_text(confined_block(true), "confined.yaml"));
  run.advance_to(1e12, 1e12);
  const continuum::PointValues v = run.at({0.3, 0.6});
  const double e = 43e9 * 1e-5 * 20;
  EXPECT_NEAR(v.stress(0) / (-e / (1 - 0.184)), 1, 1e-6);
  EXPECT_NEAR(v.stress(3) / (-e / (1 - 0.184)), 1, 1e-6);
  EXPECT_NEAR(v.stress(1), 0, 1e-6 * e);
  EXPECT_NEAR(run.at({0.5, 1}).displacement.y() / ((1 + 0.184) / (1 - 0.184) * 1e-5 * 20), 1, 1e-6);
}

// A ring a = 1 m to b = 2 m, 0.5 m high, held at both ends (uz = 0: plane
// strain), inner pressure 10 MPa, drained (one step of 1e12 s, p = 0 on the
// boundary). Lame: u_r(1) = 1.875e-3 m, u_r(1.5) = 1.42361e-3, u_r(2) =
// 1.25e-3; sigma_rr(1) = -10, sigma_tt(1) = 16.667 MPa. u_r = A r + B / r is
// not a polynomial: with 8 quadratic elements across, its error is below
// 1e-4; the catalogue asks 1 % on u_r and 2 % on the wall's stresses.
TEST(ContinuumThermoelastic, AxisymmetricRingMatchesLamesCylinder) {
  const std::string scene = R"(name: lame
physics: [continuum]
gravity: [0, 0]
materials:
  - {name: rock, density: 2500, young_modulus: 10 GPa, poisson_ratio: 0.25}
time: {end: 1e12 s}
continuum:
  geometry: axisymmetric
  domain: [[1, 0], [2, 0], [2, 0.5], [1, 0.5]]
  mesh: {divisions: [8, 2]}
  materials:
    - {name: rock, biot_modulus: 10 GPa, permeability: 1e-18 m^2}
  initial: {undrained_start: false}
  conditions:
    - {boundary: bottom, displacement: [free, 0]}
    - {boundary: top, displacement: [free, 0]}
    - {boundary: left, normal_pressure: 10 MPa}
    - {boundary: exterior, pressure: 0}
  time_step: 1e12 s
)";
  ContinuumRun run(read_scene_text(scene, "lame.yaml"));
  run.advance_to(1e12, 1e12);
  EXPECT_NEAR(run.at({1, 0.25}).displacement.x() / 1.875e-3, 1, 0.01);
  EXPECT_NEAR(run.at({1.5, 0.25}).displacement.x() / 1.42361e-3, 1, 0.01);
  EXPECT_NEAR(run.at({2, 0.25}).displacement.x() / 1.25e-3, 1, 0.01);
  const continuum::PointValues wall = run.at({1.0001, 0.25});
  EXPECT_NEAR(wall.stress(0) / -10e6, 1, 0.02);
  EXPECT_NEAR(wall.stress(3) / 16.667e6, 1, 0.02);
  EXPECT_NEAR(wall.stress(1) / (2 * 0.25 * 10e6 / 3), 1, 0.02) << "sigma_z = 2 nu A";
}

// Booker and Savvidou (verification.md (l)): 1 kW at a point in saturated
// rock (lambda = 3 W/m/K, rho c = 2.484 MJ/m^3/K), axisymmetric, the half
// space z >= 0 with 500 W (the plane z = 0 is a plane of symmetry: no heat
// flow, no water flow, uz = 0). The domain reaches 60 m, five diffusion
// lengths 2 sqrt(kappa t) at one year. Mesh graded from 5 cm at the source
// (1.5 m at 10 m); steps of 1/200 year.
TEST(ContinuumThermoelastic, PointHeatSourceHeatsAndPressurizesAsBookerAndSavvidou) {
  const test::BookerSavvidou exact;
  ContinuumRun run(read_scene_text(exact.scene(0.05, 6, 0.005), "booker_savvidou.yaml"));
  const double year = 365.25 * 86400, t = year;
  run.advance_to(t, 0.005 * year);
  for (double r : {1.0, 2.0, 4.0}) {
    // Along the axis and along the plane of symmetry.
    for (const Vec2& at : {Vec2(0, r), Vec2(r, 0)}) {
      const continuum::PointValues v = run.at(at);
      EXPECT_NEAR(v.temperature / exact.temperature(r, t), 1, 0.02)
          << "r = " << r << " at " << at.transpose();
      EXPECT_NEAR(v.pressure / exact.pressure(r, t), 1, 0.05)
          << "r = " << r << " at " << at.transpose();
    }
  }
  EXPECT_NEAR(run.at({1, 0}).temperature, 24.107, 0.02 * 24.107) << "the catalogue's value";
}

// Kirsch (verification.md (n)): a circular excavation of radius a = 4 m in
// rock under Sx = -60 MPa, Sy = -30 MPa (Hatzor's rock-burst case), plane
// strain, drained and dry. The quarter model 0 <= x, y <= `size`, the wall a
// named line of 64 segments, the far sides loaded with the initial stress's
// tractions: the excavation unloads the wall. Graded mesh: 0.15 m at the wall
// (0.04 a), growing 0.25 per metre. The catalogue: wall sigma_tt within 2 %
// (quadratic elements), displacements 2 %, stresses at r >= 2a 1 %. At 40 a
// the largest error is the roof's u_r, -0.55 % (at 20 a it is -2.2 %: the
// finite domain, not the elements).
std::string kirsch_scene(double size) {
  const double a = 4;
  std::ostringstream arc, domain;
  domain << "[[4, 0], [" << size << ", 0], [" << size << ", " << size << "], [0, " << size << "]";
  arc.precision(17);
  domain.precision(17);
  for (int k = 0; k <= 64; ++k) {
    const double theta = std::numbers::pi / 2 * (64 - k) / 64;  // from (0, a) to (a, 0)
    // The ends exactly on the axes (cos(pi / 2) is not 0 in floating point).
    const double x = k == 0 ? 0 : a * std::cos(theta), y = k == 64 ? 0 : a * std::sin(theta);
    arc << (k ? ", [" : "[") << x << ", " << y << "]";
    if (k < 64) domain << ", [" << x << ", " << y << "]";
  }
  domain << "]";
  std::ostringstream scene;
  scene << R"(name: kirsch
physics: [continuum]
gravity: [0, 0]
materials:
  - {name: rock, density: 2600, young_modulus: 25.3 GPa, poisson_ratio: 0.22}
time: {end: 1e12 s}
continuum:
  domain: )"
        << domain.str() << "\n  boundaries: [{name: wall, line: [" << arc.str() << "]}]\n"
        << "  mesh: {element_size: " << size / 6
        << R"( m, fine_element_size: 0.15 m, size_grading: 0.25}
  materials:
    - {name: rock, biot_modulus: 10 GPa, permeability: 1e-18 m^2}
  initial: {stress: [-60 MPa, -30 MPa, 0], undrained_start: false}
  conditions:
    - {boundary: left, displacement: [0, free]}
    - {boundary: bottom, displacement: [free, 0]}
    - {boundary: right, traction: [-60 MPa, 0]}
    - {boundary: top, traction: [0, -30 MPa]}
    - {boundary: exterior, pressure: 0}
  scheme: monolithic
  time_step: 1e12 s
)";
  return scene.str();
}

TEST(ContinuumThermoelastic, CircularExcavationMatchesKirsch) {
  ContinuumRun run(read_scene_text(kirsch_scene(40 * 4), "kirsch.yaml"));
  run.advance_to(1e12, 1e12);
  const double a = 4, sx = -60e6, sy = -30e6, g = 25.3e9 / (2 * 1.22), nu = 0.22;
  for (double deg : {0.0, 45.0, 90.0}) {
    const double th = deg * std::numbers::pi / 180, c = std::cos(th), s = std::sin(th);
    // On the wall: sigma_tt = Sx + Sy - 2 (Sx - Sy) cos 2 theta.
    const continuum::PointValues wall = run.at({a * c, a * s});
    const double stt = wall.stress(0) * s * s + wall.stress(1) * c * c - 2 * wall.stress(2) * s * c;
    const double stt_exact = sx + sy - 2 * (sx - sy) * std::cos(2 * th);
    EXPECT_NEAR(stt / stt_exact, 1, 0.02) << "wall sigma_tt at " << deg << " deg";
    const double ur = wall.displacement.x() * c + wall.displacement.y() * s;
    const double ut = -wall.displacement.x() * s + wall.displacement.y() * c;
    const double k = a / (4 * g);
    const double ur_exact = k * ((sx + sy) + (sx - sy) * (4 * (1 - nu) - 1) * std::cos(2 * th));
    const double ut_exact = -k * (sx - sy) * (2 * (1 - 2 * nu) + 1) * std::sin(2 * th);
    EXPECT_NEAR(ur / ur_exact, 1, 0.02) << "wall u_r at " << deg << " deg";
    EXPECT_NEAR(ut, ut_exact, 0.02 * std::abs(ur_exact)) << "wall u_theta at " << deg << " deg";
  }
  // r = 2a on the y axis: sigma_tt = sigma_xx = -74.0625, sigma_rr = sigma_yy = -30.9375 MPa.
  const continuum::PointValues v = run.at({0, 2 * a});
  EXPECT_NEAR(v.stress(0) / -74.0625e6, 1, 0.01);
  EXPECT_NEAR(v.stress(1) / -30.9375e6, 1, 0.01);
}

// The t = 0 frame under a sudden surface temperature (issue 36 item 6;
// docs/continuum.md 3, `initial.undrained_start`). A column 1 x 10 m in 1 x
// 20 cells with rollers, 20 degC, whose top is held at 60 degC from t = 0.
// At 0+ no heat has been conducted: T is 20 degC but on the top, where it is
// 60. The undrained response to that heating in uniaxial strain (sigma_yy = 0
// in a column free at the top, no fluid flowed) is
//   Delta p = Lambda Delta T,
//   Lambda = (beta_m - 3 K alpha alpha_T / (K + 4G/3)) / (1/M + alpha^2 / (K + 4G/3)),
// pointwise: with Delta T linear in the top elements, Delta p is linear and
// eps_yy = (alpha Delta p + 3 K alpha_T Delta T) / (K + 4G/3) too, which
// Taylor-Hood's quadratic displacement holds exactly (alpha = 1 here). The
// old start solved the heat equation with dt = 0, the consistent capacity's
// projection of the jump: on this mesh 16.70 degC 0.5 m below the top at
// x = 0 and 4.53 degC at x = 1 (where the diagonals join two top nodes),
// and at x = 0 a pressure of 0.97, -0.081, +0.099, -0.010 of the rise from
// the top down.
TEST(ContinuumThermoelastic, SuddenSurfaceTemperatureStartsFromTheInitialState) {
  const std::string scene = R"(name: sudden_heating
physics: [continuum]
gravity: [0, 0]
materials:
  - {name: rock, density: 2500, young_modulus: 10 GPa, poisson_ratio: 0.25}
time: {end: 1000 s}
continuum:
  domain: [[0, 0], [1, 0], [1, 10], [0, 10]]
  mesh: {divisions: [1, 20]}
  materials:
    - {name: rock, biot_modulus: 10 GPa, permeability: 1e-18 m^2, thermal_expansion: 1e-5,
       fluid_thermal_expansion: 5e-5, conductivity: 3, heat_capacity: 2.5e6}
  initial: {temperature: 20}
  conditions:
    - {boundary: left, displacement: [0, free]}
    - {boundary: right, displacement: [0, free]}
    - {boundary: bottom, displacement: [free, 0]}
    - {boundary: top, temperature: 60}
    - {boundary: top, pressure: 0}
  scheme: monolithic
  time_step: 1000 s
)";
  ContinuumRun run(read_scene_text(scene, "sudden_heating.yaml"));
  const continuum::PoroState& s = run.process().fields();
  const continuum::ContinuumMesh& mesh = run.process().mesh();
  // K = 6.667 GPa, G = 4 GPa, K + 4G/3 = 12 GPa: Lambda = 1.8182e5 Pa/K.
  const double k = 10e9 / (3 * (1 - 2 * 0.25)), m = 12e9;
  const double lambda = (5e-5 - 3 * k * 1e-5 / m) / (1 / 10e9 + 1 / m);
  const double rise = lambda * 40;  // 7.27 MPa
  double lowest = 1e300;
  for (int v = 0; v < mesh.n_vertices; ++v) {
    const bool top = mesh.nodes[v].y() > 10 - 1e-9;
    const double t = s.temperature(v), p = s.pressure(v);
    lowest = std::min(lowest, t);
    // Not below min(initial, boundary) = 20 degC, nor above 60 degC.
    EXPECT_EQ(t, top ? 60 : 20) << "T at y = " << mesh.nodes[v].y();
    // The rise on the top, none below: no sign alternating with depth.
    EXPECT_NEAR(p, top ? rise : 0, 1e-9 * rise) << "p at y = " << mesh.nodes[v].y();
  }
  EXPECT_GE(lowest, 20);
}

}  // namespace
}  // namespace fissure
