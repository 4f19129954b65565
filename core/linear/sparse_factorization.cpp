#include "core/linear/sparse_factorization.h"

#include "core/base/errors.h"
#include "core/linear/linear_cost.h"
#include "core/linear/serial_cholmod.h"

namespace fissure {

namespace {

/// Brings the scalar matrix up to date: its pattern and the symbolic
/// analysis when the block pattern has changed, A's values if `values`
/// (UMFPACK's symbolic step looks at them, so they come first; the
/// supernodal LU needs only CHOLMOD's analysis of the pattern). True if it
/// analysed.
template <class Factorization>
bool refresh(ScalarCopy& copy, bool& stale, const BlockSparseMatrix& a, bool lower,
             Factorization& f, bool values = true) {
  const bool analyze = stale;
  if (analyze) copy.build_pattern(a, lower);
  if (values) copy.copy_values(a);
  if (analyze) f.analyzePattern(copy.matrix());
  stale = false;
  return analyze;
}

}  // namespace

SparseFactorization::SparseFactorization(bool single_precision_solves)
    : single_precision_solves_(single_precision_solves) {
  keep_cholmod_serial();
  // The pattern is symmetric and the diagonal dominant (inertia, springs):
  // UMFPACK's symmetric strategy, no iterative refinement (the open-close
  // iteration re-solves anyway; refinement tripled the cost of each solve).
  lu_factor_.umfpackControl()(UMFPACK_STRATEGY) = UMFPACK_STRATEGY_SYMMETRIC;
  lu_factor_.umfpackControl()(UMFPACK_IRSTEP) = 0;
}

void SparseFactorization::factorize(const BlockSparseMatrix& a, Method method) {
  kind_ = Kind::None;
  rows_ = a.n_rows();
  switch (method) {
    case Method::Cholesky:
      analyses_ += refresh(lower_, lower_stale_, a, true, llt_);
      llt_.factorize(lower_.matrix());
      FISSURE_CHECK(llt_.info() == Eigen::Success, SolverError,
                    "CHOLMOD: the block system matrix is not positive definite (a free block "
                    "without mass, or a non-physical material?)");
      if (single_precision_solves_) single_.copy(llt_.factor());
      kind_ = Kind::Cholesky;
      ++cholesky_;
      {
        // L and L^T are read once each per solve.
        const FactorSize size = factor_size(llt_.factor());
        const double bytes = size.entries * (single_precision_solves_ ? 4 : 8);
        factorization_cost_ = linear_cost::factorization(size.flops, false) +
                              (single_precision_solves_ ? linear_cost::stream(3 * bytes) : 0);
        factor_bytes_ = 2 * bytes;
        factor_entries_ = size.entries;
      }
      return;
    case Method::SupernodalLu:
      FISSURE_CHECK(single_precision_solves_, SolverError,
                    "the supernodal LU is applied in single precision only");
      analyses_ += refresh(lower_, lower_stale_, a, true, llt_, false);
      if (supernodal_lu_stale_) supernodal_lu_.analyze(llt_.factor(), a);
      supernodal_lu_stale_ = false;
      supernodal_lu_.factorize(a);
      single_.take(supernodal_lu_);
      kind_ = Kind::SupernodalLu;
      ++lu_;
      {
        // L and U: twice the entries and operations of L L^T, in float.
        const FactorSize size = factor_size(llt_.factor());
        factorization_cost_ = linear_cost::factorization(2 * size.flops, true);
        factor_bytes_ = 2 * size.entries * 4;
        factor_entries_ = 2 * size.entries;
      }
      return;
    case Method::PivotedLu:
      analyses_ += refresh(full_, full_stale_, a, false, lu_factor_);
      lu_factor_.factorize(full_.matrix());
      FISSURE_CHECK(lu_factor_.info() == Eigen::Success, SolverError,
                    "UMFPACK: the block system matrix is singular");
      kind_ = Kind::Lu;
      ++lu_;
      factor_entries_ = lu_factor_.statistic(UMFPACK_LNZ) + lu_factor_.statistic(UMFPACK_UNZ);
      factorization_cost_ = linear_cost::factorization(lu_factor_.statistic(UMFPACK_FLOPS), false);
      factor_bytes_ = factor_entries_ * 8;
      return;
  }
}

double SparseFactorization::solve_cost(int right_hand_sides) const {
  // Memory-bound for one right-hand side; the factor is streamed once for
  // all of them, each further one adds two operations per entry.
  return linear_cost::stream(factor_bytes_) +
         linear_cost::factorization(2.0 * factor_entries_ * (right_hand_sides - 1), true);
}

void SparseFactorization::solve(Eigen::Ref<const Eigen::VectorXd> r, Eigen::VectorXd& z) const {
  solve_with_kind(r, z);
}

void SparseFactorization::solve(const Eigen::MatrixXd& r, Eigen::MatrixXd& z) const {
  solve_with_kind(r, z);
}

template <class Right, class Result>
void SparseFactorization::solve_with_kind(const Right& r, Result& z) const {
  if (kind_ == Kind::SupernodalLu || (kind_ == Kind::Cholesky && single_precision_solves_))
    single_.solve(r, z);
  else if (kind_ == Kind::Cholesky)
    z = llt_.solve(r);
  else
    z = lu_factor_.solve(r);
}

}  // namespace fissure
