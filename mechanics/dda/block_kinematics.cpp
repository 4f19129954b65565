#include "mechanics/dda/block_kinematics.h"

namespace fissure::dda {

Matrix6 mass_matrix(double density, const SectionProperties& s) {
  const double Ixx = s.Ixx, Iyy = s.Iyy, Ixy = s.Ixy;
  Matrix6 m = Matrix6::Zero();
  m(0, 0) = m(1, 1) = s.area;
  m(2, 2) = Ixx + Iyy;
  m(2, 3) = m(3, 2) = -Ixy;
  m(2, 4) = m(4, 2) = Ixy;
  m(2, 5) = m(5, 2) = (Ixx - Iyy) / 2;
  m(3, 3) = Ixx;
  m(3, 5) = m(5, 3) = Ixy / 2;
  m(4, 4) = Iyy;
  m(4, 5) = m(5, 4) = Ixy / 2;
  m(5, 5) = (Ixx + Iyy) / 4;
  return density * m;
}

Eigen::Matrix3d elastic_matrix(const Material& material, PlaneMode plane) {
  double e = material.young_modulus, nu = material.poisson_ratio;
  if (plane == PlaneMode::Strain) {
    e = e / (1 - nu * nu);
    nu = nu / (1 - nu);
  }
  const double f = e / (1 - nu * nu);
  Eigen::Matrix3d c;
  c << f, f * nu, 0,  //
      f * nu, f, 0,   //
      0, 0, f * (1 - nu) / 2;
  return c;
}

}  // namespace fissure::dda
