// Scalar CSC copy of a BlockSparseMatrix for the SuiteSparse factorizations:
// the pattern is built once (per block pattern) together with a map from each
// scalar entry to its 6x6 block and position, so that refreshing the values
// in every open-close iteration is a single gather.
#pragma once

#include <Eigen/SparseCore>
#include <vector>

#include "core/linear/block_sparse_matrix.h"

namespace fissure {

class ScalarCopy {
 public:
  /// lower_only: the lower triangle (Cholesky); else the full matrix (LU).
  void build_pattern(const BlockSparseMatrix& a, bool lower_only);
  void copy_values(const BlockSparseMatrix& a);
  const Eigen::SparseMatrix<double>& matrix() const { return matrix_; }
  bool empty() const { return source_.empty() && matrix_.rows() == 0; }

 private:
  struct Source {
    int block, row, col;
  };
  Eigen::SparseMatrix<double> matrix_;
  std::vector<Source> source_;
};

}  // namespace fissure
