#include "mechanics/dda/viscous_boundary.h"

#include <cmath>

#include <fmt/format.h>

#include "core/base/errors.h"
#include "core/geometry/segment_predicates.h"

namespace fissure::dda {

namespace {

/// The edge's ends and midpoint with Simpson's weights, and C = Z_n n n^T +
/// Z_s s s^T for its outward normal n and direction s.
struct EdgeQuadrature {
  Vec2 points[3];
  double weights[3];
  Eigen::Matrix2d c;
};

EdgeQuadrature quadrature(const ViscousEdge& e, const Block& b) {
  const Polygon& p = b.polygon;
  const Vec2 a = p.vertices[e.vertex], z = p.vertices[p.next(e.vertex)];
  const double length = (z - a).norm();
  const Vec2 s = (z - a) / length;
  const Vec2 n(s.y(), -s.x());  // outward: the block lies left of a -> z
  EdgeQuadrature q{{a, (a + z) / 2, z}, {length / 6, 4 * length / 6, length / 6}, {}};
  q.c = e.normal_impedance * n * n.transpose() + e.shear_impedance * s * s.transpose();
  return q;
}

}  // namespace

std::vector<ViscousEdge> find_viscous_edges(const RockMass& state,
                                            std::span<const ViscousBoundaryControls> boundaries,
                                            PlaneMode plane) {
  std::vector<ViscousEdge> edges;
  for (std::size_t k = 0; k < boundaries.size(); ++k) {
    const ViscousBoundaryControls& line = boundaries[k];
    const double tolerance = 1e-6 * (line.to - line.from).norm();
    const std::size_t before = edges.size();
    for (std::size_t b = 0; b < state.blocks.size(); ++b) {
      const Block& block = state.blocks[b];
      if (block.fixed) continue;
      const Material& m = state.materials[line.material >= 0 ? line.material : block.material];
      // P and S wave moduli of the plane mode: E's (0, 0) and (2, 2) terms.
      const Eigen::Matrix3d elastic = elastic_matrix(m, plane);
      const Polygon& p = block.polygon;
      for (int v = 0; v < static_cast<int>(p.vertices.size()); ++v)
        if (point_segment_distance(p.vertices[v], line.from, line.to) <= tolerance &&
            point_segment_distance(p.vertices[p.next(v)], line.from, line.to) <= tolerance)
          edges.push_back({static_cast<int>(b), v, std::sqrt(m.density * elastic(0, 0)),
                           std::sqrt(m.density * elastic(2, 2)), line.free_field});
    }
    FISSURE_CHECK(edges.size() > before, SceneError,
                  fmt::format("{}:{}:{}: mechanics.viscous_boundaries[{}]: found no edge of a free "
                              "block on the line from ({:g}, {:g}) to ({:g}, {:g}); expected a "
                              "line along the model's boundary that free blocks' edges lie on",
                              line.location.file, line.location.line, line.location.column, k,
                              line.from.x(), line.from.y(), line.to.x(), line.to.y()));
  }
  return edges;
}

void add_viscous_edge(const ViscousEdge& edge, const Block& block, const Vector6& v0,
                      const Vec2& reference_velocity, double dt, Matrix6& k, Vector6& rhs) {
  const EdgeQuadrature q = quadrature(edge, block);
  const Vec2& c = block.section.centroid;
  for (int i = 0; i < 3; ++i) {
    const Matrix26 t = displacement_matrix(q.points[i], c);
    const Eigen::Matrix<double, 6, 2> tc = q.weights[i] * t.transpose() * q.c;
    k.noalias() += (2 / dt) * tc * t;
    rhs.noalias() += tc * (t * v0 + reference_velocity);
  }
}

double viscous_work(const ViscousEdge& edge, const Block& block, const Vector6& end_velocity,
                    const Vector6& increment, const Vec2& reference_velocity) {
  const EdgeQuadrature q = quadrature(edge, block);
  const Vec2& c = block.section.centroid;
  double work = 0;
  for (int i = 0; i < 3; ++i) {
    const Vec2 relative = displacement_at(q.points[i], c, end_velocity) - reference_velocity;
    work -= q.weights[i] * relative.dot(q.c * displacement_at(q.points[i], c, increment));
  }
  return work;
}

}  // namespace fissure::dda
