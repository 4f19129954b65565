// Deformable DEM blocks in motion (mechanics/dem/zoned_block.h;
// docs/dem.md, "Deformable blocks"):
//  * energy: an L-shaped block (E = 10 GPa, nu = 0.25, 2,500 kg/m^3, zones
//    of 0.25 m), free, released from a uniform stress, rings for 10 ms.
//    Undamped, kinetic + strain energy stays at its start to O(dt^2)
//    (central differences conserve a nearby energy; the plain one
//    oscillates about it by (omega dt)^2): the largest departure at 0.8,
//    0.4 and 0.2 of the critical step, and the observed order (2). With
//    local damping 0.8, mass-proportional damping, or Rayleigh's
//    stiffness-proportional damping (the zones' viscous stresses), most of
//    the energy goes and kinetic + strain + dissipated stays at the start to
//    the same order. On a fixed base under gravity the work of the weight enters the
//    balance too;
//  * a P wave along a bar (20 m x 1 m, rollers on its long sides: plane
//    strain with no lateral strain, a one-dimensional wave at c_p = sqrt((K
//    + 4G/3) / rho)), driven at its end by a velocity pulse sin^2(pi t / T)
//    of T = 1.8 ms (c_p T = 3.9 m, 20 zones of 0.2 m): the pulse's peak
//    passes x = 5 m and 15 m at x / c_p + T / 2 (within 2 % of the travel
//    time); the speed between them within 1 % of c_p at zones of 0.2 m and
//    0.1 m (the group velocity of linear zones with lumped masses, c_p cos
//    (k h / 2), is 1.2 % slow at a 20-zone wavelength, the pulse's
//    shortest; most of the pulse is longer: 0.15 % and 0.09 % measured),
//    and the energy put in by the driven end (a support's reaction) is the
//    bar's kinetic + strain energy (to 1e-3).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "mechanics/dem/zoned_block.h"

