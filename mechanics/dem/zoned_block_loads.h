// What the DEM process passes to and takes from a deformable (zoned) block
// besides its contacts (docs/dem.md section 9): the flow's pressure on a
// stretch of its boundary as consistent nodal forces, and material points
// (monitors, point loads) that move with its zones by their linear shape
// functions.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "mechanics/dem/zoned_block.h"
#include "rockmass/fields/pressure_loads.h"

namespace fissure::dem {

/// A point in a zone: the zone and the point's barycentric coordinates
/// (the zone's shape functions N_a there).
struct PointInZone {
  int zone = -1;
  Eigen::Vector3d weights = Eigen::Vector3d::Zero();
};

/// The zone of `block` that holds `x` at the nodes' current positions (a
/// point on the boundary or just outside it: the nearest zone, its weights
/// clamped to the zone).
PointInZone locate_in_zones(const ZonedBlock& block, const Vec2& x);
/// The point's current position.
Vec2 position_of(const ZonedBlock& block, const PointInZone& p);
/// A force at the point shared by its zone's nodes with their shape
/// functions (the same work for any motion the zone can make).
void add_point_force(const ZonedBlock& block, const PointInZone& p, const Vec2& force,
                     std::vector<Vec2>& nodal);
/// A pressure, linear from p_a at a to p_b at b, on the boundary edges of
/// `block` that lie along a -> b with the load's outward normal (within
/// 10 degrees and 1 % of the stretch's length off its line): each edge's
/// nodes take int p N_a ds (Simpson's rule over the overlap, exact for the
/// quadratic) along the edge's own outward normal.
void add_edge_pressure(const ZonedBlock& block, const EdgePressureLoad& load,
                       std::vector<Vec2>& nodal);

}  // namespace fissure::dem
