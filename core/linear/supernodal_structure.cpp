#include "core/linear/supernodal_structure.h"

#include <algorithm>

#include "core/base/errors.h"

namespace fissure {

SupernodalStructure SupernodalStructure::of(const cholmod_factor& f) {
  FISSURE_CHECK(f.is_super && f.itype == CHOLMOD_INT, SolverError,
                "supernodal structure: expected a supernodal CHOLMOD factor with int indices");
  const auto* perm = static_cast<const int*>(f.Perm);
  const auto* super = static_cast<const int*>(f.super);
  const auto* pi = static_cast<const int*>(f.pi);
  const auto* px = static_cast<const int*>(f.px);
  const auto* s = static_cast<const int*>(f.s);
  const std::size_t n = f.n, nsuper = f.nsuper;
  SupernodalStructure st;
  st.perm.assign(perm, perm + n);
  st.super.assign(super, super + nsuper + 1);
  st.row_start.assign(pi, pi + nsuper + 1);
  st.rows.assign(s, s + pi[nsuper]);
  st.lower_start.assign(px, px + nsuper + 1);
  st.upper_start.assign(nsuper + 1, 0);
  for (std::size_t k = 0; k < nsuper; ++k) {
    const int kk = static_cast<int>(k);
    st.upper_start[k + 1] = st.upper_start[k] + static_cast<long>(st.below(kk)) * st.ncol(kk);
  }
  return st;
}

int SupernodalStructure::widest_below() const {
  int widest = 0;
  for (int k = 0; k < count(); ++k) widest = std::max(widest, below(k));
  return widest;
}

FactorSize factor_size(const cholmod_factor& f) {
  FISSURE_CHECK(f.is_super && f.itype == CHOLMOD_INT, SolverError,
                "factor size: expected a supernodal CHOLMOD factor with int indices");
  const auto* super = static_cast<const int*>(f.super);
  const auto* pi = static_cast<const int*>(f.pi);
  FactorSize size;
  for (std::size_t k = 0; k < f.nsuper; ++k) {
    const double ncol = super[k + 1] - super[k], nrow = pi[k + 1] - pi[k];
    size.entries += ncol * nrow;
    // sum over i = 0 ... ncol - 1 of (nrow - i)^2
    const double last = nrow - ncol;
    auto squares = [](double m) { return m * (m + 1) * (2 * m + 1) / 6; };
    size.flops += squares(nrow) - squares(last);
  }
  return size;
}

}  // namespace fissure
