// Damping of the blocks' elastic vibration that does not vanish with the time
// step (docs/dda.md section 4, "Vibration damping").
//
// Shi's time integration (Newmark beta = 1/2, gamma = 1) damps a mode of
// frequency w numerically, for w dt << 1 by the ratio (gamma - 1/2) w dt / 2
// = w dt / 4: exactly as stiffness-proportional (Rayleigh) damping C = b K
// with b = dt / 2 would. At steps near a block's period its elastic
// vibration is therefore damped within a few steps, but at steps far below
// it (1e-5 s and less for a 1 m block of 10 GPa, whose strain modes ring at
// ~1 kHz) it rings on almost undamped, and with Coulomb friction at its
// corners a ringing block walks: a block that friction holds on a 22.6 deg
// slope crept 1-30 mm in 2 s (benchmarks/dda_stability).
//
// The blocks' elasticity therefore carries stiffness-proportional damping
// C = b K_e (a viscous stress b E de/dt, not stored), with b topped up to
// what the ratio `zeta` at the block's lowest strain frequency w_min asks:
//   b = max(0, 2 zeta / w_min - dt / 2),
// and so do the contact springs, whose vibration (a block on its penalty
// springs) rings on in the same way at small steps and soft penalties
// (dashpot b k on a spring k, w = sqrt(k / m)).
// At steps of the order of the block's period and longer (dt >= 4 zeta /
// w_min) the integrator already damps that much and b = 0: nothing changes.
// At shorter steps the total (numerical plus viscous) damping stays at
// 2 zeta / w_min, whatever dt, so that results converge as dt -> 0. The
// higher strain modes get more (zeta w / w_min), rigid motion none.
#pragma once

#include <vector>

#include "core/state/rock_mass.h"
#include "mechanics/dda/block_kinematics.h"
#include "mechanics/dda/dda_contact.h"

namespace fissure::dda {

/// Viscous time b (s) that tops the integrator's damping of a mode of
/// frequency w (rad/s) up to the ratio zeta: max(0, 2 zeta / w - dt / 2).
double viscous_time(double w, double zeta, double dt);

/// Lowest frequency w_min (rad/s) of a block's strain unknowns (ex, ey, gxy)
/// with rigid motion held, from its mass matrix and elastic stiffness (area
/// x elasticity matrix). Rigid rotation does not change it (isotropic
/// elasticity).
double lowest_strain_frequency(const Matrix6& mass, const Eigen::Matrix3d& stiffness);

/// Viscous time b (s) of a contact's dashpots: each spring k (normal, and
/// shear while locked) carries the dashpot b k, with w = sqrt(k / m) for the
/// reduced mass m of the two blocks (the free block's mass against a fixed
/// one). `mass_j` <= 0: block j is fixed.
double contact_damping_time(double stiffness, double mass_i, double mass_j, double zeta, double dt);

/// Sets every contact's spring_factor 1 + b / dt for a step of dt.
void set_contact_damping(std::vector<DdaContact>& contacts, const RockMass& state,
                         double normal_penalty, double zeta, double dt);

}  // namespace fissure::dda
