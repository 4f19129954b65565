// The supernodal structure of a sparse Cholesky analysis (CHOLMOD), copied
// out of the cholmod_factor so that Fissure's own supernodal factors (the
// single-precision copy, the LU of a matrix with a symmetric pattern) can be
// built and applied on it. Supernode k owns the consecutive columns first(k)
// ... first(k) + ncol(k) - 1 of the permuted matrix; its rows are those
// columns followed by the rows below them, sorted, and its lower panel is a
// dense nrow x ncol column-major block. The supernodes are ordered children
// before parents (a postorder of the elimination tree).
#pragma once

#include <cholmod.h>

#include <vector>

namespace fissure {

struct SupernodalStructure {
  std::vector<int> perm;          ///< pivot k is unknown perm[k]
  std::vector<int> super;         ///< first column of each supernode, then n
  std::vector<int> row_start;     ///< into rows, per supernode, then the end
  std::vector<int> rows;          ///< each supernode's columns, then its rows below
  std::vector<long> lower_start;  ///< offset of each nrow x ncol lower panel, then the end
  std::vector<long> upper_start;  ///< offset of each below x ncol panel (LU), then the end

  /// From a supernodal factor, symbolic or numeric, with int indices.
  static SupernodalStructure of(const cholmod_factor& factor);

  int n() const { return static_cast<int>(perm.size()); }
  int count() const { return static_cast<int>(super.size()) - 1; }
  int first(int k) const { return super[k]; }
  int ncol(int k) const { return super[k + 1] - super[k]; }
  int nrow(int k) const { return row_start[k + 1] - row_start[k]; }
  int below(int k) const { return nrow(k) - ncol(k); }
  const int* rows_of(int k) const { return rows.data() + row_start[k]; }
  const int* rows_below(int k) const { return rows_of(k) + ncol(k); }
  int widest_below() const;
};

/// The size of a supernodal Cholesky factor: stored entries of L (its lower
/// panels) and the operations of computing it, sum over columns of c_j^2
/// where c_j counts the column's entries on and below the diagonal (George
/// and Liu, Computer Solution of Large Sparse Positive Definite Systems,
/// 1981, section 2.2; to leading order). An LU on the same structure has
/// about twice of both.
struct FactorSize {
  double entries = 0;
  double flops = 0;
};
FactorSize factor_size(const cholmod_factor& factor);

}  // namespace fissure
