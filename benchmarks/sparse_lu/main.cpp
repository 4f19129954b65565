// Cost of the sparse factorizations behind the DDA's reused-factorization
// solver (docs/performance.md "sparse_lu", docs/dda.md section 5): CHOLMOD's
// supernodal Cholesky of S, Fissure's supernodal LU of A = S + F on the same
// structure, and UMFPACK's pivoted LU of A. The matrices have the block
// pattern of a running-bond brick wall (each brick touches two neighbours in
// its course and two above and below) with 6 x 6 blocks: mass on the
// diagonal, springs 200 times stiffer between neighbours, and friction terms
// (a force along t proportional to the relative displacement along n, 5 % of
// the springs) on every pair. Walls of 20 courses by 5, 50 and 500 bricks.
// Reported per size: the best of `reps` runs of each factorization and of a
// solve with it (the two factors used as preconditioners in float, UMFPACK
// in double), the ratios to the Cholesky, the relative residual of one solve
// with each LU, and the GMRES-free measure of how well each factor
// preconditions A: |A z - b| / |b| for z = factor^-1 b. Also the solve of 32
// columns at once, each nonzero on the two blocks of one contact pair: the
// set-up of a low-rank correction of the factor (core/linear/
// low_rank_correction.h), reported per column.
//
// Usage: bench_sparse_lu [reps=5] [OUTPUT.csv]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <vector>

#include "core/base/stopwatch.h"
#include "core/linear/sparse_factorization.h"
#include "tests/support/block_systems.h"

using namespace fissure;

namespace {

struct Timing {
  double factorize = 1e300, solve = 1e300, residual = 0;
  double per_column = 1e300;  ///< of a 32-column solve
};

/// 32 right-hand sides, each random on the two blocks of a pair.
Eigen::MatrixXd contact_columns(const testing::BlockSystem& w,
                                const std::vector<std::pair<int, int>>& pairs) {
  constexpr int kColumns = 32;
  Eigen::MatrixXd r = Eigen::MatrixXd::Zero(w.b.size(), kColumns);
  std::srand(1);
  for (int k = 0; k < kColumns; ++k) {
    const auto [i, j] = pairs[(k * 7919u) % pairs.size()];
    r.col(k).segment<6>(6 * i).setRandom();
    r.col(k).segment<6>(6 * j).setRandom();
  }
  return r;
}

/// Best-of-reps factorization and solve times; the residual of A z = b.
Timing measure(SparseFactorization& f, const BlockSparseMatrix& factored,
               SparseFactorization::Method method, const testing::BlockSystem& w,
               const Eigen::MatrixXd& columns, int reps) {
  Timing t;
  Eigen::VectorXd z;
  Eigen::MatrixXd zs;
  f.factorize(factored, method);  // analysis, not timed
  for (int r = 0; r < reps; ++r) {
    Stopwatch clock;
    f.factorize(factored, method);
    t.factorize = std::min(t.factorize, clock.seconds());
    clock.restart();
    f.solve(w.b, z);
    t.solve = std::min(t.solve, clock.seconds());
    clock.restart();
    f.solve(columns, zs);
    t.per_column = std::min(t.per_column, clock.seconds() / static_cast<double>(columns.cols()));
  }
  t.residual = testing::relative_residual(w.a, w.b, z);
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  const int reps = argc > 1 ? std::atoi(argv[1]) : 5;
  const std::string out =
      argc > 2 ? argv[2] : FISSURE_SOURCE_DIR "/benchmarks/sparse_lu/results.csv";
  std::ofstream csv(out);
  csv << "blocks,method,factorize_s,solve_s,residual,per_column_s\n";
  std::printf("%7s  %-22s %12s %10s %9s %10s %12s\n", "blocks", "factorization", "factorize ms",
              "solve ms", "x Chol.", "|Az-b|/|b|", "column ms");
  using Method = SparseFactorization::Method;
  for (const int bricks : {5, 50, 500}) {
    const std::vector<std::pair<int, int>> pairs = testing::running_bond_pairs(bricks, 20);
    const testing::BlockSystem w = testing::block_system(20 * bricks, pairs, 200.0, 0.05);
    const Eigen::MatrixXd columns = contact_columns(w, pairs);
    SparseFactorization cholesky(true), supernodal(true), pivoted(false);
    const Timing c = measure(cholesky, w.spd, Method::Cholesky, w, columns, reps);
    const Timing l = measure(supernodal, w.a, Method::SupernodalLu, w, columns, reps);
    const Timing u = measure(pivoted, w.a, Method::PivotedLu, w, columns, reps);
    const int blocks = w.a.n_blocks();
    for (const auto& [name, t] :
         {std::pair{"cholesky_of_S_float", c}, std::pair{"supernodal_lu_float", l},
          std::pair{"umfpack_lu_double", u}}) {
      std::printf("%7d  %-22s %12.2f %10.3f %9.2f %10.1e %12.3f\n", blocks, name, 1e3 * t.factorize,
                  1e3 * t.solve, t.factorize / c.factorize, t.residual, 1e3 * t.per_column);
      csv << blocks << ',' << name << ',' << t.factorize << ',' << t.solve << ',' << t.residual
          << ',' << t.per_column << '\n';
    }
  }
  std::printf(
      "(residual of A z = b with z from each factor: the Cholesky of S leaves the\n"
      " friction terms, the LUs only rounding; results in %s)\n",
      out.c_str());
}
