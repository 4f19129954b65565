// LU factorization of a DDA system matrix A = S + F on the supernodal
// structure of the Cholesky analysis of its pattern, computed in single
// precision, for use as a preconditioner. Implicit sliding friction (F)
// makes A unsymmetric but leaves its pattern symmetric, so an LU without
// pivoting across supernodes has exactly the fill of the Cholesky factor of
// S: the same supernodes and dense panels, one lower panel (L) and one upper
// panel (U) each. Within a supernode the diagonal block is factorized with
// partial pivoting. A Cholesky factor of S leaves F to GMRES, ~10
// iterations per solve on the settled brick walls (docs/dda.md section 5); a
// factor of A itself leaves nothing, so GMRES converges in two or three.
// UMFPACK's LU of A does the same but costs 5-6 times as much.
//
// Why float: the factor only preconditions GMRES, which is solved to the
// tolerance in double anyway, and applying it is memory-bound. Computed in
// double and rounded, the factorization streamed twice the bytes and
// needed a copying pass; in float (with the update scatter below) it costs
// about half as much on the DDA walls (benchmarks/sparse_lu,
// docs/performance-history.md). The price is
// accuracy: the Schur complements cancel the contact springs down to the
// much softer remaining stiffness, so their float rounding is magnified by
// about that ratio. Applied once, the factor leaves a relative error of
// 1e-4 instead of 1e-7 on the test grids; GMRES needs one iteration more at
// most, and a fresh factor that does not converge falls back to UMFPACK
// (reused_factor_block_solver.cpp).
//
// Right-looking supernodal elimination (Ng and Peyton, SIAM J. Sci. Comput.
// 14, 1993, for the Cholesky case): supernode k is factorized,
//   P_k D_k = L_D U_D,  L_b = A_bk U_D^-1,  U_kb = L_D^-1 P_k A_kb,
// and its update L_b U_kb is subtracted from the ancestors' panels through a
// relative map of its rows into theirs, computed once per analysis.
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
  /// Hands the panels over (swapped with `lower` and `upper`) instead of
  /// copying them; the next factorize() sizes its own again. Lower panels:
  /// per supernode the packed L_D \ U_D of its diagonal block (unit lower
  /// L_D below the diagonal, U_D on and above it), then L_b. Upper panels:
  /// per supernode U_kb^T (below x ncol); until the supernode is factorized
  /// its panel holds A_kb minus the updates so far as ncol x below, so that
  /// the updates reach it by columns, as they reach the lower panels.
  void take_panels(std::vector<float>& lower, std::vector<float>& upper) {
    lower.swap(lower_);
    upper.swap(upper_);
  }
  /// Per column, the row permutation of its supernode's diagonal block:
  /// P_k moves local row i to local row pivots[first + i].
  const std::vector<int>& pivots() const { return pivots_; }

 private:
  void factorize_supernode(int k);
  void update_ancestors(int k);
  /// Where each supernode's update goes in its ancestors (runs_, segments_).
  void map_updates();

  /// A supernode's rows below from `first` on that are the columns of
  /// `ancestor` (those covered by the segments before columns_end) and the
  /// rows after them. Its segments are segments_[segments_begin ...
  /// segments_end).
  struct Run {
    int ancestor, first;
    int segments_begin, columns_end, segments_end;
  };
  /// Rows i ... i + length - 1 of a run (counted from its first row) are the
  /// local rows p ... p + length - 1 of its ancestor.
  struct Segment {
    int i, p, length;
  };

  SupernodalStructure structure_;
  std::vector<int> owner_;         ///< supernode of each permuted column
  std::vector<long> destination_;  ///< per entry of A: >= 0 lower_, < 0 upper_ (~offset)
  std::vector<float> lower_, upper_;
  std::vector<int> pivots_;
  std::vector<int> run_start_;  ///< per supernode into runs_, then the end
  std::vector<Run> runs_;
  std::vector<Segment> segments_;
  std::vector<float> work_;        ///< a supernode's dense update
  std::vector<float> transposed_;  ///< U_kb^T while it is computed
};

}  // namespace fissure
