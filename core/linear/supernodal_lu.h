// LU factorization of a DDA system matrix A = S + F on the supernodal
// structure of the Cholesky analysis of its pattern. Implicit sliding friction
// (F) makes A unsymmetric but leaves its pattern symmetric, so an LU without
// pivoting across supernodes has exactly the fill of the Cholesky factor of S:
// the same supernodes and dense panels, one lower panel (L) and one upper
// panel (U, stored transposed) each. Within a supernode the diagonal block is
// factorized with partial pivoting. A Cholesky factor of S leaves F to GMRES,
// ~10 iterations per solve on the settled brick walls (docs/dda.md section
// 5); a factor of A itself leaves nothing, so GMRES converges in one or two.
// UMFPACK's LU of A does the same but costs 2.5-3 times a Cholesky
// factorization and 3-6 times its solves; this one, although it computes
// both triangles, costs 0.96-1.38 times CHOLMOD's Cholesky of the same
// pattern at 1,000-10,000 blocks in the sparse_lu runs so far (it scatters
// A's blocks straight into its panels), and its solves stream as many bytes
// as a Cholesky solve (L and U once instead of L twice; benchmarks/sparse_lu).
//
// Right-looking supernodal elimination (Ng and Peyton, SIAM J. Sci. Comput.
// 14, 1993, for the Cholesky case): supernode k is factorized,
//   P_k D_k = L_D U_D,  L_b = A_bk U_D^-1,  U_kb = L_D^-1 P_k A_kb,
// and its update L_b U_kb is subtracted from the ancestors' panels through a
// relative map of its rows into theirs.
#pragma once

#include <cholmod.h>

#include <vector>

#include "core/linear/block_sparse_matrix.h"
#include "core/linear/supernodal_structure.h"

namespace fissure {

class SupernodalLu {
 public:
  /// Takes the structure of a supernodal Cholesky analysis of A's pattern
  /// (symbolic or numeric) and maps A's entries into it.
  void analyze(const cholmod_factor& symbolic, const BlockSparseMatrix& a);

  /// Factorizes A, which has the pattern given to analyze. Throws SolverError
  /// on a zero or non-finite pivot.
  void factorize(const BlockSparseMatrix& a);

  const SupernodalStructure& structure() const { return structure_; }
  /// Lower panels: per supernode the packed L_D \ U_D of its diagonal block
  /// (unit lower L_D below the diagonal, U_D on and above it), then L_b.
  const std::vector<double>& lower() const { return lower_; }
  /// Upper panels: per supernode U_kb^T (below x ncol).
  const std::vector<double>& upper() const { return upper_; }
  /// Per column, the row permutation of its supernode's diagonal block:
  /// P_k moves local row i to local row pivots[first + i].
  const std::vector<int>& pivots() const { return pivots_; }

 private:
  void factorize_supernode(int k);
  void update_ancestors(int k);

  SupernodalStructure structure_;
  std::vector<int> owner_;         ///< supernode of each permuted column
  std::vector<long> destination_;  ///< per entry of A: >= 0 lower_, < 0 upper_ (~offset)
  std::vector<double> lower_, upper_;
  std::vector<int> pivots_;
  std::vector<int> map_;          ///< relative map of a supernode's rows
  std::vector<double> work_;      ///< a supernode's dense update
  std::vector<double> permuted_;  ///< a permuted upper panel
};

}  // namespace fissure
