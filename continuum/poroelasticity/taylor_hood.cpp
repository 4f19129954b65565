#include "continuum/poroelasticity/taylor_hood.h"

namespace fissure::continuum {

namespace {

/// The 3-point rule of degree 2 (Strang and Fix): barycentric points
/// (2/3, 1/6, 1/6) and permutations, weights A/3.
const std::array<Eigen::Vector3d, 3> kPoints = {Eigen::Vector3d(2. / 3, 1. / 6, 1. / 6),
                                                Eigen::Vector3d(1. / 6, 2. / 3, 1. / 6),
                                                Eigen::Vector3d(1. / 6, 1. / 6, 2. / 3)};

/// Gradients of the 6 P2 shape functions at L (columns).
Eigen::Matrix<double, 2, 6> p2_gradients(const TriangleGeometry& g, const Eigen::Vector3d& L) {
  Eigen::Matrix<double, 2, 6> d;
  for (int i = 0; i < 3; ++i) d.col(i) = (4 * L(i) - 1) * g.grad[i];
  for (int k = 0; k < 3; ++k) {
    const int i = k, j = (k + 1) % 3;
    d.col(3 + k) = 4 * (L(j) * g.grad[i] + L(i) * g.grad[j]);
  }
  return d;
}

}  // namespace

TriangleGeometry::TriangleGeometry(const std::array<Vec2, 3>& vertices) : x(vertices) {
  area = 0.5 * cross(x[1] - x[0], x[2] - x[0]);
  // grad L_i = perp(x_k - x_j) / 2A with (i, j, k) cyclic: the outward
  // normal of the opposite edge, scaled.
  for (int i = 0; i < 3; ++i) {
    const Vec2 e = x[(i + 2) % 3] - x[(i + 1) % 3];
    grad[i] = Vec2(-e.y(), e.x()) / (2 * area);
  }
}

Eigen::Matrix<double, 6, 1> p2_values(const Eigen::Vector3d& L) {
  Eigen::Matrix<double, 6, 1> n;
  for (int i = 0; i < 3; ++i) n(i) = L(i) * (2 * L(i) - 1);
  for (int k = 0; k < 3; ++k) n(3 + k) = 4 * L(k) * L((k + 1) % 3);
  return n;
}

Matrix3x12 strain_matrix(const TriangleGeometry& g, const Eigen::Vector3d& L) {
  const Eigen::Matrix<double, 2, 6> d = p2_gradients(g, L);
  Matrix3x12 b = Matrix3x12::Zero();
  for (int a = 0; a < 6; ++a) {
    b(0, 2 * a) = d(0, a);
    b(1, 2 * a + 1) = d(1, a);
    b(2, 2 * a) = d(1, a);
    b(2, 2 * a + 1) = d(0, a);
  }
  return b;
}

Eigen::Matrix<double, 2, 3> p1_gradients(const TriangleGeometry& g) {
  Eigen::Matrix<double, 2, 3> d;
  for (int i = 0; i < 3; ++i) d.col(i) = g.grad[i];
  return d;
}

Eigen::Matrix3d elasticity_matrix(double young_modulus, double poisson_ratio) {
  const double nu = poisson_ratio;
  const double f = young_modulus / ((1 + nu) * (1 - 2 * nu));
  Eigen::Matrix3d d;
  d << f * (1 - nu), f * nu, 0, f * nu, f * (1 - nu), 0, 0, 0, f * (1 - 2 * nu) / 2;
  return d;
}

ElementMatrices element_matrices(const TriangleGeometry& g, const Eigen::Matrix3d& d,
                                 const Eigen::Vector3d& permeability) {
  ElementMatrices e;
  e.stiffness.setZero();
  e.volumetric.setZero();
  e.coupling.setZero();
  e.mass.setZero();
  const Eigen::Vector3d m(1, 1, 0);
  const double w = g.area / 3;
  for (const Eigen::Vector3d& L : kPoints) {
    const Matrix3x12 b = strain_matrix(g, L);
    e.stiffness += w * b.transpose() * d * b;
    e.volumetric += w * (b.transpose() * m) * (m.transpose() * b);
    e.coupling += w * (b.transpose() * m) * L.transpose();
    e.mass += w * L * L.transpose();
  }
  e.thermal = e.coupling;  // the same integral, scaled by 3 K alpha_T instead of alpha
  const Eigen::Matrix<double, 2, 3> dn = p1_gradients(g);
  Eigen::Matrix2d k;
  k << permeability(0), permeability(2), permeability(2), permeability(1);
  e.permeability = g.area * dn.transpose() * k * dn;
  e.laplacian = g.area * dn.transpose() * dn;
  e.shape_integral << 0, 0, 0, g.area / 3, g.area / 3, g.area / 3;
  return e;
}

Vector12 stress_vector(const TriangleGeometry& g, const Eigen::Vector3d& s0,
                       const Eigen::Vector3d& s1, double y0) {
  Vector12 f = Vector12::Zero();
  for (const Eigen::Vector3d& L : kPoints) {
    const double y = L(0) * g.x[0].y() + L(1) * g.x[1].y() + L(2) * g.x[2].y();
    f += g.area / 3 * strain_matrix(g, L).transpose() * (s0 + (y - y0) * s1);
  }
  return f;
}

}  // namespace fissure::continuum
