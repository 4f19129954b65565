#include "core/linear/supernodal_lu.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "core/base/errors.h"

namespace fissure {

namespace {
using PanelMap = Eigen::Map<Eigen::MatrixXd, 0, Eigen::OuterStride<>>;
}  // namespace

void SupernodalLu::analyze(const cholmod_factor& symbolic, const BlockSparseMatrix& a) {
  structure_ = SupernodalStructure::of(symbolic);
  const SupernodalStructure& st = structure_;
  const int n = st.n();
  FISSURE_CHECK(n == a.n_rows(), SolverError, "supernodal LU: analysis of another matrix size");
  std::vector<int> position(n);  // permuted index of each unknown
  for (int k = 0; k < n; ++k) position[st.perm[k]] = k;
  owner_.resize(n);
  for (int k = 0; k < st.count(); ++k)
    std::fill(owner_.begin() + st.first(k), owner_.begin() + st.first(k) + st.ncol(k), k);

  // Entry (i, j) of the permuted A belongs to the supernode of column
  // min(i, j): its lower panel when i >= j, else its upper panel (the
  // diagonal block sits in the lower panel, both triangles).
  const auto offset = [&](int i, int j) -> long {
    const int c = std::min(i, j), other = std::max(i, j);
    const int k = owner_[c], first = st.first(k), ncol = st.ncol(k), nrow = st.nrow(k);
    const int* rows = st.rows_of(k);
    const int r = static_cast<int>(std::lower_bound(rows + ncol, rows + nrow, other) - rows);
    const int at = other < first + ncol ? other - first : r;
    FISSURE_CHECK(at < nrow && rows[at] == other, SolverError,
                  "supernodal LU: an entry of A lies outside the analysed pattern");
    if (i >= j || at < ncol) {  // lower panel, or the diagonal block's upper triangle
      const int row = i >= j ? at : c - first, col = i >= j ? c - first : at;
      return st.lower_start[k] + static_cast<long>(col) * nrow + row;
    }
    return ~(st.upper_start[k] + static_cast<long>(c - first) * (nrow - ncol) + (at - ncol));
  };
  const auto start = a.row_start();
  const auto cols = a.columns();
  destination_.resize(36 * static_cast<std::size_t>(a.n_stored_blocks()));
  for (int I = 0; I < a.n_blocks(); ++I)
    for (int b = start[I]; b < start[I + 1]; ++b)
      for (int c = 0; c < 6; ++c)
        for (int r = 0; r < 6; ++r)  // Matrix6 is column-major
          destination_[36 * b + 6 * c + r] = offset(position[6 * I + r], position[6 * cols[b] + c]);

  lower_.assign(st.lower_start.back(), 0.0);
  upper_.assign(st.upper_start.back(), 0.0);
  pivots_.resize(n);
  map_.resize(st.widest_below());
}

void SupernodalLu::factorize(const BlockSparseMatrix& a) {
  FISSURE_CHECK(destination_.size() == 36 * static_cast<std::size_t>(a.n_stored_blocks()),
                SolverError, "supernodal LU: factorize before analyze");
  std::fill(lower_.begin(), lower_.end(), 0.0);
  std::fill(upper_.begin(), upper_.end(), 0.0);
  for (int b = 0; b < a.n_stored_blocks(); ++b) {
    const double* v = a.value(b).data();
    const long* d = destination_.data() + 36 * static_cast<std::size_t>(b);
    for (int e = 0; e < 36; ++e) (d[e] >= 0 ? lower_[d[e]] : upper_[~d[e]]) = v[e];
  }
  for (int k = 0; k < structure_.count(); ++k) {
    factorize_supernode(k);
    update_ancestors(k);
  }
}

void SupernodalLu::factorize_supernode(int k) {
  const SupernodalStructure& st = structure_;
  const int first = st.first(k), ncol = st.ncol(k), nrow = st.nrow(k), below = nrow - ncol;
  PanelMap panel(lower_.data() + st.lower_start[k], nrow, ncol, Eigen::OuterStride<>(nrow));
  PanelMap upper(upper_.data() + st.upper_start[k], below, ncol,
                 Eigen::OuterStride<>(std::max(below, 1)));
  Eigen::Ref<Eigen::MatrixXd> diagonal = panel.topRows(ncol);
  const Eigen::PartialPivLU<Eigen::Ref<Eigen::MatrixXd>> lu(diagonal);  // in place
  for (int i = 0; i < ncol; ++i) {
    const double pivot = diagonal(i, i);
    FISSURE_CHECK(std::isfinite(pivot) && pivot != 0, SolverError,
                  "supernodal LU: zero pivot in column " << first + i
                                                         << " (the DDA system matrix is singular)");
    pivots_[first + i] = lu.permutationP().indices()[i];
  }
  if (below == 0) return;
  // L_b = A_bk U_D^-1
  diagonal.triangularView<Eigen::Upper>().solveInPlace<Eigen::OnTheRight>(panel.bottomRows(below));
  // U_kb^T = (P_k A_kb)^T L_D^-T: the rows of A_kb are the columns of the panel.
  permuted_.resize(static_cast<std::size_t>(below) * ncol);
  Eigen::Map<Eigen::MatrixXd> copy(permuted_.data(), below, ncol);
  copy = upper;
  for (int i = 0; i < ncol; ++i) upper.col(pivots_[first + i]) = copy.col(i);
  diagonal.triangularView<Eigen::UnitLower>().transpose().solveInPlace<Eigen::OnTheRight>(upper);
}

void SupernodalLu::update_ancestors(int k) {
  const SupernodalStructure& st = structure_;
  const int ncol = st.ncol(k), nrow = st.nrow(k), below = nrow - ncol;
  if (below == 0) return;
  const PanelMap panel(lower_.data() + st.lower_start[k], nrow, ncol, Eigen::OuterStride<>(nrow));
  const auto lower = panel.bottomRows(below);
  const PanelMap upper(upper_.data() + st.upper_start[k], below, ncol, Eigen::OuterStride<>(below));
  const int* rows = st.rows_below(k);
  // The whole update C = L_b U_kb in one product; its rows and columns are
  // the rows below. They fall into runs of columns of one ancestor t each.
  // The run j0 ... j1 - 1 receives, for its columns j, C(i, j) for the rows
  // i >= j into t's lower panel and C(j, i) for i > j into t's diagonal
  // block or upper panel.
  work_.resize(static_cast<std::size_t>(below) * below);
  Eigen::Map<Eigen::MatrixXd> update(work_.data(), below, below);
  update.noalias() = lower * upper.transpose();
  for (int j0 = 0; j0 < below;) {
    const int t = owner_[rows[j0]], t_first = st.first(t), t_ncol = st.ncol(t);
    const int t_nrow = st.nrow(t), t_below = t_nrow - t_ncol;
    int j1 = j0;
    while (j1 < below && rows[j1] < t_first + t_ncol) ++j1;
    const int w = j1 - j0, m = below - j0;
    const int* t_rows = st.rows_of(t);
    for (int i = 0, p = 0; i < m; ++i) {  // t's rows contain k's rows from j0 on
      while (p < t_nrow && t_rows[p] != rows[j0 + i]) ++p;
      FISSURE_CHECK(p < t_nrow, SolverError,
                    "supernodal LU: the analysis is not a supernodal elimination structure");
      map_[i] = p;
    }
    const auto cl = update.bottomRightCorner(m, m).leftCols(w);
    const auto cu = update.bottomRightCorner(m, m).topRows(w).transpose();
    PanelMap t_panel(lower_.data() + st.lower_start[t], t_nrow, t_ncol,
                     Eigen::OuterStride<>(t_nrow));
    PanelMap t_upper(upper_.data() + st.upper_start[t], t_below, t_ncol,
                     Eigen::OuterStride<>(std::max(t_below, 1)));
    for (int c = 0; c < w; ++c) {
      const int col = map_[c];  // a column of t: its local index
      for (int i = c; i < m; ++i) t_panel(map_[i], col) -= cl(i, c);
      for (int i = c + 1; i < m; ++i) {
        const int p = map_[i];
        if (p < t_ncol)
          t_panel(col, p) -= cu(i, c);
        else
          t_upper(p - t_ncol, col) -= cu(i, c);
      }
    }
    j0 = j1;
  }
}

}  // namespace fissure
