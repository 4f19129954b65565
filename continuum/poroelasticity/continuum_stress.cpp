#include "continuum/poroelasticity/continuum_stress.h"

namespace fissure::continuum {

Vector4 total_stress(const ContinuumMesh& mesh, const ContinuumControls& c,
                     const PoroelasticMatrices& m, const PoroState& s, int t,
                     const Eigen::Vector3d& w) {
  const std::array<int, 6>& tri = mesh.triangles[t];
  const TriangleGeometry g({mesh.nodes[tri[0]], mesh.nodes[tri[1]], mesh.nodes[tri[2]]},
                           c.axisymmetric, c.linear_displacement);
  Vector12 u;
  for (int a = 0; a < 6; ++a) u.segment<2>(2 * a) = s.displacement.segment<2>(2 * tri[a]);
  const Eigen::Vector3d p(s.pressure(tri[0]), s.pressure(tri[1]), s.pressure(tri[2]));
  const Eigen::Vector3d temp(s.temperature(tri[0]), s.temperature(tri[1]), s.temperature(tri[2]));
  const Vec2 x = w(0) * g.x[0] + w(1) * g.x[1] + w(2) * g.x[2];
  const double p0 = c.initial_pressure_at(x.y()), t0 = c.initial_temperature_at(x.y());
  const Vector4 ones(1, 1, 0, 1);
  return initial_stress4(c.initial_stress) +
         (x.y() - c.reference_y) * initial_stress4(c.initial_stress_gradient) +
         m.elasticity[t] * (strain_matrix(g, w) * u) -
         (m.biot[t] * (w.dot(p) - p0) + m.thermal_stress_modulus[t] * (w.dot(temp) - t0)) * ones;
}

}  // namespace fissure::continuum
