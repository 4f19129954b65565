#include "core/linear/single_precision_factor.h"

#include <algorithm>

#include "core/base/errors.h"
#include "core/linear/supernodal_lu.h"

namespace fissure {

void SinglePrecisionFactor::copy(const cholmod_factor& f) {
  FISSURE_CHECK(f.is_super && f.is_ll && f.itype == CHOLMOD_INT && f.xtype == CHOLMOD_REAL,
                SolverError, "single-precision factor: expected a real supernodal LL^T factor");
  lu_ = false;
  structure_ = SupernodalStructure::of(f);
  const auto* x = static_cast<const double*>(f.x);
  lower_.assign(x, x + structure_.lower_start.back());  // rounded to float
  upper_.clear();
  pivots_.clear();
  resize_work();
}

void SinglePrecisionFactor::take(SupernodalLu& f) {
  lu_ = true;
  structure_ = f.structure();
  f.take_panels(lower_, upper_);
  pivots_ = f.pivots();
  resize_work();
}

void SinglePrecisionFactor::resize_work() {
  x_.resize(structure_.n());
  work_.resize(structure_.widest_below());
  int widest = 0;
  for (int k = 0; k < structure_.count(); ++k) widest = std::max(widest, structure_.ncol(k));
  own_.resize(widest);
}

SinglePrecisionFactor::Panel SinglePrecisionFactor::lower_panel(int k) const {
  const int nrow = structure_.nrow(k);
  return Panel(lower_.data() + structure_.lower_start[k], nrow, structure_.ncol(k),
               Eigen::OuterStride<>(nrow));
}

SinglePrecisionFactor::Panel SinglePrecisionFactor::upper_panel(int k) const {
  const int ncol = structure_.ncol(k), below = structure_.below(k);
  if (!lu_)
    return Panel(lower_panel(k).data() + ncol, below, ncol, Eigen::OuterStride<>(below + ncol));
  return Panel(upper_.data() + structure_.upper_start[k], below, ncol,
               Eigen::OuterStride<>(std::max(below, 1)));
}

void SinglePrecisionFactor::solve(Eigen::Ref<const Eigen::VectorXd> r, Eigen::VectorXd& z) const {
  const SupernodalStructure& st = structure_;
  const int n = st.n();
  for (int k = 0; k < n; ++k) x_[k] = static_cast<float>(r[st.perm[k]]);
  substitute(x_, work_, own_);
  z.resize(n);
  for (int k = 0; k < n; ++k) z[st.perm[k]] = x_[k];
}

void SinglePrecisionFactor::solve(const Eigen::MatrixXd& r, Eigen::MatrixXd& z) const {
  const SupernodalStructure& st = structure_;
  const int n = st.n();
  const Eigen::Index m = r.cols();
  RowMajorMatrixXf x(n, m), work(work_.size(), m), own(own_.size(), m);
  for (int k = 0; k < n; ++k) x.row(k) = r.row(st.perm[k]).cast<float>();
  substitute(x, work, own);
  z.resize(n, m);
  for (int k = 0; k < n; ++k) z.row(st.perm[k]) = x.row(k).cast<double>();
}

// One code for one right-hand side (a vector) and several (a row-major
// matrix, whose rows the scatter moves whole).
template <class Dense>
void SinglePrecisionFactor::substitute(Dense& x, Dense& work, Dense& scratch) const {
  const SupernodalStructure& st = structure_;
  const int nsuper = st.count();
  // Forward substitution, one supernode (dense panel) at a time: a
  // triangular solve for its own columns (after the diagonal block's row
  // permutation, LU), then its rows below update x.
  for (int k = 0; k < nsuper; ++k) {
    const int first = st.first(k), ncol = st.ncol(k), below = st.below(k);
    const Panel panel = lower_panel(k);
    auto own = x.middleRows(first, ncol);
    // Right-hand sides nonzero on a few rows (a low-rank correction's
    // columns) stay zero outside their rows' paths to the root.
    if constexpr (!Dense::IsVectorAtCompileTime)
      if (own.isZero(0)) continue;
    if (lu_) {
      auto original = scratch.topRows(ncol);
      original = own;
      for (int i = 0; i < ncol; ++i) own.row(pivots_[first + i]) = original.row(i);
      panel.topRows(ncol).template triangularView<Eigen::UnitLower>().solveInPlace(own);
    } else {
      panel.topRows(ncol).template triangularView<Eigen::Lower>().solveInPlace(own);
    }
    if (below == 0) continue;
    auto w = work.topRows(below);
    w.noalias() = panel.bottomRows(below) * own;
    const int* rows = st.rows_below(k);
    for (int i = 0; i < below; ++i) x.row(rows[i]) -= w.row(i);
  }
  // Backward substitution (U, or L^T), supernodes in reverse order.
  for (int k = nsuper; k-- > 0;) {
    const int first = st.first(k), ncol = st.ncol(k), below = st.below(k);
    auto own = x.middleRows(first, ncol);
    if (below > 0) {
      auto w = work.topRows(below);
      const int* rows = st.rows_below(k);
      for (int i = 0; i < below; ++i) w.row(i) = x.row(rows[i]);
      own.noalias() -= upper_panel(k).transpose() * w;
    }
    const auto diagonal = lower_panel(k).topRows(ncol);
    if (lu_)
      diagonal.template triangularView<Eigen::Upper>().solveInPlace(own);
    else
      diagonal.template triangularView<Eigen::Lower>().transpose().solveInPlace(own);
  }
}

}  // namespace fissure
