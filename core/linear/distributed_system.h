// A sparse linear system solved by PETSc over every MPI rank (errors: petsc_session.h;
// docs/architecture.md 6). Each rank holds a share of the matrix and of the
// right-hand side, assembled from its own elements; the system is the sum of
// the shares (one rank: its share is the system). PETSc sums them into rows
// that each rank owns: contiguous runs of the unknowns ordered along a
// space-filling curve (`keys`), so that a rank's rows are a compact part of
// the domain. Every rank gets the whole solution back. The system is
// scaled symmetrically by its diagonal (a saddle point's second field by its
// Schur preconditioner's), so that a relative tolerance weighs every
// equation alike: a poro-elastic system's rows differ by 20 orders of
// magnitude in Pa and m^3/s.
//
// Symmetric positive definite systems are solved by CG with hypre's
// BoomerAMG (GAMG where PETSc has no hypre; the caller's options may choose
// another, e.g. GAMG with the near-null space given, the rigid-body modes of
// elasticity); two-field saddle-point systems by GMRES with a
// Schur-complement field split whose Schur preconditioner the caller gives
// (a fixed-stress operator of coupled u-p systems: White, Castelletto and
// Tchelepi 2016). Options may choose a factorization instead
// (`-ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps`); MUMPS
// on several ranks is not reproducible to the bit (docs/continuum.md 3).
// Precedence: the environment's PETSC_OPTIONS, then the scene's options
// (with `prefix`), then the caller's, then these defaults. PETSc's options
// database is the process's: the options a system sets are cleared when the
// last system using them is destroyed (two systems of one prefix alive at
// once share the first one's).
#pragma once

#ifdef FISSURE_WITH_PETSC
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <string>
#include <vector>

#include "core/linear/linear_solver_controls.h"
#include "core/linear/petsc_options.h"

namespace fissure {

struct DistributedSystemLayout {
  /// The sizes of the system's fields, in its order (one, or two for a
  /// saddle point: the second field's rows are the constraint's).
  std::vector<int> field_sizes;
  /// Per unknown: its place along a space-filling curve (ranks own runs).
  std::vector<double> keys;
  /// Near-null-space vectors of the first field (AMG's coarse spaces).
  std::vector<Eigen::VectorXd> near_null_space;
  /// Per field, a factor for its rows: a saddle point's second block row
  /// negated (-1) makes its Schur complement positive definite.
  std::vector<double> row_signs;
  bool symmetric_positive = true;  ///< one field, SPD: CG
  std::string prefix;              ///< of the PETSc options, e.g. "module_system_"
  /// The caller's defaults for this system (after the generic ones, before
  /// the scene's), without the prefix.
  std::string options;
};

class DistributedSystem {
 public:
  DistributedSystem(DistributedSystemLayout layout, const LinearSolverControls& controls);
  ~DistributedSystem();
  DistributedSystem(const DistributedSystem&) = delete;
  DistributedSystem& operator=(const DistributedSystem&) = delete;

  /// This rank's share of the matrix, and for a saddle point its share of
  /// the Schur preconditioner on the second field (positive definite).
  void set_matrix(const Eigen::SparseMatrix<double>& share,
                  const Eigen::SparseMatrix<double>* schur_share = nullptr);
  /// Solves with this rank's share of the right-hand side, from `guess`
  /// (empty: zero); every rank returns the whole solution. Throws
  /// SolverError when the Krylov method does not converge, or when a
  /// factorization the options chose (-ksp_type preonly) leaves a relative
  /// residual above 1e-6.
  Eigen::VectorXd solve(const Eigen::VectorXd& share, const Eigen::VectorXd& guess);

  long iterations() const { return iterations_; }  ///< of every solve so far
  long last_iterations() const { return last_iterations_; }
  std::string describe() const;

 private:
  void check_direct_residual();
  PetscOptionsLease options_;  ///< the scene's and the defaults, prefixed, while it lives
  struct Petsc;
  std::unique_ptr<Petsc> petsc_;
  DistributedSystemLayout layout_;
  LinearSolverControls controls_;
  Eigen::VectorXd scale_;  ///< per unknown: 1 / sqrt(its diagonal)
  long iterations_ = 0, last_iterations_ = 0;
};

}  // namespace fissure
#endif
