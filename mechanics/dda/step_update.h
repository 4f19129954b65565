// End-of-step update of an accepted DDA step (theory.md 1.3, 1.8).
//  * Velocity (Newmark beta = 1/2, gamma = 1): v1 = 2 d / dt - v0, where v0 is
//    the carried-over start velocity k01 * v. The state keeps the physical v1.
//  * Geometry: x <- x + T(x) d with the rigid rotation taken exactly,
//    (-r Y, r X) -> ((cos r - 1) X - sin r Y, sin r X + (cos r - 1) Y), so that
//    a rotating block keeps its size; the linear update scales radii by
//    sqrt(1 + r^2) per step ("block inflation").
//  * Stress: sigma <- sigma + E (eps(d) - d_eps*), d_eps* the step's thermal
//    strain (thermal_strain.h; theory.md 4.3), then rotated with the block,
//    sigma <- R sigma R^T, so that stress stays attached to the material.
#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "core/state/rock_mass.h"
#include "mechanics/dda/block_kinematics.h"

namespace fissure::dda {

/// The increment d of `block` applied to a point x (exact or linear rotation).
Vec2 moved_point(const Vec2& x, const Vec2& centroid, const Vector6& d, bool exact_rotation);

/// Applies the increment to one block: velocity, vertices, stress, strain
/// (the total strain; the stress takes the elastic part, without the step's
/// thermal strain `thermal`).
void update_block(Block& block, const Vector6& d, double dt, double velocity_carry_over,
                  const Eigen::Matrix3d& elastic, bool exact_rotation,
                  const Eigen::Vector3d* thermal = nullptr);

/// The free block whose area the increments' strain shrinks most, and the
/// share of its area it keeps, det(I + strain) = (1 + ex)(1 + ey) - (gxy/2)^2
/// (the rotation keeps the area); (-1, 1) without free blocks.
std::pair<int, double> smallest_area_ratio(const RockMass& state,
                                           const std::vector<Vector6>& increments);

/// Largest vertex displacement of the increment over all blocks (m).
double max_vertex_displacement(const RockMass& state, const std::vector<Vector6>& increments);

}  // namespace fissure::dda
