// The global Galerkin matrices of the poro-thermo-elastic continuum
// (theory.md 5.2), on the full numbering: displacement unknowns 2 n + c of
// P2 node n, pressure and temperature unknowns at the vertices. Assembled
// once: the materials are linear and the mesh does not move (small strain);
// only the flow terms H and G are assembled again when a permeability
// follows the stress (stress_permeability.h).
// On several MPI ranks each rank assembles its own triangles (a compact run
// along the Hilbert curve, owned_triangles): its matrices and load vectors
// are its share, and the sum over the ranks is the whole.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "continuum/poroelasticity/continuum_mesh.h"
#include "continuum/poroelasticity/continuum_settings.h"
#include "continuum/poroelasticity/taylor_hood.h"

namespace fissure::continuum {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// Without heat (ContinuumControls::with_temperature) K_T, W, C_T and L_T,
/// and without the undrained scheme K_v, have their sizes and no entries.
struct PoroelasticMatrices {
  SparseMatrix stiffness;          ///< K = int B^T D B
  SparseMatrix coupling;           ///< Q = int B^T alpha m N_p
  SparseMatrix thermal_stress;     ///< K_T = int B^T 3 K alpha_T m N_T
  SparseMatrix storage;            ///< S = int N^T (1/M) N
  SparseMatrix fixed_stress;       ///< int N^T beta_FS N, beta_FS = factor alpha^2 / K_dr
  SparseMatrix undrained;          ///< int B^T alpha^2 M m m^T B (the undrained split)
  SparseMatrix mobility;           ///< H = int grad N^T (k / mu) grad N
  SparseMatrix pressurization;     ///< W = int N^T beta_m N
  SparseMatrix heat_capacity;      ///< C_T = int N^T (rho c)_m N
  SparseMatrix conduction;         ///< L_T = int grad N^T lambda_m grad N
  Eigen::VectorXd body_force;      ///< int N_u rho_b g
  Eigen::VectorXd initial_stress;  ///< int B^T sigma_0
  Eigen::VectorXd gravity_flow;    ///< int grad N^T (k / mu) rho_f g
  /// Per triangle: its D, alpha and 3 K alpha_T, for stresses, and its
  /// permeability (kxx, kyy, kxy) in H and G.
  std::vector<Matrix4> elasticity;
  std::vector<double> biot, thermal_stress_modulus;
  std::vector<Eigen::Vector3d> permeability;
};

/// The scene's initial stress (sxx, syy, sxy) with szz = sxx: the
/// horizontal stress acts alike in every horizontal direction (the hoop
/// stress of an axisymmetric model).
Vector4 initial_stress4(const Eigen::Vector3d& s);

/// The triangles this rank assembles (all of them on one rank): the
/// triangles cut into equal runs along a Hilbert curve of their centroids.
std::vector<char> owned_triangles(const ContinuumMesh& mesh, int rank, int ranks);

/// The matrices of the triangles `owned` (every triangle when empty); the
/// per-triangle data (elasticity, biot, ...) of every triangle.
/// Written into `out` (Eigen 3.4's SparseMatrix has no move: a returned
/// struct is copied, every matrix twice in memory for a moment).
void assemble_poroelastic(const ContinuumMesh& mesh, const ContinuumControls& c,
                          const Vec2& gravity, const std::vector<char>& owned,
                          PoroelasticMatrices& out);

/// H and G (mobility, gravity_flow) of the triangles `owned` (every
/// triangle when empty) from the per-triangle permeability of `m`.
void assemble_flow_terms(const ContinuumMesh& mesh, const ContinuumControls& c, const Vec2& gravity,
                         const std::vector<char>& owned, PoroelasticMatrices& m);

/// The coupling strength tau = alpha^2 M / K_dr (theory.md 5.3), largest
/// over the materials the mesh uses: the drained split converges only
/// below about 1.
double largest_coupling_strength(const ContinuumMesh& mesh, const ContinuumControls& c);

}  // namespace fissure::continuum
