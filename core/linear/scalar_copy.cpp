#include "core/linear/scalar_copy.h"

namespace fissure {

void ScalarCopy::build_pattern(const BlockSparseMatrix& a, bool lower_only) {
  // Column-major: scalar column 6J + b holds, for every stored block (J, I) of
  // block row J (the pattern is symmetric), the entries of block (I, J) =
  // value(J, I)^T in rows 6I + r. Block rows are sorted, so rows increase.
  const int n = a.n_blocks();
  const auto start = a.row_start();
  const auto cols = a.columns();
  std::vector<int> outer(6 * n + 1, 0);
  std::vector<int> inner;
  source_.clear();
  for (int J = 0; J < n; ++J) {
    for (int b = 0; b < 6; ++b) {
      outer[6 * J + b] = static_cast<int>(inner.size());
      for (int k = start[J]; k < start[J + 1]; ++k) {
        const int I = cols[k];
        if (lower_only && I < J) continue;
        // Entry (6I + r, 6J + b) is block (I, J)(r, b); block (I, J) is stored
        // in row I, found by symmetry of the pattern.
        const int ij = a.find(I, J);
        for (int r = (lower_only && I == J ? b : 0); r < 6; ++r) {
          inner.push_back(6 * I + r);
          source_.push_back({ij, r, b});
        }
      }
    }
  }
  outer[6 * n] = static_cast<int>(inner.size());
  matrix_ = Eigen::SparseMatrix<double>(6 * n, 6 * n);
  matrix_.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
  std::copy(outer.begin(), outer.end(), matrix_.outerIndexPtr());
  std::copy(inner.begin(), inner.end(), matrix_.innerIndexPtr());
}

void ScalarCopy::copy_values(const BlockSparseMatrix& a) {
  double* v = matrix_.valuePtr();
  for (std::size_t s = 0; s < source_.size(); ++s)
    v[s] = a.value(source_[s].block)(source_[s].row, source_[s].col);
}

}  // namespace fissure
