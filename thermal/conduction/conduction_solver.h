// The linear systems of one implicit conduction step, A T = b with A =
// a0 M / dt + K (docs/thermal.md 3), temperatures fixed on some unknowns.
// The fixed unknowns are eliminated; the rest is symmetric positive
// definite and factorized by CHOLMOD (supernodal Cholesky, serial so that
// runs are reproducible to the bit), once per matrix: the factor is reused
// while dt, the mesh and the joints' contact set stay the same. With the
// fracture water's rows (thermal/convection/fracture_fluid.h) the matrix is
// not symmetric (upwind advection): UMFPACK's LU then (serial BLAS, as
// CHOLMOD: reproducible to the bit).
#pragma once

#include <Eigen/CholmodSupport>
#include <Eigen/Core>
#include <Eigen/UmfPackSupport>
#include <memory>
#include <vector>

#include "thermal/conduction/conduction_matrices.h"

namespace fissure::thermal {

/// CHOLMOD's Cholesky made for many solves with one factor (issue 41,
/// docs/performance.md "continuum_vs_fenicsx"): the supernodal
/// factorization without the zeros that merge columns into wider supernodes
/// (CHOLMOD's zrelax), then turned into a simplicial factor: on the thin
/// supernodes of a 2D mesh the supernodal solve's BLAS-2 calls cost more
/// than the simplicial loops (a step at 1e5 nodes 12.5 -> 10.8 ms). From
/// kMetisFrom unknowns METIS alone orders (CHOLMOD tries AMD first): at 1e6
/// nodes the step 150 -> 113 ms and the factorization 9.1 -> 8.8 s; at 1e5
/// METIS's 0.35 s would take 130 steps to repay.
class ConductionCholesky : public Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower> {
 public:
  static constexpr Eigen::Index kMetisFrom = 200'000;
  void compute(const SparseMatrix& a);
};

class ConductionSolver {
 public:
  ConductionSolver();
  /// A new matrix (all unknowns) and which unknowns are fixed: the next
  /// solve factorizes (Cholesky when symmetric, else LU). `counted` false:
  /// the matrix of a restored checkpoint's factor, computed again after a
  /// restart, which the uninterrupted run did not factorize again.
  void set_matrix(SparseMatrix a, std::vector<bool> fixed, bool symmetric = true,
                  bool counted = true);
  /// Solves for the free unknowns of `t`; `t` holds the fixed values on
  /// entry. `b` is the right-hand side of all unknowns.
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& t);
  /// The sum over the fixed unknowns of (A T - b): the heat the fixed
  /// temperatures bring in (W/m).
  double fixed_reaction(const Eigen::VectorXd& b, const Eigen::VectorXd& t) const;
  const SparseMatrix& matrix() const { return a_; }
  long factorizations() const { return factorizations_; }
  long solves() const { return solves_; }
  double factor_seconds() const { return factor_seconds_; }
  double solve_seconds() const { return solve_seconds_; }
  /// Its counters (core/io/checkpoint.h); a restored run factorizes its
  /// first matrix again (the factor itself is not saved). Self is const
  /// ConductionSolver when writing.
  template <class Self, class Archive>
  static void checkpoint_counters(Self& self, Archive& a) {
    a("factorizations", self.factorizations_);
    a("solves", self.solves_);
  }

 private:
  SparseMatrix a_, a_free_, a_coupling_;  ///< A, A_ff, A_fd
  std::vector<int> free_, fixed_;
  std::unique_ptr<ConductionCholesky> llt_;
  std::unique_ptr<Eigen::UmfPackLU<SparseMatrix>> lu_;
  bool symmetric_ = true;
  bool stale_ = true;
  bool counted_ = true;  ///< whether the next factorization counts
  long factorizations_ = 0, solves_ = 0;
  double factor_seconds_ = 0, solve_seconds_ = 0;
};

}  // namespace fissure::thermal
