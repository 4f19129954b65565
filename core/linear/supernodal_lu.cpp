#include "core/linear/supernodal_lu.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "core/base/errors.h"

namespace fissure {

namespace {
using PanelMap = Eigen::Map<Eigen::MatrixXf, 0, Eigen::OuterStride<>>;
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
    return ~(st.upper_start[k] + static_cast<long>(at - ncol) * ncol + (c - first));
  };
  const auto start = a.row_start();
  const auto cols = a.columns();
  destination_.resize(36 * static_cast<std::size_t>(a.n_stored_blocks()));
  for (int I = 0; I < a.n_blocks(); ++I)
    for (int b = start[I]; b < start[I + 1]; ++b)
      for (int c = 0; c < 6; ++c)
        for (int r = 0; r < 6; ++r)  // Matrix6 is column-major
          destination_[36 * b + 6 * c + r] = offset(position[6 * I + r], position[6 * cols[b] + c]);

  map_updates();
  pivots_.resize(n);
}

void SupernodalLu::factorize(const BlockSparseMatrix& a) {
  FISSURE_CHECK(destination_.size() == 36 * static_cast<std::size_t>(a.n_stored_blocks()),
                SolverError, "supernodal LU: factorize before analyze");
  // assign, not fill: the panels may have been handed over (take_panels).
  lower_.assign(structure_.lower_start.back(), 0.0f);
  upper_.assign(structure_.upper_start.back(), 0.0f);
  for (int b = 0; b < a.n_stored_blocks(); ++b) {
    const double* v = a.value(b).data();
    const long* d = destination_.data() + 36 * static_cast<std::size_t>(b);
    for (int e = 0; e < 36; ++e)
      (d[e] >= 0 ? lower_[d[e]] : upper_[~d[e]]) = static_cast<float>(v[e]);
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
  Eigen::Ref<Eigen::MatrixXf> diagonal = panel.topRows(ncol);
  const Eigen::PartialPivLU<Eigen::Ref<Eigen::MatrixXf>> lu(diagonal);  // in place
  for (int i = 0; i < ncol; ++i) {
    const float pivot = diagonal(i, i);
    FISSURE_CHECK(std::isfinite(pivot) && pivot != 0, SolverError,
                  "supernodal LU: zero pivot in column "
                      << first + i << " (the block system matrix is singular)");
    pivots_[first + i] = lu.permutationP().indices()[i];
  }
  if (below == 0) return;
  // L_b = A_bk U_D^-1, a column at a time: a matrix-vector product per
  // column over all rows below. Eigen's blocked triangular solves from the
  // right (this one and U's), with a few dozen columns, took a fifth of the
  // factorization.
  auto solved = panel.bottomRows(below);
  for (int j = 0; j < ncol; ++j) {
    if (j > 0) solved.col(j).noalias() -= solved.leftCols(j) * diagonal.col(j).head(j);
    solved.col(j) /= diagonal(j, j);
  }
  // U_kb = L_D^-1 P_k A_kb, as U_kb^T = (P_k A_kb)^T L_D^-T by the same
  // column loop. The panel held A_kb (ncol x below, as the updates reached
  // it) and now takes U_kb^T (below x ncol, as the solves read it).
  const PanelMap accumulated(upper_.data() + st.upper_start[k], ncol, below,
                             Eigen::OuterStride<>(ncol));
  transposed_.resize(static_cast<std::size_t>(ncol) * below);
  Eigen::Map<Eigen::MatrixXf> transposed(transposed_.data(), below, ncol);
  for (int i = 0; i < ncol; ++i)
    transposed.col(pivots_[first + i]) = accumulated.row(i).transpose();
  for (int j = 1; j < ncol; ++j)
    transposed.col(j).noalias() -= transposed.leftCols(j) * diagonal.row(j).head(j).transpose();
  std::copy(transposed_.begin(), transposed_.end(), upper_.begin() + st.upper_start[k]);
}

void SupernodalLu::map_updates() {
  const SupernodalStructure& st = structure_;
  run_start_.assign(1, 0);
  runs_.clear();
  segments_.clear();
  std::vector<int> map;
  for (int k = 0; k < st.count(); ++k) {
    const int below = st.below(k);
    const int* rows = st.rows_below(k);
    for (int j0 = 0; j0 < below;) {
      const int t = owner_[rows[j0]], t_first = st.first(t), t_ncol = st.ncol(t);
      const int t_nrow = st.nrow(t);
      int j1 = j0;
      while (j1 < below && rows[j1] < t_first + t_ncol) ++j1;
      const int w = j1 - j0, m = below - j0;
      const int* t_rows = st.rows_of(t);
      map.resize(m);
      for (int i = 0, p = 0; i < m; ++i) {  // t's rows contain k's rows from j0 on
        while (p < t_nrow && t_rows[p] != rows[j0 + i]) ++p;
        FISSURE_CHECK(p < t_nrow, SolverError,
                      "supernodal LU: the analysis is not a supernodal elimination structure");
        map[i] = p;
      }
      // Maximal stretches of rows consecutive in both, split where t's
      // columns end (i = w).
      Run run{t, j0, static_cast<int>(segments_.size()), 0, 0};
      for (int i = 0; i < m;) {
        if (i == w) run.columns_end = static_cast<int>(segments_.size());
        int end = i + 1;
        while (end < m && end != w && map[end] == map[end - 1] + 1) ++end;
        segments_.push_back({i, map[i], end - i});
        i = end;
      }
      run.segments_end = static_cast<int>(segments_.size());
      if (w == m) run.columns_end = run.segments_end;
      runs_.push_back(run);
      j0 = j1;
    }
    run_start_.push_back(static_cast<int>(runs_.size()));
  }
}

namespace {
/// to[0 ... n) -= from[0 ... n)
inline void subtract(float* __restrict to, const float* __restrict from, int n) {
  for (int i = 0; i < n; ++i) to[i] -= from[i];
}
}  // namespace

void SupernodalLu::update_ancestors(int k) {
  const SupernodalStructure& st = structure_;
  const int ncol = st.ncol(k), nrow = st.nrow(k), below = nrow - ncol;
  if (below == 0) return;
  const PanelMap panel(lower_.data() + st.lower_start[k], nrow, ncol, Eigen::OuterStride<>(nrow));
  const PanelMap upper(upper_.data() + st.upper_start[k], below, ncol, Eigen::OuterStride<>(below));
  // The whole update C = L_b U_kb in one product; its rows and columns are
  // the rows below. They fall into runs of columns of one ancestor t each
  // (map_updates). The run j0 ... j0 + w - 1 receives C(i, j) for its
  // columns j and the rows i >= j into t's lower panel (columns of C into
  // columns of L), and C(j, i) for i > j into t's diagonal block or its
  // upper panel, which holds A_tb by columns until t is factorized (columns
  // of C into columns of U). Both are subtracted as stretches of rows
  // consecutive in k and in t.
  work_.resize(static_cast<std::size_t>(below) * below);
  Eigen::Map<Eigen::MatrixXf> update(work_.data(), below, below);
  update.noalias() = panel.bottomRows(below) * upper.transpose();
  for (int r = run_start_[k]; r < run_start_[k + 1]; ++r) {
    const Run& run = runs_[r];
    const Segment* const run_begin = segments_.data() + run.segments_begin;
    const Segment* const columns_end = segments_.data() + run.columns_end;
    const Segment* const run_end = segments_.data() + run.segments_end;
    const int t = run.ancestor, t_ncol = st.ncol(t), t_nrow = st.nrow(t), j0 = run.first;
    float* const t_lower = lower_.data() + st.lower_start[t];
    float* const t_upper = upper_.data() + st.upper_start[t];
    // L: C(i, c) for i >= c into column p(c) of t's lower panel.
    for (const Segment* s = run_begin; s != columns_end; ++s)
      for (int c = s->i; c < s->i + s->length; ++c) {
        float* const to = t_lower + static_cast<long>(s->p + c - s->i) * t_nrow;
        const float* const from = &update(j0, j0 + c);
        for (const Segment* q = s; q != run_end; ++q) {
          const int start = std::max(q->i, c);
          subtract(to + q->p + start - q->i, from + start, q->i + q->length - start);
        }
      }
    // U: C(c, i) for c < i into column p(i) of t's diagonal block (p(i) <
    // t_ncol, i < w) or of its upper panel.
    for (const Segment* q = run_begin; q != run_end; ++q)
      for (int i = q->i; i < q->i + q->length; ++i) {
        const int p = q->p + i - q->i;
        float* const to = p < t_ncol ? t_lower + static_cast<long>(p) * t_nrow
                                     : t_upper + static_cast<long>(p - t_ncol) * t_ncol;
        const float* const from = &update(j0, j0 + i);
        for (const Segment* s = run_begin; s != columns_end && s->i < i; ++s)
          subtract(to + s->p, from + s->i, std::min(s->length, i - s->i));
      }
  }
}

}  // namespace fissure
