// The Taylor-Hood triangle (theory.md 5.2): quadratic displacement (6 nodes,
// 12 unknowns), linear pressure and temperature (3 vertices). P2/P1 meets
// the inf-sup condition of the undrained (S, dt H -> 0) u-p saddle point, so
// the first steps after a load show no pressure oscillation (unlike
// equal-order P1/P1; docs/continuum.md 3). Plane strain, straight sides:
// the Jacobian is constant and the 3-point rule (degree 2) integrates every
// matrix below exactly.
#pragma once

#include <array>

#include <Eigen/Core>

#include "core/geometry/vec2.h"

namespace fissure::continuum {

using Matrix12 = Eigen::Matrix<double, 12, 12>;
using Matrix12x3 = Eigen::Matrix<double, 12, 3>;
using Vector12 = Eigen::Matrix<double, 12, 1>;
using Matrix3x12 = Eigen::Matrix<double, 3, 12>;

/// A triangle's geometry: its vertices, area and the gradients of the
/// barycentric coordinates (constant).
struct TriangleGeometry {
  std::array<Vec2, 3> x;
  double area = 0;
  std::array<Vec2, 3> grad;  ///< grad L_i
  explicit TriangleGeometry(const std::array<Vec2, 3>& vertices);
};

/// The P2 shape functions at barycentric point L (vertices, then the
/// midpoints of edges 0-1, 1-2, 2-0).
Eigen::Matrix<double, 6, 1> p2_values(const Eigen::Vector3d& L);
/// The strain matrix B (exx, eyy, gxy rows; unknowns ux0, uy0, ux1, ...)
/// at barycentric point L.
Matrix3x12 strain_matrix(const TriangleGeometry& g, const Eigen::Vector3d& L);
/// The gradients of the P1 shape functions (columns: vertices).
Eigen::Matrix<double, 2, 3> p1_gradients(const TriangleGeometry& g);

/// The element matrices of one triangle with its material (theory.md 5.2).
struct ElementMatrices {
  Matrix12 stiffness;    ///< K = int B^T D B
  Matrix12 volumetric;   ///< int B^T m m^T B (the undrained split's stiffness, times alpha^2 M)
  Matrix12x3 coupling;   ///< Q = int B^T m N_p (times alpha)
  Matrix12x3 thermal;    ///< K_T = int B^T m N_T (times 3 K alpha_T)
  Eigen::Matrix3d mass;  ///< int N_p^T N_p (P1)
  Eigen::Matrix3d permeability;  ///< int grad N^T k grad N
  Eigen::Matrix3d laplacian;     ///< int grad N^T grad N
  /// int N_u per P2 node: 0 at the vertices, A/3 at the midpoints (the
  /// body force's distribution).
  Eigen::Matrix<double, 6, 1> shape_integral;
};

/// Plane-strain elasticity D (tension positive) of E, nu.
Eigen::Matrix3d elasticity_matrix(double young_modulus, double poisson_ratio);

/// The element matrices; `permeability` is (kxx, kyy, kxy); the stress-like
/// terms are per unit alpha and 3 K alpha_T.
ElementMatrices element_matrices(const TriangleGeometry& g, const Eigen::Matrix3d& d,
                                 const Eigen::Vector3d& permeability);

/// int B^T sigma(y) over the triangle for a stress linear in y:
/// sigma(x) = s0 + (y - y0) s1 (initial geostatic stress).
Vector12 stress_vector(const TriangleGeometry& g, const Eigen::Vector3d& s0,
                       const Eigen::Vector3d& s1, double y0);

}  // namespace fissure::continuum
