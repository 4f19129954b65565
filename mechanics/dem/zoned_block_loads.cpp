#include "mechanics/dem/zoned_block_loads.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fissure::dem {

namespace {

constexpr double kSameDirection = 0.98480775301220802;  // cos 10 deg
constexpr double kOffLine = 0.01;                       // of the stretch's length

/// Barycentric coordinates of x in triangle (a, b, c).
Eigen::Vector3d barycentric(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& x) {
  const double area = cross(b - a, c - a);
  const double wa = cross(b - x, c - x) / area, wb = cross(c - x, a - x) / area;
  return {wa, wb, 1 - wa - wb};
}

}  // namespace

PointInZone locate_in_zones(const ZonedBlock& block, const Vec2& x) {
  const std::vector<Vec2>& pos = block.positions();
  PointInZone best;
  double best_outside = std::numeric_limits<double>::infinity();
  for (int z = 0; z < block.n_zones(); ++z) {
    const auto& t = block.zones()[z];
    const Eigen::Vector3d w = barycentric(pos[t[0]], pos[t[1]], pos[t[2]], x);
    // How far outside the zone, in shape-function units (0 inside).
    const double outside = std::max(0.0, -w.minCoeff());
    if (outside < best_outside) {
      best_outside = outside;
      best = {z, w};
      if (outside == 0) break;
    }
  }
  if (best_outside > 0) {
    best.weights = best.weights.cwiseMax(0.0);
    best.weights /= best.weights.sum();
  }
  return best;
}

Vec2 position_of(const ZonedBlock& block, const PointInZone& p) {
  const auto& t = block.zones()[p.zone];
  const std::vector<Vec2>& pos = block.positions();
  return p.weights(0) * pos[t[0]] + p.weights(1) * pos[t[1]] + p.weights(2) * pos[t[2]];
}

void add_point_force(const ZonedBlock& block, const PointInZone& p, const Vec2& force,
                     std::vector<Vec2>& nodal) {
  const auto& t = block.zones()[p.zone];
  for (int k = 0; k < 3; ++k) nodal[t[k]] += p.weights(k) * force;
}

void add_edge_pressure(const ZonedBlock& block, const EdgePressureLoad& load,
                       std::vector<Vec2>& nodal) {
  const double length = (load.b - load.a).norm();
  if (!(length > 0)) return;
  const Vec2 t = (load.b - load.a) / length;
  const std::vector<Vec2>& pos = block.positions();
  auto pressure = [&](double s) { return load.p_a + (load.p_b - load.p_a) * s / length; };
  auto shear = [&](double s) { return load.s_a + (load.s_b - load.s_a) * s / length; };
  for (const std::vector<int>& loop : block.boundary()) {
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const int n0 = loop[k], n1 = loop[(k + 1) % loop.size()];
      const Vec2 &x0 = pos[n0], &x1 = pos[n1];
      const Vec2 edge = x1 - x0;
      const double edge_length = edge.norm();
      if (!(edge_length > 0)) continue;
      const Vec2 normal(edge.y() / edge_length, -edge.x() / edge_length);  // outward
      if (normal.dot(load.normal) < kSameDirection) continue;
      if (std::abs(cross(t, x0 - load.a)) > kOffLine * length ||
          std::abs(cross(t, x1 - load.a)) > kOffLine * length)
        continue;
      // The edge's stretch under the load, in the load's coordinate s.
      const double s0 = (x0 - load.a).dot(t), s1 = (x1 - load.a).dot(t);
      const double lo = std::max(std::min(s0, s1), 0.0), hi = std::min(std::max(s0, s1), length);
      if (!(hi > lo)) continue;
      // N_1 = (s - s0) / (s1 - s0) along the edge; p N is quadratic in s.
      auto n1_at = [&](double s) { return (s - s0) / (s1 - s0); };
      const double mid = 0.5 * (lo + hi), ds = (hi - lo) * edge_length / std::abs(s1 - s0);
      auto integral = [&](auto value, auto shape) {
        return ds / 6 *
               (value(lo) * shape(lo) + 4 * value(mid) * shape(mid) + value(hi) * shape(hi));
      };
      const double f1 = integral(pressure, n1_at);
      const double f0 = integral(pressure, [&](double s) { return 1 - n1_at(s); });
      nodal[n0] -= f0 * normal;
      nodal[n1] -= f1 * normal;
      if (load.has_shear()) {  // +int s t N ds, alike
        const double g1 = integral(shear, n1_at);
        const double g0 = integral(shear, [&](double s) { return 1 - n1_at(s); });
        nodal[n0] += g0 * t;
        nodal[n1] += g1 * t;
      }
    }
  }
}

}  // namespace fissure::dem
