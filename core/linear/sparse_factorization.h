// Sparse factorization of a DDA block matrix through a scalar copy:
// CHOLMOD supernodal LL^T for symmetric systems, UMFPACK LU when implicit
// friction makes them unsymmetric. The symbolic analysis of each kind is
// reused until the block pattern changes. Shared by the direct back end
// (factor and solve every time) and the reused-factorization back end (the
// factor preconditions later systems).
#pragma once

#include <Eigen/CholmodSupport>
#include <Eigen/UmfPackSupport>

#include "core/linear/block_sparse_matrix.h"
#include "core/linear/scalar_copy.h"

namespace fissure {

class SparseFactorization {
 public:
  SparseFactorization();

  /// The pattern of the next matrix differs from the last one's.
  void pattern_changed() { lower_stale_ = full_stale_ = true; }

  /// Factorizes A (Cholesky if `symmetric`, else LU). Throws SolverError when
  /// A is singular or, for Cholesky, not positive definite.
  void factorize(const BlockSparseMatrix& a, bool symmetric);

  /// z = F^-1 r with the last factorization.
  void solve(Eigen::Ref<const Eigen::VectorXd> r, Eigen::VectorXd& z) const;

  bool empty() const { return kind_ == Kind::None; }
  Eigen::Index rows() const { return rows_; }
  long analyses() const { return analyses_; }
  long cholesky_count() const { return cholesky_; }
  long lu_count() const { return lu_; }

 private:
  enum class Kind { None, Cholesky, Lu };
  Kind kind_ = Kind::None;
  Eigen::Index rows_ = 0;
  bool lower_stale_ = true, full_stale_ = true;  ///< scalar patterns out of date
  ScalarCopy lower_, full_;
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt_;
  Eigen::UmfPackLU<Eigen::SparseMatrix<double>> lu_factor_;
  long analyses_ = 0, cholesky_ = 0, lu_ = 0;
};

}  // namespace fissure
