#include "core/linear/block_sparse_matrix.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "core/base/errors.h"

namespace fissure {

void BlockSparseMatrix::set_pattern(int n_blocks, std::span<const std::pair<int, int>> pairs) {
  n_ = n_blocks;
  // Count entries per row (diagonal + both orientations), then fill (CSR).
  std::vector<int> count(n_ + 1, 1);
  for (const auto& [i, j] : pairs) {
    ++count[i];
    ++count[j];
  }
  row_start_.assign(n_ + 1, 0);
  for (int i = 0; i < n_; ++i) row_start_[i + 1] = row_start_[i] + count[i];
  col_.resize(row_start_[n_]);
  std::vector<int> fill(row_start_.begin(), row_start_.end() - 1);
  for (int i = 0; i < n_; ++i) col_[fill[i]++] = i;
  for (const auto& [i, j] : pairs) {
    col_[fill[i]++] = j;
    col_[fill[j]++] = i;
  }
  // Sort each row and remove duplicate pairs.
  std::vector<int> new_start(n_ + 1, 0);
  int out = 0;
  for (int i = 0; i < n_; ++i) {
    auto first = col_.begin() + row_start_[i], last = col_.begin() + row_start_[i + 1];
    std::sort(first, last);
    const auto end = std::unique(first, last);
    new_start[i] = out;
    for (auto it = first; it != end; ++it) col_[out++] = *it;
  }
  new_start[n_] = out;
  col_.resize(out);
  row_start_ = std::move(new_start);
  diag_.resize(n_);
  for (int i = 0; i < n_; ++i) diag_[i] = find(i, i);
  values_.assign(col_.size(), Matrix6::Zero());
}

int BlockSparseMatrix::find(int i, int j) const {
  const auto first = col_.begin() + row_start_[i], last = col_.begin() + row_start_[i + 1];
  const auto it = std::lower_bound(first, last, j);
  return (it != last && *it == j) ? static_cast<int>(it - col_.begin()) : -1;
}

void BlockSparseMatrix::add_pair(int index_ij, int index_ji, const Matrix6& a) {
  values_[index_ij] += a;
  values_[index_ji] += a.transpose();
}

void BlockSparseMatrix::set_zero() {
  for (Matrix6& v : values_) v.setZero();
}

void BlockSparseMatrix::multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  y.resize(6 * n_);
  for (int i = 0; i < n_; ++i) {
    Eigen::Matrix<double, 6, 1> acc = Eigen::Matrix<double, 6, 1>::Zero();
    for (int k = row_start_[i]; k < row_start_[i + 1]; ++k)
      acc.noalias() += values_[k] * x.segment<6>(6 * col_[k]);
    y.segment<6>(6 * i) = acc;
  }
}

void BlockSparseMatrix::invert_diagonal_blocks(Matrix6List& inverses) const {
  inverses.resize(n_);
  for (int i = 0; i < n_; ++i) {
    const Eigen::PartialPivLU<Matrix6> lu(values_[diag_[i]]);
    const double det = lu.determinant();
    FISSURE_CHECK(det != 0 && std::isfinite(det), SolverError,
                  "the diagonal block of unknown block "
                      << i
                      << " of the block system is singular (a free block without mass or "
                         "stiffness, or a non-physical material?)");
    inverses[i] = lu.inverse();
  }
}

}  // namespace fissure
