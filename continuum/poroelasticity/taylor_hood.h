// The Taylor-Hood triangle (theory.md 5.2): quadratic displacement (6 nodes,
// 12 unknowns), linear pressure and temperature (3 vertices). P2/P1 meets
// the inf-sup condition of the undrained (S, dt H -> 0) u-p saddle point, so
// the first steps after a load show no pressure oscillation (unlike
// equal-order P1/P1; docs/continuum.md 2).
//
// Plane strain, or axisymmetric about the y axis (x = r >= 0, y = z): the
// strain has four components (exx, eyy, gxy, and ezz = 0 in plane strain or
// the hoop strain u_r / r), and integrals carry the weight 1 (per metre of
// thickness) or 2 pi r (the whole ring). Straight sides: the Jacobian is
// constant; the 6-point rule of degree 4 integrates every matrix exactly in
// plane strain and with the linear weight r.
#pragma once

#include <array>

#include <Eigen/Core>

#include "core/geometry/vec2.h"

namespace fissure::continuum {

using Matrix12 = Eigen::Matrix<double, 12, 12>;
using Matrix12x3 = Eigen::Matrix<double, 12, 3>;
using Vector12 = Eigen::Matrix<double, 12, 1>;
using Matrix4x12 = Eigen::Matrix<double, 4, 12>;
using Vector4 = Eigen::Vector4d;
using Matrix4 = Eigen::Matrix4d;

/// A triangle's geometry: its vertices, area and the gradients of the
/// barycentric coordinates (constant).
struct TriangleGeometry {
  std::array<Vec2, 3> x;
  double area = 0;
  std::array<Vec2, 3> grad;  ///< grad L_i
  bool axisymmetric = false;
  /// Equal-order P1/P1 (continuum.elements: p1p1): linear displacement on
  /// the vertices, the midpoints unused. Unstable for the undrained saddle
  /// point; kept to show its first-step oscillation (docs/continuum.md 2).
  bool linear_displacement = false;
  TriangleGeometry(const std::array<Vec2, 3>& vertices, bool axisymmetric,
                   bool linear_displacement = false);
  Vec2 point(const Eigen::Vector3d& L) const { return L(0) * x[0] + L(1) * x[1] + L(2) * x[2]; }
  /// The integration weight at L: 1, or 2 pi r.
  double weight(const Eigen::Vector3d& L) const;
};

/// The quadrature rule: barycentric points and weights (summing to 1).
struct QuadraturePoint {
  Eigen::Vector3d L;
  double w;
};
extern const std::array<QuadraturePoint, 6> kQuadrature;

/// The displacement's shape functions at barycentric point L (vertices,
/// then the midpoints of edges 0-1, 1-2, 2-0): P2, or P1 with zeros at the
/// midpoints.
Eigen::Matrix<double, 6, 1> displacement_values(const TriangleGeometry& g,
                                                const Eigen::Vector3d& L);
/// The strain matrix B (exx, eyy, gxy, ezz-or-hoop rows; unknowns ux0,
/// uy0, ux1, ...) at barycentric point L.
Matrix4x12 strain_matrix(const TriangleGeometry& g, const Eigen::Vector3d& L);
/// The gradients of the P1 shape functions (columns: vertices).
Eigen::Matrix<double, 2, 3> p1_gradients(const TriangleGeometry& g);
/// m: the strains that change volume (1, 1, 0, 0 in plane strain; 1, 1, 0,
/// 1 axisymmetric).
Vector4 volumetric_vector(bool axisymmetric);

/// The element matrices of one triangle with its material (theory.md 5.2).
struct ElementMatrices {
  Matrix12 stiffness;         ///< K = int B^T D B
  Matrix12 volumetric;        ///< int B^T m m^T B (the undrained split, times alpha^2 M)
  Matrix12x3 coupling;        ///< int B^T m N_p (times alpha, or 3 K alpha_T)
  Eigen::Matrix3d mass;       ///< int N^T N (P1)
  Eigen::Matrix3d laplacian;  ///< int grad N^T grad N
  Eigen::Matrix<double, 6, 1> shape_integral;  ///< int N_u per P2 node (body forces)
  double measure = 0;                          ///< int 1: the area, or the ring's volume
};

/// The 3D isotropic elasticity D (tension positive) of E, nu on the four
/// strains (exx, eyy, gxy, ezz).
Matrix4 elasticity_matrix(double young_modulus, double poisson_ratio);

/// int 1 over the triangle by the quadrature: its area, or its ring's
/// volume.
double triangle_measure(const TriangleGeometry& g);

/// The element matrices (the flow's mobility, which follows the
/// permeability, is poroelastic_matrices.cpp's assemble_flow_terms).
ElementMatrices element_matrices(const TriangleGeometry& g, const Matrix4& d);

/// int B^T sigma(y) over the triangle for a stress linear in y:
/// sigma(x) = s0 + (y - y0) s1 (initial geostatic stress; sxx, syy, sxy,
/// szz).
Vector12 stress_vector(const TriangleGeometry& g, const Vector4& s0, const Vector4& s1, double y0);

}  // namespace fissure::continuum
