#include "continuum/poroelasticity/taylor_hood.h"

#include <numbers>

namespace fissure::continuum {

// Dunavant's 6-point rule of degree 4: (a, a, 1 - 2a) and permutations.
const std::array<QuadraturePoint, 6> kQuadrature = [] {
  std::array<QuadraturePoint, 6> q;
  const double a[2] = {0.445948490915965, 0.091576213509771};
  const double w[2] = {0.223381589678011, 0.109951743655322};
  for (int k = 0; k < 2; ++k) {
    const double b = 1 - 2 * a[k];
    q[3 * k] = {Eigen::Vector3d(b, a[k], a[k]), w[k]};
    q[3 * k + 1] = {Eigen::Vector3d(a[k], b, a[k]), w[k]};
    q[3 * k + 2] = {Eigen::Vector3d(a[k], a[k], b), w[k]};
  }
  return q;
}();

namespace {

/// Gradients of the 6 displacement shape functions at L (columns).
Eigen::Matrix<double, 2, 6> p2_gradients(const TriangleGeometry& g, const Eigen::Vector3d& L) {
  Eigen::Matrix<double, 2, 6> d;
  if (g.linear_displacement) {
    d.setZero();
    for (int i = 0; i < 3; ++i) d.col(i) = g.grad[i];
    return d;
  }
  for (int i = 0; i < 3; ++i) d.col(i) = (4 * L(i) - 1) * g.grad[i];
  for (int k = 0; k < 3; ++k) {
    const int i = k, j = (k + 1) % 3;
    d.col(3 + k) = 4 * (L(j) * g.grad[i] + L(i) * g.grad[j]);
  }
  return d;
}

}  // namespace

TriangleGeometry::TriangleGeometry(const std::array<Vec2, 3>& vertices, bool axi, bool linear)
    : x(vertices), axisymmetric(axi), linear_displacement(linear) {
  area = 0.5 * cross(x[1] - x[0], x[2] - x[0]);
  // grad L_i = perp(x_k - x_j) / 2A with (i, j, k) cyclic: the inward
  // normal of the opposite edge, scaled.
  for (int i = 0; i < 3; ++i) {
    const Vec2 e = x[(i + 2) % 3] - x[(i + 1) % 3];
    grad[i] = Vec2(-e.y(), e.x()) / (2 * area);
  }
}

double TriangleGeometry::weight(const Eigen::Vector3d& L) const {
  return axisymmetric ? 2 * std::numbers::pi * point(L).x() : 1.0;
}

Eigen::Matrix<double, 6, 1> displacement_values(const TriangleGeometry& g,
                                                const Eigen::Vector3d& L) {
  Eigen::Matrix<double, 6, 1> n;
  if (g.linear_displacement) {
    n << L(0), L(1), L(2), 0, 0, 0;
    return n;
  }
  for (int i = 0; i < 3; ++i) n(i) = L(i) * (2 * L(i) - 1);
  for (int k = 0; k < 3; ++k) n(3 + k) = 4 * L(k) * L((k + 1) % 3);
  return n;
}

Matrix4x12 strain_matrix(const TriangleGeometry& g, const Eigen::Vector3d& L) {
  const Eigen::Matrix<double, 2, 6> d = p2_gradients(g, L);
  Matrix4x12 b = Matrix4x12::Zero();
  for (int a = 0; a < 6; ++a) {
    b(0, 2 * a) = d(0, a);
    b(1, 2 * a + 1) = d(1, a);
    b(2, 2 * a) = d(1, a);
    b(2, 2 * a + 1) = d(0, a);
  }
  if (g.axisymmetric) {  // the hoop strain u_r / r (r > 0 at every quadrature point)
    const Eigen::Matrix<double, 6, 1> n = displacement_values(g, L);
    const double r = g.point(L).x();
    for (int a = 0; a < 6; ++a) b(3, 2 * a) = n(a) / r;
  }
  return b;
}

Eigen::Matrix<double, 2, 3> p1_gradients(const TriangleGeometry& g) {
  Eigen::Matrix<double, 2, 3> d;
  for (int i = 0; i < 3; ++i) d.col(i) = g.grad[i];
  return d;
}

Vector4 volumetric_vector(bool axisymmetric) {
  return Vector4(1, 1, 0, axisymmetric ? 1 : 0);
}

Matrix4 elasticity_matrix(double young_modulus, double poisson_ratio) {
  const double nu = poisson_ratio;
  const double f = young_modulus / ((1 + nu) * (1 - 2 * nu));
  Matrix4 d = Matrix4::Zero();
  for (int i : {0, 1, 3})
    for (int j : {0, 1, 3}) d(i, j) = f * (i == j ? 1 - nu : nu);
  d(2, 2) = f * (1 - 2 * nu) / 2;
  return d;
}

double triangle_measure(const TriangleGeometry& g) {
  double measure = 0;
  for (const QuadraturePoint& q : kQuadrature) measure += q.w * g.area * g.weight(q.L);
  return measure;
}

ElementMatrices element_matrices(const TriangleGeometry& g, const Matrix4& d) {
  ElementMatrices e;
  e.stiffness.setZero();
  e.volumetric.setZero();
  e.coupling.setZero();
  e.mass.setZero();
  e.shape_integral.setZero();
  const Vector4 m = volumetric_vector(g.axisymmetric);
  for (const QuadraturePoint& q : kQuadrature) {
    const double w = q.w * g.area * g.weight(q.L);
    const Matrix4x12 b = strain_matrix(g, q.L);
    const Vector12 bm = b.transpose() * m;
    e.stiffness += w * b.transpose() * d * b;
    e.volumetric += w * bm * bm.transpose();
    e.coupling += w * bm * q.L.transpose();
    e.mass += w * q.L * q.L.transpose();
    e.shape_integral += w * displacement_values(g, q.L);
  }
  e.measure = triangle_measure(g);
  const Eigen::Matrix<double, 2, 3> dn = p1_gradients(g);
  e.laplacian = e.measure * dn.transpose() * dn;
  return e;
}

Vector12 stress_vector(const TriangleGeometry& g, const Vector4& s0, const Vector4& s1, double y0) {
  Vector12 f = Vector12::Zero();
  for (const QuadraturePoint& q : kQuadrature) {
    const double y = g.point(q.L).y();
    f += q.w * g.area * g.weight(q.L) * strain_matrix(g, q.L).transpose() * (s0 + (y - y0) * s1);
  }
  return f;
}

}  // namespace fissure::continuum
