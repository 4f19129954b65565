// A single-precision copy of a CHOLMOD supernodal Cholesky factor, for use as
// a preconditioner. Applying a factor is memory-bound: the forward and the
// backward substitution each stream the whole factor once (47 MB at 10,000
// DDA blocks, more than the last-level cache). GMRES only needs the
// preconditioner to be close to A^-1, and it already uses a factor of an
// earlier system; rounding that factor to float (relative error 6e-8) halves
// the bytes moved per iteration and left the GMRES iteration counts of the
// DDA walls unchanged (docs/dda.md section 5). The factorization itself
// stays in double.
#pragma once

#include <cholmod.h>

#include <Eigen/Core>
#include <vector>

namespace fissure {

class SinglePrecisionFactor {
 public:
  /// Copies a supernodal LL^T factor (int indices, real), rounding to float.
  void copy(const cholmod_factor& factor);

  /// z = (P^T L L^T P)^-1 r, computed in single precision.
  void solve(Eigen::Ref<const Eigen::VectorXd> r, Eigen::VectorXd& z) const;

 private:
  using Panel = Eigen::Map<const Eigen::MatrixXf, 0, Eigen::OuterStride<>>;
  /// Supernode k: columns first ... first + ncol - 1 and a dense panel of
  /// ncol + below rows (its own columns' triangle, then the rows below).
  struct Supernode {
    int first, ncol, below;
    Panel panel;
    const int* rows_below;
  };
  Supernode supernode(std::size_t k) const;

  std::vector<int> perm_;          ///< pivot k is unknown perm_[k]
  std::vector<int> super_;         ///< first column of each supernode
  std::vector<int> row_start_;     ///< into rows_, per supernode
  std::vector<long> value_start_;  ///< into values_, per supernode
  std::vector<int> rows_;          ///< row indices of each supernode
  std::vector<float> values_;      ///< column-major nrow x ncol per supernode
  mutable Eigen::VectorXf x_, work_;
};

}  // namespace fissure
