#include "continuum/poroelasticity/stress_permeability.h"

#include <algorithm>

#include "continuum/poroelasticity/continuum_stress.h"

namespace fissure::continuum {

double update_stress_permeability(const ContinuumMesh& mesh, const ContinuumControls& c,
                                  const PoroState& s, PoroelasticMatrices& m) {
  const Eigen::Vector3d centroid = Eigen::Vector3d::Constant(1.0 / 3);
  double change = 0;
  for (int t = 0; t < mesh.n_triangles(); ++t) {
    const PoroMaterial& material = c.materials[mesh.triangle_material[t]];
    if (!material.permeability_law) continue;
    const std::array<int, 6>& tri = mesh.triangles[t];
    const Vector4 sigma = total_stress(mesh, c, m, s, t, centroid);
    const double p =
        centroid.dot(Eigen::Vector3d(s.pressure(tri[0]), s.pressure(tri[1]), s.pressure(tri[2])));
    const Eigen::Vector3d k =
        material.permeability_law->at(mean_effective_stress(sigma(0), sigma(1), p));
    Eigen::Vector3d& old = m.permeability[t];
    change = std::max(change, (k - old).lpNorm<Eigen::Infinity>() / k.lpNorm<Eigen::Infinity>());
    old = k;
  }
  return change;
}

}  // namespace fissure::continuum
