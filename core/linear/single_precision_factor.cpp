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

void SinglePrecisionFactor::copy(const SupernodalLu& f) {
  lu_ = true;
  structure_ = f.structure();
  lower_.assign(f.lower().begin(), f.lower().end());  // rounded to float
  upper_.assign(f.upper().begin(), f.upper().end());
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
  const int n = st.n(), nsuper = st.count();
  for (int k = 0; k < n; ++k) x_[k] = static_cast<float>(r[st.perm[k]]);
  // Forward substitution, one supernode (dense panel) at a time: a
  // triangular solve for its own columns (after the diagonal block's row
  // permutation, LU), then its rows below update x.
  for (int k = 0; k < nsuper; ++k) {
    const int first = st.first(k), ncol = st.ncol(k), below = st.below(k);
    const Panel panel = lower_panel(k);
    auto own = x_.segment(first, ncol);
    if (lu_) {
      auto original = own_.head(ncol);
      original = own;
      for (int i = 0; i < ncol; ++i) own[pivots_[first + i]] = original[i];
      panel.topRows(ncol).triangularView<Eigen::UnitLower>().solveInPlace(own);
    } else {
      panel.topRows(ncol).triangularView<Eigen::Lower>().solveInPlace(own);
    }
    if (below == 0) continue;
    auto w = work_.head(below);
    w.noalias() = panel.bottomRows(below) * own;
    const int* rows = st.rows_below(k);
    for (int i = 0; i < below; ++i) x_[rows[i]] -= w[i];
  }
  // Backward substitution (U, or L^T), supernodes in reverse order.
  for (int k = nsuper; k-- > 0;) {
    const int first = st.first(k), ncol = st.ncol(k), below = st.below(k);
    auto own = x_.segment(first, ncol);
    if (below > 0) {
      auto w = work_.head(below);
      const int* rows = st.rows_below(k);
      for (int i = 0; i < below; ++i) w[i] = x_[rows[i]];
      own.noalias() -= upper_panel(k).transpose() * w;
    }
    const auto diagonal = lower_panel(k).topRows(ncol);
    if (lu_)
      diagonal.triangularView<Eigen::Upper>().solveInPlace(own);
    else
      diagonal.triangularView<Eigen::Lower>().transpose().solveInPlace(own);
  }
  z.resize(n);
  for (int k = 0; k < n; ++k) z[st.perm[k]] = x_[k];
}

}  // namespace fissure
