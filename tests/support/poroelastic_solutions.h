// Closed-form poroelastic references for the u-p verification tests:
// Terzaghi's 1D consolidation (verification.md (j)), Mandel's problem
// (verification.md (k)) and Booker and Savvidou's point heat source
// (verification.md (l)). Plain series, no solver code, so that a mistake in
// the FEM cannot hide in the reference. SI units, p positive in compression,
// stresses tension-positive (theory.md).
#pragma once

#include <string>
#include <vector>

namespace fissure::test {

/// Terzaghi 1D consolidation (verification.md (j)): a column of height H, drained
/// loaded top at z = 0, rigid impermeable base, lateral rollers, load sigma from t = 0+
/// (z measured DOWN from the drained top, z = H at the impermeable base).
struct Terzaghi {
  double height = 10;  // H, m
  double load = 1e6;   // sigma, Pa (compressive magnitude)
  double young_modulus = 1e9, poisson_ratio = 0.25, biot = 1, biot_modulus = 1e10;  // M, Pa
  double mobility = 1e-12;  // k / mu, m^2/(Pa s)

  double constrained_modulus() const;        // K_v = lambda + 2G
  double consolidation_coefficient() const;  // c_v
  double initial_pressure() const;           // p0
  double time_factor(double t) const;        // T_v = c_v t / H^2
  /// Series with >= 200 terms, then until the tail is below 1e-14 p0 (at most 100000 terms).
  /// For t <= 0 the t -> 0+ limit: p0, and 0 on the drained top.
  double pressure(double z, double t) const;
  double degree_of_consolidation(double t) const;  // U, 0 for t <= 0
  double settlement(double t) const;               // w = w0 + (winf - w0) U, positive downwards
};

/// Mandel's problem (verification.md (k)); quarter model 0 <= x <= a, 0 <= y <= b.
/// The series use the roots up to alpha_n^2 c t / a^2 = 45 (at least 400 roots, at most
/// 100000): truncation below 1e-14 relative for c t / a^2 >= 1e-8. For t <= 0 the
/// undrained closed forms (the t -> 0+ limit).
struct Mandel {
  double a = 1, young_modulus = 1e9, poisson_ratio = 0.2, biot = 1, biot_modulus = 2e9,
         mobility = 1e-10, force = 1e6;  // F, N/m (half the total 2F)

  // Derived: bulk, shear, undrained bulk, Skempton B, undrained Poisson ratio nu_u, c.
  double bulk_modulus() const;
  double shear_modulus() const;
  double undrained_bulk_modulus() const;  // K_u = K + alpha^2 M
  double undrained_poisson_ratio() const;
  double skempton() const;
  double consolidation_coefficient() const;
  double initial_pressure() const;  // p0 = F B (1 + nu_u) / (3 a)
  /// The first n roots of tan(x) = (1 - nu)/(nu_u - nu) x, x_n in ((n-1) pi, (n - 1/2) pi),
  /// by bisection to adjacent doubles.
  std::vector<double> roots(int n) const;
  double pressure(double x, double t) const;
  double stress_yy(double x, double t) const;  // tension positive, so about -F/a
  double displacement_x(double x, double t) const;
  double displacement_y(double y, double t) const;

  // The roots computed so far, for the slope (1 - nu)/(nu_u - nu) they were computed with
  // (recomputed when the parameters change). Public only to keep designated initialisers;
  // not thread-safe.
  mutable std::vector<double> root_cache_{};
  mutable double root_cache_slope_ = 0;
};

/// Booker and Savvidou (verification.md (l)): a point heat source Q in
/// saturated thermo-poro-elastic rock, temperature rise and pore pressure at
/// distance r and time t (full space; the model is the half space z >= 0
/// with Q / 2, axisymmetric, the plane z = 0 a plane of symmetry).
struct BookerSavvidou {
  double power = 1000;                               // Q, W
  double conductivity = 3, heat_capacity = 2.484e6;  // lambda W/(m K), rho c J/(m^3 K)
  double young_modulus = 5e9, poisson_ratio = 0.25, biot_modulus = 10e9;
  double permeability = 1e-19, viscosity = 1e-3;
  double expansion = 1e-5, fluid_expansion = 3e-5;  // alpha_T of the solid, beta_m, 1/K

  double temperature(double r, double t) const;  // Delta T
  double pressure(double r, double t) const;
  /// The scene: 60 m x 60 m, a mesh graded from `fine` at the source to
  /// `coarse` (h = fine + grading x distance), steps of `step_years`, one
  /// year.
  std::string scene(double fine, double coarse, double step_years, double grading = 0.15) const;
};

}  // namespace fissure::test
