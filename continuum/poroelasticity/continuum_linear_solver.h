// The linear systems of the continuum (docs/continuum.md 3): elasticity,
// the flow and heat diffusion equations, and the monolithic u-p saddle
// point, each on its free unknowns. Each rank passes its share of the
// matrix and of the right-hand side (the sum over the ranks is the system,
// poroelastic_matrices.h) and gets the whole solution back.
//   direct: CHOLMOD (SPD systems) or UMFPACK (the saddle point); on several
//           ranks rank 0 factorizes the sum of the shares, so that runs are
//           the same to the bit (MUMPS is not: petsc_options may still
//           choose it, docs/continuum.md 3).
//   petsc:  PETSc KSP: CG with BoomerAMG and the rigid-body near-null space
//           for elasticity, CG with BoomerAMG for diffusion, GMRES with the
//           fixed-stress Schur field split for the saddle point
//           (core/linear/distributed_system.h); options `continuum.solver.
//           petsc_options`, prefixed per system (continuum_mechanics_,
//           continuum_flow_, continuum_heat_, continuum_monolithic_).
//   auto:   direct up to kAutoIterativeUnknowns unknowns per system, petsc
//           above.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <string>
#include <vector>

#include "continuum/poroelasticity/continuum_constraints.h"
#include "continuum/poroelasticity/continuum_mesh.h"
#include "core/linear/linear_solver_controls.h"

namespace fissure::continuum {

/// Above this many unknowns in one system `auto` takes PETSc's Krylov
/// solvers: in 2D the direct factors are cheap (a monolithic system of 1e6
/// unknowns: 3.3 GB per rank and 2.5 s per step with MUMPS on 2 ranks, where
/// BoomerAMG-preconditioned GMRES took over 10 times as long; docs/
/// performance.md "continuum scaling"), so the Krylov solvers are for the
/// systems whose factors would not fit in memory.
inline constexpr int kAutoIterativeUnknowns = 3000000;

enum class SystemKind { Elasticity, Diffusion, SaddlePoint };

class ContinuumLinearSolver {
 public:
  virtual ~ContinuumLinearSolver() = default;
  /// This rank's share of the matrix; a saddle point's iterative solver
  /// also takes a share of its Schur preconditioner (the flow block with the
  /// fixed-stress term).
  /// A solver that copies it (UMFPACK's 64-bit indices) empties `share`
  /// before it factorizes (an rvalue: Eigen 3.4's SparseMatrix has no move).
  virtual void set_matrix(Eigen::SparseMatrix<double>&& share,
                          const Eigen::SparseMatrix<double>* schur_share = nullptr) = 0;
  /// The whole solution from this rank's share of the right-hand side;
  /// `guess` (possibly empty) starts an iterative solver.
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& share, const Eigen::VectorXd& guess) = 0;
  virtual int size() const = 0;         ///< unknowns
  virtual long iterations() const = 0;  ///< Krylov iterations so far (0: direct)
  /// Whether solve() starts from its guess (a direct solver ignores it, and
  /// callers need not make one).
  virtual bool takes_a_guess() const = 0;
  virtual std::string describe() const = 0;
  /// The size of its last factor, for summary.json: entries of L and U (of
  /// L for a Cholesky factor) and the flops of its factorization; zeros for
  /// a solver without a factor of its own (the Krylov solvers, the ranks
  /// other than the one that factorizes).
  struct FactorSize {
    double entries = 0, flops = 0;
    /// An LU factor's componentwise backward error, measured when it was
    /// made (0: not measured: a Cholesky factor, `refinement: never`), and
    /// whether its solves refine (continuum_linear_solver.cpp).
    double backward_error = 0;
    bool refined = false;
  };
  virtual FactorSize factor_size() const { return {}; }
  /// What a direct solver's last analysis found, for the solver of a
  /// related system to start from: its fill-reducing column order (a
  /// permutation of its unknowns) and the memory its factorization took
  /// (in the factorization's own units).
  struct Analysis {
    std::vector<long> column_order;
    double memory = 0;
  };
  /// Empty where it has none (Krylov solvers, CHOLMOD, ranks that do not
  /// factorize).
  virtual Analysis analysis() const { return {}; }
  /// An analysis carried to its unknowns, for its next one: spares the
  /// ordering. Solvers that order by themselves ignore it.
  virtual void take_analysis(Analysis) {}
};

/// The solver of a system of `kind` on the free unknowns of `first` (and,
/// for the saddle point, then of `second`), by `controls` (type auto,
/// direct or petsc). `name` (mechanics, flow, heat, monolithic) is in its
/// messages and its PETSc prefix (continuum_NAME_).
std::unique_ptr<ContinuumLinearSolver> make_linear_solver(SystemKind kind, const char* name,
                                                          const ContinuumMesh& mesh,
                                                          bool axisymmetric,
                                                          const FieldNumbering& first,
                                                          const FieldNumbering* second,
                                                          const LinearSolverControls& controls);

}  // namespace fissure::continuum
