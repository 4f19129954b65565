// The explicit DEM's energy ledger and Rayleigh damping (mechanics/dem/
// dem_energy.h, dem_system.h; docs/dem.md section 10; docs/verification.md):
//  * a closed undamped stack (two rigid 1 m blocks, 2,500 kg/m^3, on a fixed
//    base; bonded Coulomb joints of k_n = 2 k_s = 1 GPa/m whose strengths
//    are never reached, so that nothing slips or opens), released under
//    gravity with the upper block moving at (0.02, -0.01) m/s and turning at
//    0.01 rad/s, rings for 0.1 s (some 8 periods of its slowest mode):
//    kinetic + contacts' elastic energy - the weight's work stays at its
//    start to O(dt^2); the largest departure at 0.4 and 0.2 of the critical
//    step and the observed order (2, within 1.75 to 2.25). The balance
//    oscillates about a nearby conserved energy by (omega dt)^2, and the
//    contacts' frames turn with the blocks by 1e-5 rad (a third-order term
//    of the amplitude, dem_energy.h), far below it;
//  * the same stack with local damping 0.8, and with Rayleigh damping
//    (xi = 0.2 at the stack's fundamental frequency): most of the energy is
//    gone and kinetic + stored + dissipated - work stays at its start to the
//    same order;
//  * a block sliding on a frictional joint (20 degrees, no cohesion) at 1
//    m/s under gravity: the balance closes to second order, and the slip
//    dissipated is Coulomb's mu m g s over the block's slide s (within 2 %,
//    the normal force's ringing about m g);
//  * a zoned block on a joint keeps the balance with its zones' own, and a
//    checkpoint carries the ledger and the contacts' dashpots;
//  * a single-degree-of-freedom oscillator (a 1 m block on a linear joint,
//    vertical motion without gravity) with Rayleigh damping: its
//    logarithmic decrement over 6 periods gives the damping ratio xi =
//    a / (2 omega) + b omega / 2 at its frequency omega = sqrt(k_n L / m).
//    The mass-proportional update is the trapezoidal rule: its xi is off
//    by O((omega dt)^2) (measured 5.5e-4 and 1.4e-4 at omega dt = 0.12 and
//    0.06). The dashpots act on the half-step velocities v^{n-1/2}: their
//    lag by dt / 2 stiffens the oscillator by b k omega^2 dt / 2, which
//    lowers the stiffness part's ratio by xi_b omega dt / 2 relative (first
//    order: 2.2e-3 and 1.2e-3 measured at xi_b = 0.05; UDEC's dashpots lag
//    alike). The bound at dt = 0.05 of the critical step (omega dt =
//    0.055), 5e-3 of xi, is three times the largest measured (1.5e-3, xi_b
//    = 0.06); a ratio b omega instead of b omega / 2 would be off by 100 %.
//    The peaks are read by a parabola through the three samples around
//    each (error O(dt^3)).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <utility>
#include <vector>

#include "core/io/memory_checkpoint.h"
#include "mechanics/dem/dem_system.h"
#include "mechanics/dem/zone_mesh.h"
#include "rockmass/joints/coulomb_slip.h"

