#include "tests/support/block_systems.h"

#include <cmath>

namespace fissure::testing {

BlockSystem block_system(int n_blocks, const std::vector<std::pair<int, int>>& pairs, double spring,
                         double friction) {
  BlockSystem s;
  s.spd.set_pattern(n_blocks, pairs);
  // A fixed symmetric positive definite spring coupling the six unknowns.
  Matrix6 g = Matrix6::Identity();
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c) g(r, c) += 0.1 * std::sin(1.0 + r + 7.0 * c);
  const Matrix6 k = spring * g * g.transpose();
  BlockSparseMatrix& m = s.spd;
  for (int i = 0; i < n_blocks; ++i) m.value(m.diagonal_index(i)) = Matrix6::Identity();  // mass
  for (const auto& [i, j] : pairs) {
    m.value(m.diagonal_index(i)) += k;
    m.value(m.diagonal_index(j)) += k;
    m.add_pair(m.find(i, j), m.find(j, i), -k);
  }
  s.a = s.spd;
  s.friction = friction != 0;
  const Matrix6 f = friction * spring * g.col(1) * g.col(0).transpose();  // t n^T
  for (const auto& [i, j] : pairs) {
    s.a.add(s.a.diagonal_index(i), f);
    s.a.add(s.a.diagonal_index(j), f);
    s.a.add(s.a.find(i, j), -f);
    s.a.add(s.a.find(j, i), -f);
  }
  s.b.resize(6 * n_blocks);
  for (int r = 0; r < 6 * n_blocks; ++r) s.b(r) = std::cos(0.37 * r) + (r % 6 == 1 ? -2.0 : 0.0);
  return s;
}

std::vector<std::pair<int, int>> grid_pairs(int nx, int ny) {
  std::vector<std::pair<int, int>> pairs;
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x) {
      if (x + 1 < nx) pairs.emplace_back(y * nx + x, y * nx + x + 1);
      if (y + 1 < ny) pairs.emplace_back(y * nx + x, (y + 1) * nx + x);
    }
  return pairs;
}

std::vector<std::pair<int, int>> running_bond_pairs(int bricks, int courses) {
  std::vector<std::pair<int, int>> pairs;
  for (int y = 0; y < courses; ++y)
    for (int x = 0; x < bricks; ++x) {
      const int i = y * bricks + x;
      if (x + 1 < bricks) pairs.emplace_back(i, i + 1);
      if (y + 1 == courses) continue;
      pairs.emplace_back(i, i + bricks);
      const int offset = y % 2 == 0 ? x - 1 : x + 1;  // the course above is offset
      if (offset >= 0 && offset < bricks) pairs.emplace_back(i, (y + 1) * bricks + offset);
    }
  return pairs;
}

double relative_residual(const BlockSparseMatrix& a, const Eigen::VectorXd& b,
                         const Eigen::VectorXd& x) {
  Eigen::VectorXd ax;
  a.multiply(x, ax);
  return (b - ax).norm() / b.norm();
}

Eigen::MatrixXd dense(const LowRankUpdate& terms, Eigen::Index n) {
  Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(n, n);
  for (const RankOneTerm& t : terms) {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(n), v = u;
    for (int side = 0; side < 2; ++side) {
      const int block = side == 0 ? t.block_i : t.block_j;
      if (block < 0) continue;
      u.segment<6>(6 * block) = t.u.segment<6>(6 * side);
      v.segment<6>(6 * block) = t.v.segment<6>(6 * side);
    }
    sum += u * v.transpose();
  }
  return sum;
}

}  // namespace fissure::testing
