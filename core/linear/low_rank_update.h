// How the system of an open-close iteration differs from the step's first
// one: a sum of rank-one terms u v^T, each nonzero on the rows and columns of
// (at most) two blocks. A contact that changed state since the first solve
// adds or removes its springs (normal, shear) and its friction terms, each a
// rank-one 12 x 12 term on its two blocks (contact_springs.h), so that a few
// changed contacts change A by a matrix of low rank.
#pragma once

#include <Eigen/Core>
#include <Eigen/StdVector>
#include <vector>

namespace fissure {

using Vector12 = Eigen::Matrix<double, 12, 1>;

/// A += u v^T; u and v hold block i's six entries, then block j's (a block
/// of -1 has no unknowns and its entries are ignored).
struct RankOneTerm {
  int block_i = -1, block_j = -1;
  Vector12 u = Vector12::Zero(), v = Vector12::Zero();
  bool operator==(const RankOneTerm&) const = default;
};

using LowRankUpdate = std::vector<RankOneTerm, Eigen::aligned_allocator<RankOneTerm>>;

}  // namespace fissure
