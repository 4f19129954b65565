// Sparse matrix of dense 6x6 blocks with a symmetric pattern (DDA: six
// unknowns per block; only contacts create off-diagonal blocks, theory.md
// 1.1). The values are symmetric except for implicit friction terms. Block-row
// CSR with both triangles stored, so that assembly and products touch
// contiguous memory; the pattern is fixed for a time step and values are
// reset per open-close iteration.
#pragma once

#include <Eigen/Core>
#include <Eigen/StdVector>
#include <span>
#include <utility>
#include <vector>

namespace fissure {

using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Matrix6List = std::vector<Matrix6, Eigen::aligned_allocator<Matrix6>>;

class BlockSparseMatrix {
 public:
  /// Pattern: the diagonal plus blocks (i, j) and (j, i) for each listed pair.
  void set_pattern(int n_blocks, std::span<const std::pair<int, int>> pairs);

  int n_blocks() const { return n_; }
  int n_rows() const { return 6 * n_; }
  int n_stored_blocks() const { return static_cast<int>(values_.size()); }

  /// Storage index of block (i, j), -1 if not in the pattern.
  int find(int i, int j) const;
  int diagonal_index(int i) const { return diag_[i]; }

  Matrix6& value(int index) { return values_[index]; }
  const Matrix6& value(int index) const { return values_[index]; }

  /// Adds A to block (i, j) and A^T to block (j, i); i != j.
  void add_pair(int index_ij, int index_ji, const Matrix6& a);
  /// Adds A to one stored block (unsymmetric terms).
  void add(int index, const Matrix6& a) { values_[index] += a; }

  void set_zero();

  /// y = A x
  void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;

  /// The inverses of the 6x6 diagonal blocks. Explicit inverses: applying
  /// one is a 6x6 product, several times cheaper than two triangular solves.
  /// Throws SolverError when a diagonal block is singular.
  void invert_diagonal_blocks(Matrix6List& inverses) const;

  std::span<const int> row_start() const { return row_start_; }
  std::span<const int> columns() const { return col_; }

  /// Pattern and values (core/io/checkpoint.h).
  template <class Self, class Archive>
  static void checkpoint(Self& self, Archive& a) {
    a("n_blocks", self.n_);
    a("row_start", self.row_start_);
    a("columns", self.col_);
    a("diagonal", self.diag_);
    a("values", self.values_);
  }

 private:
  int n_ = 0;
  std::vector<int> row_start_;  ///< size n + 1
  std::vector<int> col_;        ///< block column per stored block, sorted per row
  std::vector<int> diag_;       ///< storage index of (i, i)
  Matrix6List values_;
};

}  // namespace fissure