namespace fissure::dem {
namespace {

constexpr double kDensity = 2500;
constexpr double kG = 9.81;

DemBlock rigid_block(const Polygon& polygon, bool fixed = false) {
  DemBlock b;
  b.polygon = polygon;
  const SectionProperties s = section_properties(polygon);
  b.centroid = s.centroid;
  b.body = rigid_body(s, kDensity);
  b.fixed = fixed;
  return b;
}

Polygon box(double x0, double y0, double x1, double y1) {
  return Polygon({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
}

/// A linear joint that never slips nor opens (a bond stronger than any
/// stress here), or a frictional one without cohesion.
joints::CoulombProperties joint(double friction_deg, bool bonded) {
  joints::CoulombProperties j;
  j.normal_stiffness = 1e9;
  j.shear_stiffness = 0.5e9;
  j.friction_angle = friction_deg * std::numbers::pi / 180;
  if (bonded) j.cohesion = j.tensile_strength = 1e12;
  return j;
}

struct Damping {
  DampingControls controls;
  double stiffness = 0;  ///< beta, s
};

/// `blocks` under gravity on the bonded joint (30 deg), with `damping`.
DemSystem damped_system(std::vector<DemBlock> blocks, const Damping& damping) {
  DemSettings s;
  s.rounding = s.margin = 0.01;
  s.gravity = Vec2(0, -kG);
  s.damping = damping.controls;
  s.stiffness_damping = damping.stiffness;
  return DemSystem(std::move(blocks), {joints::JointLaw(joint(30, true))}, s);
}

DemSystem stack(const Damping& damping) {
  std::vector<DemBlock> blocks;
  blocks.push_back(rigid_block(box(-2, -1, 3, 0), true));
  blocks.push_back(rigid_block(box(0, 0, 1, 1)));
  blocks.push_back(rigid_block(box(0.25, 1, 1.25, 2)));
  blocks[2].velocity = Motion(0.02, -0.01, 0.01);
  return damped_system(std::move(blocks), damping);
}

struct Balance {
  double start = 0;      ///< the energy the balance is measured against, J/m
  double departure = 0;  ///< the largest |balance - its start| / start
  DemEnergy end;
  double slide = 0;  ///< block 1's centroid's move along x, m
};

/// Runs `system` for `seconds` at `fraction` of its critical step at the
/// start; the departure against `scale` (J/m, the energy at stake).
Balance run(DemSystem system, double fraction, double seconds, double scale) {
  system.prepare();
  const double dt = fraction * system.critical_time_step();
  system.set_time_step(dt);
  const int steps = static_cast<int>(std::ceil(seconds / dt));
  Balance b;
  b.start = scale;
  const double at_start = system.energy().balance();
  const double x0 = system.blocks()[1].centroid.x();
  for (int k = 0; k < steps; ++k) {
    system.step();
    const DemEnergy e = system.energy();
    b.departure = std::max(b.departure, std::abs(e.balance() - at_start) / scale);
    b.end = e;
  }
  b.slide = system.blocks()[1].centroid.x() - x0;
  return b;
}

/// The energy at stake in the stack: the upper block's kinetic energy and
/// the weight's work over the joints' settlement, m g (m g / (k_n L)).
double stack_scale() {
  const double m = kDensity, v2 = 0.02 * 0.02 + 0.01 * 0.01, inertia = m / 6;
  return 0.5 * m * v2 + 0.5 * inertia * 0.01 * 0.01 + 2 * m * kG * (2 * m * kG / 1e9);
}

/// Departures at 0.4 and 0.2 of the critical step, printed with the
/// observed order, which must be 2 (within 0.25); returns the run at 0.2.
Balance expect_second_order(const char* what, const auto& make, double seconds, double scale) {
  const Balance coarse = run(make(), 0.4, seconds, scale);
  const Balance fine = run(make(), 0.2, seconds, scale);
  for (const auto& [fraction, b] : {std::pair{0.4, &coarse}, std::pair{0.2, &fine}})
    std::printf(
        "%s, dt = %.1f of the critical step: balance off by %.3e of %.4g J/m (kinetic %.4g, "
        "contacts %.4g, gravity work %.4g, damping %.4g, slip %.4g J/m at the end)\n",
        what, fraction, b->departure, scale, b->end.kinetic, b->end.contacts_elastic,
        b->end.gravity_work, b->end.damping_dissipated, b->end.slip_dissipated);
  const double order = std::log2(coarse.departure / fine.departure);
  std::printf("%s: observed order %.2f\n", what, order);
  EXPECT_GT(order, 1.75) << what;
  EXPECT_LT(order, 2.25) << what;
  // The plain energy of a mode of frequency omega oscillates about the
  // scheme's conserved one by (omega dt / 2)^2 of it: at most 0.04 at 0.2
  // of the critical step 2 / omega_max.
  EXPECT_LT(fine.departure, 0.04) << what;
  return fine;
}

TEST(DemEnergy, AClosedUndampedStackConservesEnergyToSecondOrder) {
  const Balance b = expect_second_order(
      "undamped stack", [] { return stack({}); }, 0.1, stack_scale());
  // Not idle: the energy is in the springs and the motion, gravity worked,
  // and nothing was dissipated.
  EXPECT_GT(b.end.contacts_elastic, 0.1 * b.start);
  EXPECT_GT(b.end.kinetic, 0.01 * b.start);
  EXPECT_GT(b.end.gravity_work, 0.1 * b.start);
  EXPECT_EQ(b.end.damping_dissipated, 0);
  EXPECT_LT(std::abs(b.end.slip_dissipated), 1e-5 * b.start);
}

/// The stack's lowest frequency (rad/s): the upper block's vertical mode
/// on its joint, sqrt(k_n L / m) with L its 0.75 m of contact.
double stack_frequency() {
  return std::sqrt(1e9 * 0.75 / kDensity);
}

TEST(DemEnergy, DampingDissipatesWhatTheStackLoses) {
  const double scale = stack_scale();
  const Balance local = expect_second_order(
      "stack, local damping 0.8",
      [] {
        return stack({{0.8, 0}, 0});
      },
      0.1, scale);
  // Rayleigh's, xi = 0.2 at the stack's lowest frequency (a = xi omega,
  // b = xi / omega).
  const double xi = 0.2, omega = stack_frequency();
  const Balance rayleigh = expect_second_order(
      "stack, Rayleigh damping xi 0.2",
      [&] {
        return stack({{0, xi * omega}, xi / omega});
      },
      0.1, scale);
  for (const Balance* b : {&local, &rayleigh}) {
    // Most of the energy at stake is gone, into the damping, not the slip.
    EXPECT_GT(b->end.damping_dissipated, 0.5 * b->start);
    EXPECT_LT(b->end.kinetic, 0.1 * b->start);
    EXPECT_LT(std::abs(b->end.slip_dissipated), 1e-3 * b->start);
  }
}

DemSystem sliding_block() {
  std::vector<DemBlock> blocks;
  blocks.push_back(rigid_block(box(-1, -1, 5, 0), true));
  blocks.push_back(rigid_block(box(0, 0, 1, 0.5)));
  blocks[1].velocity = Motion(1, 0, 0);
  DemSettings s;
  s.rounding = s.margin = 0.01;
  s.gravity = Vec2(0, -kG);
  return DemSystem(std::move(blocks), {joints::JointLaw(joint(20, false))}, s);
}

TEST(DemEnergy, TheSlipDissipatesWhatASlidingBlockLoses) {
  // 0.2 s of sliding (it stops after v / (g tan 20) = 0.28 s).
  const double m = 0.5 * kDensity, start = 0.5 * m * 1.0;
  const Balance b = expect_second_order("sliding block", sliding_block, 0.2, start);
  // Coulomb's friction on the block's weight over its slide s, mu m g s:
  // the normal force rings about m g by up to m g (the block is released
  // onto unstressed springs, at omega = sqrt(k_n L / m) = 894 rad/s),
  // which moves the friction's work by at most mu m g v0 / omega, 0.9 % of
  // it over the 0.13 m slide; bound 2 %.
  const double mu = std::tan(20 * std::numbers::pi / 180);
  const double friction_work = mu * m * kG * b.slide;
  std::printf("sliding block: slide %.5f m, slip dissipated %.6g J/m, mu m g s %.6g J/m (%+.2e)\n",
              b.slide, b.end.slip_dissipated, friction_work,
              b.end.slip_dissipated / friction_work - 1);
  EXPECT_GT(b.end.slip_dissipated, 0.5 * start);  // most of the motion's energy
  EXPECT_NEAR(b.end.slip_dissipated / friction_work, 1, 0.02);
  EXPECT_EQ(b.end.damping_dissipated, 0);
}

// The ledger's sums and the contacts' dashpot stresses go through a
// checkpoint (the coordinator's rollback takes one every step): a run of the
// stack under Rayleigh damping saved after 150 cycles and read into a fresh
// system (the blocks' polygons and velocities are the coordinator's)
// continues to the same bits, its ledger with it. Without the dashpots in
// the checkpoint the continued run differs at its first cycle.
TEST(DemEnergy, ACheckpointCarriesTheLedgerAndTheDashpots) {
  const double xi = 0.2, omega = stack_frequency();
  const auto make = [&] { return stack({{0, xi * omega}, xi / omega}); };
  DemSystem straight = make();
  straight.prepare();
  const double dt = 0.3 * straight.critical_time_step();
  straight.set_time_step(dt);
  for (int k = 0; k < 150; ++k) straight.step();
  MemoryCheckpoint saved;
  {
    CheckpointWriter writer = saved.writer();
    DemSystem::checkpoint(std::as_const(straight), writer);
  }
  DemSystem restarted = make();
  for (std::size_t b = 0; b < straight.blocks().size(); ++b) {
    restarted.blocks()[b].polygon = straight.blocks()[b].polygon;
    restarted.blocks()[b].velocity = straight.blocks()[b].velocity;
  }
  {
    CheckpointReader reader = saved.reader();
    DemSystem::checkpoint(restarted, reader);
  }
  restarted.set_time_step(dt);
  for (int k = 0; k < 150; ++k) {
    straight.step();
    restarted.step();
  }
  const auto same = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  const DemEnergy a = straight.energy(), b = restarted.energy();
  EXPECT_TRUE(same(a.kinetic, b.kinetic) && same(a.contacts_elastic, b.contacts_elastic) &&
              same(a.gravity_work, b.gravity_work) &&
              same(a.damping_dissipated, b.damping_dissipated) &&
              same(a.slip_dissipated, b.slip_dissipated));
  for (std::size_t k = 1; k < straight.blocks().size(); ++k) {
    const Vec2 p = straight.blocks()[k].centroid, q = restarted.blocks()[k].centroid;
    EXPECT_TRUE(same(p.x(), q.x()) && same(p.y(), q.y())) << "block " << k;
  }
  EXPECT_GT(a.damping_dissipated, 0);
}

/// A deformable 1 m block (zones of 0.25 m, E = 10 GPa, nu = 0.25) on a
/// fixed rigid base, on the bonded joint, released under gravity.
DemSystem zoned_on_base(const Damping& damping) {
  std::vector<DemBlock> blocks;
  blocks.push_back(rigid_block(box(-1, -1, 2, 0), true));
  DemBlock zoned;
  zoned.zoned = ZonedBlock(mesh_block(box(0, 0, 1, 1), 0.25), {10e9, 0.25, kDensity});
  blocks.push_back(std::move(zoned));
  return damped_system(std::move(blocks), damping);
}

TEST(DemEnergy, AZonedBlockOnAJointKeepsTheBalanceUndampedAndWithRayleighDamping) {
  // The energy at stake: the weight's work over the joint's closure, m g
  // (m g / (k_n L)), L = 1 m.
  const double weight = kDensity * kG, scale = weight * weight / 1e9;
  const Balance undamped = expect_second_order(
      "zoned block on a joint, undamped", [] { return zoned_on_base({}); }, 0.0225, scale);
  EXPECT_GT(undamped.end.zones_strain, 1e-3 * scale);  // the zones take part
  EXPECT_GT(undamped.end.kinetic, 1e-2 * scale);
  // Rayleigh's, xi = 0.01 at the block's bounce on the joint (omega =
  // sqrt(k_n L / m) = 632 rad/s), on the nodes' masses, the contacts'
  // dashpots and the zones' stress rate (xi = 0.1 there overdamps the
  // zones' highest modes, xi = 3 at 4e4 rad/s, and the balance's
  // departure, 4e-8, no longer shows the scheme's order).
  const double omega = std::sqrt(1e9 / kDensity), xi = 0.01;
  const Balance damped = expect_second_order(
      "zoned block on a joint, Rayleigh xi 0.01",
      [&] {
        return zoned_on_base({{0, xi * omega}, xi / omega});
      },
      0.0225, scale);
  EXPECT_GT(damped.end.damping_dissipated, 0.05 * scale);  // 0.125 measured
  EXPECT_LT(damped.end.kinetic, 0.9 * undamped.end.kinetic);
}

/// The logarithmic decrement's damping ratio of a 1 m block on a linear
/// joint (vertical, no gravity) with Rayleigh's a and b, at `fraction` of
/// the (damped) critical step; and its frequency sqrt(k_n L / m).
struct Decay {
  double xi = 0, omega = 0, critical = 0, undamped_critical = 0;
};

Decay oscillator(double a, double b, double fraction) {
  std::vector<DemBlock> blocks;
  blocks.push_back(rigid_block(box(-1, -1, 2, 0), true));
  blocks.push_back(rigid_block(box(0, 0, 1, 1)));
  blocks[1].velocity = Motion(0, 0.01, 0);
  DemSettings s;
  s.rounding = s.margin = 0.01;
  s.damping = {0, a};
  s.stiffness_damping = b;
  DemSystem system(std::move(blocks), {joints::JointLaw(joint(30, true))}, s);
  system.prepare();
  double length = 0;
  for (const DemContact& c : system.contacts()) length += c.geometry.length;
  Decay d;
  d.omega = std::sqrt(1e9 * length / kDensity);
  d.critical = system.critical_time_step();
  system.set_stiffness_damping(0);
  d.undamped_critical = system.critical_time_step();
  system.set_stiffness_damping(b);
  const double dt = fraction * d.critical;
  system.set_time_step(dt);
  // The peaks of the upper block's height, each by a parabola through the
  // three samples around it.
  std::vector<double> peaks;
  double y[3] = {0, 0, 0};
  const double y0 = system.blocks()[1].centroid.y();
  const double period = 2 * std::numbers::pi / d.omega;
  for (int k = 0; k * dt < 6.3 * period; ++k) {
    system.step();
    y[0] = y[1];
    y[1] = y[2];
    y[2] = system.blocks()[1].centroid.y() - y0;
    if (k >= 2 && y[1] > y[0] && y[1] >= y[2]) {
      const double curvature = y[0] - 2 * y[1] + y[2];
      peaks.push_back(y[1] - 0.125 * (y[2] - y[0]) * (y[2] - y[0]) / curvature);
    }
  }
  EXPECT_GE(peaks.size(), 6u);
  const double n = static_cast<double>(peaks.size() - 1);
  const double delta = std::log(peaks.front() / peaks.back()) / n;
  d.xi = delta / std::sqrt(4 * std::numbers::pi * std::numbers::pi + delta * delta);
  return d;
}

TEST(DemEnergy, RayleighDampingGivesItsDampingRatio) {
  const double omega = oscillator(0, 0, 0.05).omega;
  struct Case {
    const char* what;
    double a, b;
  };
  const Case cases[] = {{"mass-proportional, xi 0.05", 2 * 0.05 * omega, 0},
                        {"stiffness-proportional, xi 0.05", 0, 2 * 0.05 / omega},
                        {"UDEC's xi 0.05 at f = omega / 2 pi", 0.05 * omega, 0.05 / omega},
                        {"mass 0.02 + stiffness 0.06", 2 * 0.02 * omega, 2 * 0.06 / omega}};
  for (const Case& c : cases) {
    const double expected = c.a / (2 * omega) + c.b * omega / 2;
    std::vector<double> errors;
    for (double fraction : {0.1, 0.05}) {
      const Decay d = oscillator(c.a, c.b, fraction);
      errors.push_back(d.xi / expected - 1);
      std::printf(
          "%s, dt = %.2f of the critical step (omega dt %.3f): xi %.5f against %.5f "
          "(%+.2e)\n",
          c.what, fraction, d.omega * fraction * d.critical, d.xi, expected, errors.back());
    }
    EXPECT_NEAR(errors.back(), 0, 5e-3) << c.what;
  }
  // The stiffness-proportional part shortens the critical step by
  // sqrt(1 + xi^2) - xi at the highest frequency (here xi = 0.5 there).
  const Decay plain = oscillator(0, 0, 0.05);
  const double omega_max = 2 / plain.undamped_critical, b = 2 * 0.5 / omega_max;
  const Decay damped = oscillator(0, b, 0.05);
  EXPECT_NEAR(damped.critical / damped.undamped_critical, std::sqrt(1.25) - 0.5, 1e-12);
}

}  // namespace
}  // namespace fissure::dem
