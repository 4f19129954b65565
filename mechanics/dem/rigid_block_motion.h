// The motion law of the explicit distinct-element method for a rigid block
// (Cundall and Hart 1992; Itasca's UDEC; docs/theory.md, "Explicit DEM"):
// central differences with the velocities at half steps, damped or not
// (central_difference.h), per degree of freedom: x, y and the rotation
// about the centroid, with the moment M and the moment of inertia I in
// place of F and m.
// Stable for dt < 2 / omega_max = 2 sqrt(m / k) (undamped), the bound the
// critical time step is taken from.
#pragma once

#include <Eigen/Core>

#include "core/geometry/polygon.h"
#include "mechanics/dem/central_difference.h"

namespace fissure::dem {

/// Velocities or increments of the three degrees of freedom (x, y, rotation).
using Motion = Eigen::Vector3d;

/// The inertia of a rigid block per unit thickness.
struct RigidBody {
  double mass = 0;     ///< kg/m
  double inertia = 0;  ///< kg m^2/m, polar, about the centroid
};

/// Mass and polar moment of inertia of a polygon of uniform density.
RigidBody rigid_body(const SectionProperties& section, double density);

/// The unbalanced load on a block without its weight: contact forces,
/// applied loads, pressures (N/m), and their moment about the centroid (N).
struct BlockLoad {
  Vec2 force = Vec2::Zero();
  double moment = 0;
};

/// The half-step velocity before the first step, v^{-1/2} = v^0 - a^0 dt/2,
/// from which the first advance() gives v^{1/2} = v^0 + a^0 dt/2 (undamped;
/// a^0 from the load at the start).
Motion velocity_before_first_step(const Motion& velocity, const RigidBody& body,
                                  const BlockLoad& load, const Vec2& gravity, double dt);
/// The same with the inertia of `inertial` (density scaling, advance).
Motion velocity_before_first_step(const Motion& velocity, const RigidBody& body,
                                  const RigidBody& inertial, const BlockLoad& load,
                                  const Vec2& gravity, double dt);

/// One central-difference step: `velocity` (v^{n-1/2}) becomes v^{n+1/2};
/// returns the increment v^{n+1/2} dt of (x, y, rotation).
Motion advance(Motion& velocity, const RigidBody& body, const BlockLoad& load, const Vec2& gravity,
               double dt, const DampingControls& damping);
/// The same with the inertia of `inertial` (density scaling: a mass larger
/// than the block's, for a quasi-static solve in pseudo-time) and the
/// weight of `body`.
Motion advance(Motion& velocity, const RigidBody& body, const RigidBody& inertial,
               const BlockLoad& load, const Vec2& gravity, double dt,
               const DampingControls& damping);

/// Moves a rigid block by a step's increment: its centroid by (dx, dy),
/// its vertices by the exact rotation dtheta about the centroid (a
/// linearized rotation would grow the block by dtheta^2 / 2 a step).
void move_rigidly(Polygon& polygon, Vec2& centroid, const Motion& increment);

/// The largest stable step of a mass m on a spring k, 2 sqrt(m / k), and of
/// the rotation, 2 sqrt(I / k_rot): the caller takes the smallest over the
/// blocks and contacts, times a safety factor.
double critical_time_step(double mass, double stiffness);

}  // namespace fissure::dem
