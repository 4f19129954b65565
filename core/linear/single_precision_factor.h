// A single-precision supernodal factor, for use as a preconditioner: a copy
// of CHOLMOD's Cholesky factor L L^T of S, or the panels of Fissure's LU of A
// on the same structure (supernodal_lu.h, computed in float). Applying a factor is
// memory-bound: the forward and the backward substitution each stream one
// triangle once (23.6 MB each at 10,000 DDA blocks in float; together more
// than the last-level cache). GMRES only needs the preconditioner to be close
// to A^-1, and it already uses a factor of an earlier system; rounding that
// factor to float (relative error 6e-8) halves the bytes moved per iteration
// and left the GMRES iteration counts of the DDA walls unchanged
// (docs/dda.md section 5).
#pragma once

#include <cholmod.h>

#include <Eigen/Core>
#include <vector>

#include "core/linear/supernodal_structure.h"

namespace fissure {

class SupernodalLu;

class SinglePrecisionFactor {
 public:
  /// Copies a supernodal LL^T factor (int indices, real), rounding to float.
  void copy(const cholmod_factor& factor);
  /// Takes over the panels of a supernodal LU factor (computed in float).
  void take(SupernodalLu& factor);

  /// z = A^-1 r with the copied factor, computed in single precision.
  void solve(Eigen::Ref<const Eigen::VectorXd> r, Eigen::VectorXd& z) const;
  /// Z = A^-1 R for several right-hand sides at once: each panel is
  /// streamed once for all of them (matrix products instead of
  /// matrix-vector ones).
  void solve(const Eigen::MatrixXd& r, Eigen::MatrixXd& z) const;

 private:
  using Panel = Eigen::Map<const Eigen::MatrixXf, 0, Eigen::OuterStride<>>;
  Panel lower_panel(int k) const;
  Panel upper_panel(int k) const;  ///< LU: U_kb^T; Cholesky: L_b
  void resize_work();
  using RowMajorMatrixXf = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  template <class Dense>
  void substitute(Dense& x, Dense& work, Dense& scratch) const;

  bool lu_ = false;
  SupernodalStructure structure_;
  std::vector<float> lower_, upper_;
  std::vector<int> pivots_;  ///< LU only (supernodal_lu.h)
  mutable Eigen::VectorXf x_, work_, own_;
};

}  // namespace fissure
