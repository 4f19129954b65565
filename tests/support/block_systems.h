// Penalty-coupled 6 x 6 block systems shaped like the DDA's (tests of the
// linear solvers, benchmarks/sparse_lu): unit mass on the diagonal, a fixed
// symmetric positive definite spring between each listed pair of blocks, and
// optionally an unsymmetric friction term per pair, a force along t
// proportional to the relative displacement along n (as implicit sliding
// friction adds: zero on rigid motions).
#pragma once

#include <utility>
#include <vector>

#include "core/linear/block_sparse_matrix.h"
#include "core/linear/low_rank_update.h"

namespace fissure::testing {

struct BlockSystem {
  BlockSparseMatrix a;
  BlockSparseMatrix spd;  ///< a without the friction terms
  bool friction = false;
  Eigen::VectorXd b;
  bool symmetric() const { return !friction; }
};

/// `spring` scales the couplings (times the mass), `friction` the friction
/// terms (times the springs; 0: a symmetric system).
BlockSystem block_system(int n_blocks, const std::vector<std::pair<int, int>>& pairs, double spring,
                         double friction);

/// |b - A x| / |b|
double relative_residual(const BlockSparseMatrix& a, const Eigen::VectorXd& b,
                         const Eigen::VectorXd& x);

/// The update's terms summed into a dense n x n matrix, U V^T.
Eigen::MatrixXd dense(const LowRankUpdate& terms, Eigen::Index n);

/// Pairs of an nx x ny grid of blocks (four neighbours each).
std::vector<std::pair<int, int>> grid_pairs(int nx, int ny);

/// Pairs of a running-bond brick wall of `courses` x `bricks`: each brick
/// touches two neighbours in its course and two above and two below.
std::vector<std::pair<int, int>> running_bond_pairs(int bricks, int courses);

}  // namespace fissure::testing
