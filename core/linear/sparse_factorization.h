// Sparse factorization of a DDA block matrix: CHOLMOD supernodal LL^T for
// symmetric systems (through a scalar copy); for unsymmetric ones (implicit
// friction) UMFPACK LU with pivoting, or, as a preconditioner, Fissure's LU on
// the supernodal structure of the Cholesky analysis (supernodal_lu.h). The
// symbolic analysis of each kind is reused until the block pattern changes.
// Shared by the direct back end (factor and solve every time) and the
// reused-factorization back end (the factor, applied in single precision,
// preconditions later systems).
#pragma once

#include <Eigen/CholmodSupport>
#include <Eigen/UmfPackSupport>

#include "core/linear/block_sparse_matrix.h"
#include "core/linear/scalar_copy.h"
#include "core/linear/single_precision_factor.h"
#include "core/linear/supernodal_lu.h"

namespace fissure {

class SparseFactorization {
 public:
  enum class Method {
    Cholesky,      ///< CHOLMOD LL^T; A must be symmetric positive definite
    SupernodalLu,  ///< LU on the Cholesky structure, in float (a preconditioner)
    PivotedLu,     ///< UMFPACK LU
  };

  /// single_precision_solves: solve() applies a Cholesky factor rounded to
  /// float, or the supernodal LU (computed in float; for preconditioning).
  /// UMFPACK solves stay in double.
  explicit SparseFactorization(bool single_precision_solves = false);

  /// The pattern of the next matrix differs from the last one's.
  void pattern_changed() { lower_stale_ = full_stale_ = supernodal_lu_stale_ = true; }

  /// Factorizes A. Throws SolverError when A is singular (a zero pivot) or,
  /// for Cholesky, not positive definite.
  void factorize(const BlockSparseMatrix& a, Method method);

  /// z = F^-1 r with the last factorization.
  void solve(Eigen::Ref<const Eigen::VectorXd> r, Eigen::VectorXd& z) const;
  /// Z = F^-1 R for several right-hand sides.
  void solve(const Eigen::MatrixXd& r, Eigen::MatrixXd& z) const;

  bool empty() const { return kind_ == Kind::None; }
  Eigen::Index rows() const { return rows_; }
  long analyses() const { return analyses_; }
  long cholesky_count() const { return cholesky_; }
  long lu_count() const { return lu_; }  ///< both kinds of LU
  /// Its counters (core/io/checkpoint.h); a restored factor is computed
  /// again from the matrix it stands for, which the caller keeps.
  template <class Self, class Archive>
  static void checkpoint_counters(Self& self, Archive& a) {
    a("analyses", self.analyses_);
    a("cholesky_factorizations", self.cholesky_);
    a("lu_factorizations", self.lu_);
  }

  /// Model costs (linear_cost.h) of the last factorization, and of applying
  /// it to `right_hand_sides` vectors at once; from the factor's size, not
  /// from clocks, so that solvers deciding by them decide the same way on
  /// every run.
  double factorization_cost() const { return factorization_cost_; }
  double solve_cost(int right_hand_sides = 1) const;

 private:
  enum class Kind { None, Cholesky, SupernodalLu, Lu };
  /// z = F^-1 r with the factor of the last factorization's kind.
  template <class Right, class Result>
  void solve_with_kind(const Right& r, Result& z) const;
  Kind kind_ = Kind::None;
  Eigen::Index rows_ = 0;
  bool lower_stale_ = true, full_stale_ = true;  ///< scalar patterns out of date
  bool supernodal_lu_stale_ = true;              ///< its map of A's entries out of date
  ScalarCopy lower_, full_;
  /// Eigen's CHOLMOD wrapper, with access to the factor it holds.
  struct SupernodalLlt : Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> {
    const cholmod_factor& factor() const { return *m_cholmodFactor; }
  };
  SupernodalLlt llt_;
  bool single_precision_solves_;
  SinglePrecisionFactor single_;  ///< the Cholesky factor in float, or the supernodal LU
  SupernodalLu supernodal_lu_;
  /// Eigen's UMFPACK wrapper, with access to UMFPACK's statistics.
  struct PivotedLu : Eigen::UmfPackLU<Eigen::SparseMatrix<double>> {
    double statistic(int entry) const { return m_umfpackInfo(entry); }
  };
  PivotedLu lu_factor_;
  long analyses_ = 0, cholesky_ = 0, lu_ = 0;
  double factorization_cost_ = 0;
  double factor_bytes_ = 0;  ///< read by one application of the factor
  double factor_entries_ = 0;
};

}  // namespace fissure
