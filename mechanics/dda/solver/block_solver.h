// Linear-solver front for the DDA block systems A x = b. A = S + F: S is
// symmetric positive definite (inertia, elasticity, springs), F holds the
// unsymmetric terms of implicit sliding friction and is absent while no
// contact slides. Back ends behind one interface:
//  * direct: CHOLMOD supernodal Cholesky for symmetric systems, UMFPACK
//            multifrontal LU for unsymmetric ones, factorized for every solve;
//  * reused factorization: GMRES preconditioned by the factor of an earlier
//            system (Cholesky, or LU with friction), corrected by a low-rank
//            update when the caller describes one, renewed when it stops
//            paying (used by `auto`);
//  * pcg:    conjugate gradients (BiCGStab when unsymmetric) with a
//            block-Jacobi (6x6) preconditioner, warm-started from x;
//  * petsc:  PETSc KSP on an AIJ matrix with block size 6, options from the scene
//            (prefix "dda_"), defaults cg + ILU (gmres when unsymmetric).
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "core/linear/block_sparse_matrix.h"
#include "core/linear/linear_solver_controls.h"
#include "core/linear/low_rank_update.h"

namespace fissure {

class CheckpointWriter;  // core/io/checkpoint.h
class CheckpointReader;

class BlockSolver {
 public:
  virtual ~BlockSolver() = default;
  virtual std::string name() const = 0;
  /// Called whenever the pattern of A changes.
  virtual void analyze(const BlockSparseMatrix& a) = 0;
  /// Solves A x = b; `symmetric` is false when A has friction terms.
  /// Iterative back ends start from the given x. Throws SolverError when
  /// the system is singular or the iteration fails.
  virtual void solve(const BlockSparseMatrix& a, bool symmetric, const Eigen::VectorXd& b,
                     Eigen::VectorXd& x) = 0;
  /// Counters for summary.json (solves, iterations, ...).
  virtual nlohmann::json statistics() const = 0;
  /// Iterative back ends give up (SolverError) after this many iterations
  /// from the next solve on; the direct and PETSc back ends ignore it.
  virtual void set_max_iterations(int) {}
  /// Whether the last solve factorized its system: the one that later
  /// updates (expect) are relative to.
  virtual bool factorized() const { return false; }
  /// How the next system differs from the last factorized one: A = A_f +
  /// U V^T + a small remainder (the update outlives the solve); null when
  /// unknown. A hint that back ends without a use for it ignore.
  virtual void expect(const LowRankUpdate* /*update*/) {}
  /// The most update terms the back end uses (0: it ignores updates).
  virtual int max_update_terms() const { return 0; }
  /// Model cost (core/linear/linear_cost.h) of the last solve, given up or
  /// not, for back ends that `auto` chooses between; 0 for the others.
  virtual double last_solve_cost() const { return 0; }
  /// Its state for a checkpoint (core/io/checkpoint.h): what its next solves
  /// and choices depend on, and its counters.
  virtual void save(CheckpointWriter& out) const = 0;
  virtual void restore(CheckpointReader& in) = 0;
};

/// `auto`: direct below 300 blocks; above, the cheaper by model cost of pcg
/// and the reused factorization.
std::unique_ptr<BlockSolver> make_block_solver(const LinearSolverControls& controls);

std::unique_ptr<BlockSolver> make_direct_solver();
std::unique_ptr<BlockSolver> make_pcg_solver(double relative_tolerance, int max_iterations);
std::unique_ptr<BlockSolver> make_reused_factor_solver(double relative_tolerance,
                                                       int max_iterations);
std::unique_ptr<BlockSolver> make_petsc_solver(const LinearSolverControls& controls);

}  // namespace fissure