namespace fissure::dem {
namespace {

constexpr ZoneMaterial kRock{10e9, 0.25, 2500};

Polygon l_block() {
  return Polygon({{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 2}, {0, 2}});
}

struct Balance {
  double start = 0;                          ///< J/m
  double departure = 0;                      ///< the largest |E + D - W - E_0| / E_0 over the steps
  double dissipated = 0, external_work = 0;  ///< at the end, J/m
};

/// The block from `stress` at rest for `seconds`, at `fraction` of its
/// critical step.
Balance ring(double fraction, const DampingControls& damping, double seconds = 0.01,
             bool on_base = false, double stiffness_damping = 0) {
  ZonedBlock block(mesh_block(l_block(), 0.25), kRock);
  block.set_stress({1e4, -2e4, 5e3, -0.25e4});
  Vec2 gravity = Vec2::Zero();
  if (on_base) {
    gravity = Vec2(0, -9.81);
    for (int a = 0; a < block.n_nodes(); ++a)
      if (block.positions()[a].y() == 0) block.fix(a, true, true);
  }
  const double dt = fraction * block.critical_time_step();
  const int steps = static_cast<int>(std::ceil(seconds / dt));
  Balance b;
  b.start = block.energy().kinetic + block.energy().strain;
  for (int k = 0; k < steps; ++k) {
    block.step(dt, gravity, damping, stiffness_damping);
    const EnergyBalance e = block.energy();
    const double total = e.kinetic + e.strain + e.dissipated - e.external_work;
    b.departure = std::max(b.departure, std::abs(total - b.start) / b.start);
    b.dissipated = e.dissipated;
    b.external_work = e.external_work;
  }
  return b;
}

/// Departures at 0.8, 0.4, 0.2 of the critical step, printed with their
/// orders, which must be 2 (within 0.25).
void expect_second_order(const char* what, const DampingControls& damping, bool on_base = false,
                         double stiffness_damping = 0) {
  std::vector<double> departures;
  for (double fraction : {0.8, 0.4, 0.2}) {
    const Balance b = ring(fraction, damping, 0.01, on_base, stiffness_damping);
    departures.push_back(b.departure);
    std::printf(
        "%s, dt = %.1f of the critical step: energy balance off by %.3e of the start "
        "(dissipated %.3f, external work %.3f of it)\n",
        what, fraction, b.departure, b.dissipated / b.start, b.external_work / b.start);
  }
  for (std::size_t i = 1; i < departures.size(); ++i) {
    const double order = std::log2(departures[i - 1] / departures[i]);
    std::printf("%s: observed order %.2f\n", what, order);
    EXPECT_GT(order, 1.75) << what;
    EXPECT_LT(order, 2.25) << what;
  }
}

TEST(DemZonedDynamics, AFreeUndampedBlockConservesEnergyToSecondOrder) {
  expect_second_order("undamped", {});
  // The energy moves between strain and motion (the test is not idle).
  const Balance b = ring(0.2, {});
  EXPECT_LT(b.departure, 1e-3);
  EXPECT_EQ(b.dissipated, 0);
}

TEST(DemZonedDynamics, DampingDissipatesWhatTheBlockLoses) {
  expect_second_order("local damping 0.8", {0.8, 0});
  expect_second_order("mass damping 2000/s", {0, 2000});
  for (const DampingControls& d : {DampingControls{0.8, 0}, DampingControls{0, 2000}}) {
    const Balance b = ring(0.4, d);
    EXPECT_GT(b.dissipated, 0.5 * b.start);  // most of it gone
  }
  // On a base, under gravity: the weight's work in the balance.
  expect_second_order("on a base, gravity, local damping", {0.8, 0}, true);
  // Rayleigh's stiffness-proportional part, beta = 0.1 of the critical
  // step (xi = 0.1 at the highest frequency 2 / dt_crit, whose damped
  // bound is then 0.905 dt_crit, above the 0.8 of the coarsest run): what
  // the zones' viscous stresses take is in the balance.
  const double beta = 0.1 * ZonedBlock(mesh_block(l_block(), 0.25), kRock).critical_time_step();
  expect_second_order("stiffness damping 0.1 dt_crit", {}, false, beta);
  const Balance b = ring(0.4, {}, 0.01, false, beta);
  EXPECT_GT(b.dissipated, 0.3 * b.start);  // 0.43 measured: the zones' high modes
}

/// A point's zone and its weights there (barycentric), to read the
/// velocity field at it.
struct Probe {
  std::array<int, 3> nodes{};
  double weight[3] = {0, 0, 0};
  double velocity_x(const ZonedBlock& block) const {
    double v = 0;
    for (int k = 0; k < 3; ++k) v += weight[k] * block.velocities()[nodes[k]].x();
    return v;
  }
};

Probe probe(const ZonedBlock& block, const Vec2& p) {
  const std::vector<Vec2>& x = block.positions();
  for (const auto& t : block.zones()) {
    const double whole = orient(x[t[0]], x[t[1]], x[t[2]]);
    const double w0 = orient(p, x[t[1]], x[t[2]]) / whole, w1 = orient(x[t[0]], p, x[t[2]]) / whole;
    const double w2 = 1 - w0 - w1;
    if (std::min({w0, w1, w2}) >= -1e-12) return {t, {w0, w1, w2}};
  }
  ADD_FAILURE() << "no zone holds (" << p.x() << ", " << p.y() << ")";
  return {};
}

struct Wave {
  double arrival[2] = {0, 0};  ///< s, of the peak at x = 5 m and 15 m
  double speed = 0;            ///< m/s, between them
  double balance = 0;          ///< |K + U - W| / W at the end
};

Wave p_wave(double zone_size) {
  const double length = 20, pulse = 1.8e-3, v0 = 1e-3;
  ZonedBlock block(mesh_block(Polygon({{0, 0}, {length, 0}, {length, 1}, {0, 1}}), zone_size),
                   kRock);
  std::vector<int> driven;
  for (int a = 0; a < block.n_nodes(); ++a) {
    const Vec2& x = block.positions()[a];
    block.fix(a, x.x() == 0, x.y() == 0 || x.y() == 1);
    if (x.x() == 0) driven.push_back(a);
  }
  const double dt = 0.5 * block.critical_time_step();
  const double stations[2] = {5, 15};
  const Probe probes[2] = {probe(block, Vec2(stations[0], 0.5)),
                           probe(block, Vec2(stations[1], 0.5))};
  // The velocity at the stations (x, 0.5) after each step, at the half steps.
  std::vector<double> times, at[2];
  for (double t = 0; t < 9e-3; t += dt) {
    // The driven end's velocity over this step (its half step's).
    const double tm = t + 0.5 * dt;
    const double s = tm < pulse ? std::sin(std::numbers::pi * tm / pulse) : 0.0;
    for (int a : driven) block.set_velocity(a, Vec2(v0 * s * s, 0));
    block.step(dt, Vec2::Zero(), {});
    times.push_back(tm);
    for (int i = 0; i < 2; ++i) at[i].push_back(probes[i].velocity_x(block));
  }
  Wave w;
  for (int i = 0; i < 2; ++i) {
    // The peak by a parabola through the largest sample and its neighbours.
    const std::size_t k = std::max_element(at[i].begin(), at[i].end()) - at[i].begin();
    const double a = at[i][k - 1], b = at[i][k], c = at[i][k + 1];
    w.arrival[i] = times[k] + 0.5 * dt * (a - c) / (a - 2 * b + c);
  }
  w.speed = (stations[1] - stations[0]) / (w.arrival[1] - w.arrival[0]);
  const EnergyBalance e = block.energy();
  w.balance = std::abs(e.kinetic + e.strain - e.external_work) / e.external_work;
  return w;
}

TEST(DemZonedDynamics, APWaveTravelsAtThePWaveSpeed) {
  const double c = kRock.p_wave_speed(), pulse = 1.8e-3;
  for (double h : {0.2, 0.1}) {
    const Wave w = p_wave(h);
    const double error = std::abs(w.speed / c - 1);
    std::printf(
        "P wave, zones of %.1f m: peak at 5 m at %.5f ms (expected %.5f), at 15 m at "
        "%.5f ms (%.5f); speed %.1f m/s against c_p = %.1f m/s (%.2e); energy balance "
        "%.1e\n",
        h, 1e3 * w.arrival[0], 1e3 * (5 / c + pulse / 2), 1e3 * w.arrival[1],
        1e3 * (15 / c + pulse / 2), w.speed, c, error, w.balance);
    EXPECT_LT(error, 0.01);
    for (int i = 0; i < 2; ++i)
      EXPECT_NEAR(w.arrival[i], (i == 0 ? 5 : 15) / c + pulse / 2, 0.02 * (i == 0 ? 5 : 15) / c);
    EXPECT_LT(w.balance, 1e-3);
  }
}

}  // namespace
}  // namespace fissure::dem
