// Sparse SPD solvers for the network systems T p = q (steady) and
// (S + gamma T) p = r (implicit transient), theory.md 3.3:
//  * direct: CHOLMOD Cholesky (supernodal or simplicial, CHOLMOD's choice);
//    the symbolic analysis (fill-reducing ordering) is done once per pattern;
//  * pcg:    Eigen conjugate gradients with a diagonal (Jacobi) preconditioner;
//  * petsc:  PETSc KSP, CG + hypre BoomerAMG by default, on the symmetrically
//    diagonal-scaled system D^-1/2 T D^-1/2 (conductances span ~1e9, the
//    scaling keeps AMG's strength-of-connection test meaningful). Options
//    from the scene (prefix flow_) override the defaults. PETSc is not
//    thread-safe: only the main thread may use it.
//  * auto:   direct below kAutoPetscUnknowns unknowns, petsc above. Measured
//    (docs/performance.md "flow_steady"): on 2D DFN graphs CHOLMOD's fill
//    stays small (planar graphs, nested dissection) and it beats CG + AMG by
//    two orders of magnitude at 1e5 segments (AMG needs ~800 iterations on
//    these graphs), so PETSc is chosen only where the factor would outgrow
//    memory, or when asked for (type petsc, e.g. with its own options).
#pragma once

#include <Eigen/SparseCore>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "core/linear/linear_solver_controls.h"

namespace fissure::flow {

using SparseMatrix = Eigen::SparseMatrix<double>;

class SpdSolver {
 public:
  virtual ~SpdSolver() = default;
  virtual std::string name() const = 0;
  /// New sparsity pattern (both triangles stored). Values may change later.
  virtual void analyze(const SparseMatrix& a) = 0;
  /// New values on the analysed pattern.
  virtual void factorize(const SparseMatrix& a) = 0;
  /// x = A^-1 b; iterative back ends start from x when its size matches.
  virtual void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) = 0;
  virtual nlohmann::json statistics() const = 0;
};

/// Unknowns from which `auto` uses PETSc (when the build has it).
inline constexpr int kAutoPetscUnknowns = 5000000;

/// The solver for a system of n unknowns. `allow_petsc` is false in worker
/// threads (then auto and petsc fall back to direct).
std::unique_ptr<SpdSolver> make_spd_solver(const LinearSolverControls& controls, int n_unknowns,
                                           bool allow_petsc = true);

std::unique_ptr<SpdSolver> make_direct_spd_solver();
std::unique_ptr<SpdSolver> make_pcg_spd_solver(double relative_tolerance, int max_iterations);
std::unique_ptr<SpdSolver> make_petsc_spd_solver(const LinearSolverControls& controls);

}  // namespace fissure::flow
