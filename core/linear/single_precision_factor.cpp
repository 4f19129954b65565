#include "core/linear/single_precision_factor.h"

#include <algorithm>

#include "core/base/errors.h"

namespace fissure {

void SinglePrecisionFactor::copy(const cholmod_factor& f) {
  FISSURE_CHECK(f.is_super && f.is_ll && f.itype == CHOLMOD_INT && f.xtype == CHOLMOD_REAL,
                SolverError, "single-precision factor: expected a real supernodal LL^T factor");
  const auto* perm = static_cast<const int*>(f.Perm);
  const auto* super = static_cast<const int*>(f.super);
  const auto* pi = static_cast<const int*>(f.pi);
  const auto* px = static_cast<const int*>(f.px);
  const auto* s = static_cast<const int*>(f.s);
  const auto* x = static_cast<const double*>(f.x);
  const std::size_t n = f.n, nsuper = f.nsuper;
  perm_.assign(perm, perm + n);
  super_.assign(super, super + nsuper + 1);
  row_start_.assign(pi, pi + nsuper + 1);
  rows_.assign(s, s + pi[nsuper]);
  value_start_.assign(px, px + nsuper + 1);
  values_.assign(x, x + px[nsuper]);  // rounded to float
  int widest = 0;
  for (std::size_t k = 0; k < nsuper; ++k)
    widest = std::max(widest, (pi[k + 1] - pi[k]) - (super[k + 1] - super[k]));
  x_.resize(n);
  work_.resize(widest);
}

SinglePrecisionFactor::Supernode SinglePrecisionFactor::supernode(std::size_t k) const {
  const int first = super_[k], ncol = super_[k + 1] - first;
  const int nrow = row_start_[k + 1] - row_start_[k];
  return {first, ncol, nrow - ncol,
          Panel(values_.data() + value_start_[k], nrow, ncol, Eigen::OuterStride<>(nrow)),
          rows_.data() + row_start_[k] + ncol};
}

void SinglePrecisionFactor::solve(Eigen::Ref<const Eigen::VectorXd> r, Eigen::VectorXd& z) const {
  const std::size_t n = perm_.size(), nsuper = super_.size() - 1;
  for (std::size_t k = 0; k < n; ++k) x_[k] = static_cast<float>(r[perm_[k]]);
  // Forward substitution L y = P r, one supernode (dense panel) at a time:
  // a triangular solve for its own columns, then its rows below update x.
  for (std::size_t k = 0; k < nsuper; ++k) {
    const Supernode s = supernode(k);
    auto own = x_.segment(s.first, s.ncol);
    s.panel.topRows(s.ncol).triangularView<Eigen::Lower>().solveInPlace(own);
    if (s.below == 0) continue;
    auto w = work_.head(s.below);
    w.noalias() = s.panel.bottomRows(s.below) * own;
    for (int i = 0; i < s.below; ++i) x_[s.rows_below[i]] -= w[i];
  }
  // Backward substitution L^T x = y, supernodes in reverse order.
  for (std::size_t k = nsuper; k-- > 0;) {
    const Supernode s = supernode(k);
    auto own = x_.segment(s.first, s.ncol);
    if (s.below > 0) {
      auto w = work_.head(s.below);
      for (int i = 0; i < s.below; ++i) w[i] = x_[s.rows_below[i]];
      own.noalias() -= s.panel.bottomRows(s.below).transpose() * w;
    }
    s.panel.topRows(s.ncol).triangularView<Eigen::Lower>().transpose().solveInPlace(own);
  }
  z.resize(static_cast<Eigen::Index>(n));
  for (std::size_t k = 0; k < n; ++k) z[perm_[k]] = x_[k];
}

}  // namespace fissure
