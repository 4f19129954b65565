// What a DEM contact passes between its two rigid blocks in a step (Cundall
// and Hart 1992; docs/theory.md, "Explicit DEM"): the relative velocity of
// block j against block i at the contact point C,
//   V = v_j + omega_j x (C - x_j) - v_i - omega_i x (C - x_i),
// gives the step's normal and shear displacement increments du_n = V.n dt
// (opening positive, n from i to j) and du_s = V.t dt (t = n turned by +90
// degrees); the joint law turns them into the stresses sigma_n (compression
// positive) and tau, and the contact's length L into the forces
//   on i: (-sigma_n n + tau t) L,   on j: the opposite,
// both acting at C (their moments about each block's centroid).
#pragma once

#include "core/geometry/vec2.h"
#include "mechanics/dem/rigid_block_motion.h"

namespace fissure::dem {

/// The contact's frame: n from block i to block j, t = n turned by +90 deg.
inline Vec2 tangent_of(const Vec2& normal) {
  return Vec2(-normal.y(), normal.x());
}

struct DisplacementIncrement {
  double normal = 0;  ///< du_n, m, opening positive
  double shear = 0;   ///< du_s, m, along t
};

/// The velocity of a rigid block's material point at p (x, y, rotation).
Vec2 point_velocity(const Motion& velocity, const Vec2& centroid, const Vec2& p);

/// The increments over dt from the velocities of the two walls at the
/// contact point (a rigid block's point_velocity, a zoned block's node or
/// the interpolation along its edge).
DisplacementIncrement relative_displacement(const Vec2& normal, const Vec2& velocity_i,
                                            const Vec2& velocity_j, double dt);
/// The increments over dt from the blocks' half-step velocities (x, y,
/// rotation) and centroids.
DisplacementIncrement relative_displacement(const Vec2& point, const Vec2& normal,
                                            const Motion& velocity_i, const Vec2& centroid_i,
                                            const Motion& velocity_j, const Vec2& centroid_j,
                                            double dt);

/// The load that stresses (sigma_n compression positive, tau) over a
/// contact of length L put on block i (block j takes the opposite force, its
/// moment about its own centroid).
BlockLoad load_on_i(const Vec2& point, const Vec2& normal, double normal_stress,
                    double shear_stress, double length, const Vec2& centroid_i);
BlockLoad load_on_j(const Vec2& point, const Vec2& normal, double normal_stress,
                    double shear_stress, double length, const Vec2& centroid_j);

}  // namespace fissure::dem
