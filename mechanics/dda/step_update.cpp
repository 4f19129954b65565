#include "mechanics/dda/step_update.h"

#include <cmath>

namespace fissure::dda {

Vec2 moved_point(const Vec2& x, const Vec2& c, const Vector6& d, bool exact_rotation) {
  if (!exact_rotation) return x + displacement_at(x, c, d);
  const double X = x.x() - c.x(), Y = x.y() - c.y();
  const double cr = std::cos(d(2)) - 1, sr = std::sin(d(2));
  return Vec2(x.x() + d(0) + cr * X - sr * Y + d(3) * X + d(5) * Y / 2,
              x.y() + d(1) + sr * X + cr * Y + d(4) * Y + d(5) * X / 2);
}

void update_block(Block& b, const Vector6& d, double dt, double k01, const Eigen::Matrix3d& elastic,
                  bool exact_rotation, const Eigen::Vector3d* thermal) {
  b.velocity = (2 / dt) * d - k01 * b.velocity;

  const Vec2 c = b.section.centroid;
  for (Vec2& x : b.polygon.vertices) x = moved_point(x, c, d, exact_rotation);
  b.section = section_properties(b.polygon);

  const Eigen::Vector3d eps = d.segment<3>(3);
  b.strain += eps;
  if (thermal)
    b.stress += elastic * (eps - *thermal);
  else
    b.stress += elastic * eps;
  b.rotation += d(2);
  if (exact_rotation && d(2) != 0) {
    const double cs = std::cos(d(2)), sn = std::sin(d(2));
    const double sxx = b.stress(0), syy = b.stress(1), sxy = b.stress(2);
    b.stress(0) = cs * cs * sxx + sn * sn * syy - 2 * cs * sn * sxy;
    b.stress(1) = sn * sn * sxx + cs * cs * syy + 2 * cs * sn * sxy;
    b.stress(2) = cs * sn * (sxx - syy) + (cs * cs - sn * sn) * sxy;
  }
}

std::pair<int, double> smallest_area_ratio(const RockMass& state,
                                           const std::vector<Vector6>& increments) {
  std::pair<int, double> worst{-1, 1.0};
  for (std::size_t b = 0; b < state.blocks.size(); ++b) {
    if (state.blocks[b].fixed) continue;
    const Vector6& d = increments[b];
    const double ratio = (1 + d(3)) * (1 + d(4)) - 0.25 * d(5) * d(5);
    if (ratio < worst.second) worst = {static_cast<int>(b), ratio};
  }
  return worst;
}

double max_vertex_displacement(const RockMass& state, const std::vector<Vector6>& increments) {
  double dmax = 0;
  for (std::size_t b = 0; b < state.blocks.size(); ++b) {
    const Block& block = state.blocks[b];
    if (block.fixed) continue;
    for (const Vec2& x : block.polygon.vertices)
      dmax = std::max(dmax, displacement_at(x, block.section.centroid, increments[b]).norm());
  }
  return dmax;
}

}  // namespace fissure::dda
