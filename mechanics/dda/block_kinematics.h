// The DDA displacement function and the per-block matrices that follow from
// it (theory.md 1.1, 1.3). Unknowns per block: D = (u0, v0, r0, ex, ey, gxy),
// increments over the step, about the block centroid c:
//   u = u0 - r0 Y + ex X + gxy Y/2,   v = v0 + r0 X + ey Y + gxy X/2,
// with X = x - cx, Y = y - cy.
#pragma once

#include <Eigen/Core>

#include "core/geometry/polygon.h"
#include "core/state/rock_mass.h"
#include "mechanics/dda/dda_settings.h"

namespace fissure::dda {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Matrix26 = Eigen::Matrix<double, 2, 6>;

/// T(x): displacement at x = T(x) D.
inline Matrix26 displacement_matrix(const Vec2& x, const Vec2& centroid) {
  const double X = x.x() - centroid.x(), Y = x.y() - centroid.y();
  Matrix26 t;
  t << 1, 0, -Y, X, 0, Y / 2,  //
      0, 1, X, 0, Y, X / 2;
  return t;
}

/// T(x)^T w, without forming T.
inline Vector6 displacement_matrix_transpose_times(const Vec2& x, const Vec2& centroid,
                                                   const Vec2& w) {
  const double X = x.x() - centroid.x(), Y = x.y() - centroid.y();
  Vector6 r;
  r << w.x(), w.y(), -Y * w.x() + X * w.y(), X * w.x(), Y * w.y(), (Y * w.x() + X * w.y()) / 2;
  return r;
}

/// T(x) D, without forming T.
inline Vec2 displacement_at(const Vec2& x, const Vec2& centroid, const Vector6& d) {
  const double X = x.x() - centroid.x(), Y = x.y() - centroid.y();
  return Vec2(d(0) - Y * d(2) + X * d(3) + Y * d(5) / 2, d(1) + X * d(2) + Y * d(4) + X * d(5) / 2);
}

/// Consistent mass matrix rho * integral(T^T T) over the block (theory.md 1.3).
Matrix6 mass_matrix(double density, const SectionProperties& section);

/// Kinetic energy v^T M v / 2 of block b moving with the six velocities v,
/// M at its current density (the energy ledger, ejected blocks).
inline double kinetic_energy(const Block& b, double initial_density, const Vector6& v) {
  return 0.5 * v.dot(mass_matrix(current_density(b, initial_density), b.section) * v);
}

/// Elasticity matrix of (ex, ey, gxy) -> (sxx, syy, sxy); plane strain by Shi's
/// substitution E -> E/(1-nu^2), nu -> nu/(1-nu).
Eigen::Matrix3d elastic_matrix(const Material& material, PlaneMode plane);

}  // namespace fissure::dda
