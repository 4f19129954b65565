// Applies (F + U V^T)^-1 given a solver for F, by the Sherman-Morrison-
// Woodbury identity (Golub & Van Loan, Matrix Computations, 4th ed., 2.1.4):
//   (F + U V^T)^-1 = F^-1 - W H^-1 V^T F^-1,  W = F^-1 U,  H = I + V^T W.
// Setting up costs one solve with F per term (the columns of W) and an LU of
// the r x r matrix H; each application then costs one solve with F (the
// caller's) plus two n x r products (correct()). Used to correct a reused
// factorization F for the contacts that changed state since the system it
// stands for (low_rank_update.h).
#pragma once

#include <Eigen/Dense>
#include <functional>

#include "core/linear/low_rank_update.h"

namespace fissure {

class LowRankCorrection {
 public:
  using SolveMany = std::function<void(const Eigen::MatrixXd&, Eigen::MatrixXd&)>;

  /// Prepares the correction of F by the terms (none: F alone); solve_f
  /// solves with F for the new terms' columns at once. Columns of terms the
  /// last set-up also had are kept (between open-close iterations most
  /// changed contacts stay changed). Returns the number of new columns.
  int set_up(const SolveMany& solve_f, const LowRankUpdate& terms, Eigen::Index n);
  /// F alone, until the next set-up.
  void clear() { rank_ = 0; }
  /// F has changed: no kept columns.
  void forget();
  int rank() const { return rank_; }
  /// H is far enough from singular for its solves to mean something.
  bool well_conditioned() const;

  /// z = F^-1 r on entry, (F + U V^T)^-1 r on return.
  void correct(Eigen::VectorXd& z) const;

  /// The kept columns (core/io/checkpoint.h): the next set-up reuses them,
  /// and a column solved again in another batch may differ in its last bit.
  template <class Self, class Archive>
  static void checkpoint(Self& self, Archive& a) {
    a.list("known_terms", self.known_terms_, [](auto& e, auto& t) {
      e("block_i", t.block_i);
      e("block_j", t.block_j);
      e("u", t.u);
      e("v", t.v);
    });
    a("known_w", self.known_w_);
  }

 private:
  /// V^T z
  Eigen::VectorXd project(const Eigen::VectorXd& z) const;

  int rank_ = 0;
  LowRankUpdate known_terms_;  ///< of the last set-up
  /// F^-1 U, n x r, in float: F^-1 is applied in float (the reused
  /// factor's solves), and W is the largest part of a correction (n x 256
  /// at most: 61 MB at 10,000 blocks).
  Eigen::MatrixXf known_w_;
  Eigen::PartialPivLU<Eigen::MatrixXd> h_;
};

}  // namespace fissure
