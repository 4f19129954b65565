// The DDA linear-solver back ends on penalty-coupled block systems shaped like
// a settling wall: mass on the diagonal, contact springs 200 times stiffer
// between neighbours on a grid, optionally an unsymmetric friction term.
// Every back end must reach its tolerance; the reused factorization must
// solve slowly changing systems without refactorizing and still solve a
// system that has changed completely.
#include <gtest/gtest.h>

#include "core/base/errors.h"
#include "core/linear/sparse_factorization.h"
#include "mechanics/dda/solver/block_solver.h"
#include "tests/support/block_systems.h"

namespace fissure {
namespace {

using testing::relative_residual;

constexpr double kTolerance = 1e-10;
constexpr double kFloatEpsilon = 6e-8;  ///< unit roundoff of float
/// 2-norm condition numbers of the 20 x 16 test grids (springs 200 times the
/// mass), from a dense SVD: with friction 5 % and 20 times the springs.
constexpr double kConditionFriction5 = 2.8e3, kConditionFriction20 = 7.0e4;

using GridSystem = testing::BlockSystem;

/// nx x ny blocks; `spring` scales the couplings, `friction` adds to each
/// coupling a force along t proportional to the relative displacement along n
/// (as implicit sliding friction does: unsymmetric, zero on rigid motions).
GridSystem grid_system(int nx, int ny, double spring, double friction) {
  return testing::block_system(nx * ny, testing::grid_pairs(nx, ny), spring, friction);
}

LinearSolverControls controls(LinearSolverControls::Type type) {
  LinearSolverControls c;
  c.type = type;
  c.relative_tolerance = kTolerance;
  return c;
}

long statistic(const BlockSolver& s, const char* key) {
  return s.statistics()[key].get<long>();
}

TEST(BlockSolvers, EveryBackEndSolvesAStiffSymmetricAndUnsymmetricSystem) {
  for (double friction : {0.0, 0.05}) {
    GridSystem s = grid_system(20, 16, 200.0, friction);
    for (auto type : {LinearSolverControls::Type::Direct, LinearSolverControls::Type::Pcg,
                      LinearSolverControls::Type::Auto}) {
      std::unique_ptr<BlockSolver> solver = make_block_solver(controls(type));
      solver->analyze(s.a);
      Eigen::VectorXd x;
      solver->solve(s.a, s.symmetric(), s.b, x);
      // The direct solve is exact to rounding (condition number ~1e3).
      EXPECT_LT(relative_residual(s.a, s.b, x), kTolerance) << solver->name();
    }
    std::unique_ptr<BlockSolver> reused = make_reused_factor_solver(kTolerance, 2000);
    reused->analyze(s.a);
    Eigen::VectorXd x;
    reused->solve(s.a, s.symmetric(), s.b, x);
    EXPECT_LT(relative_residual(s.a, s.b, x), kTolerance);
  }
}

using Method = SparseFactorization::Method;

/// Solves A x = b with `reference` applied in double (its residual must be
/// round-off) and with `method` applied in float; returns the relative
/// difference of the two solutions.
double float_against_double(const GridSystem& s, Method reference, Method method) {
  SparseFactorization in_double(false), in_single(true);
  in_double.factorize(s.a, reference);
  in_single.factorize(s.a, method);
  Eigen::VectorXd z_double, z_single;
  in_double.solve(s.b, z_double);
  in_single.solve(s.b, z_single);
  EXPECT_LT(relative_residual(s.a, s.b, z_double), 1e-12);
  return (z_single - z_double).norm() / z_double.norm();
}

TEST(SparseFactorization, SinglePrecisionSolvesDifferFromDoubleOnesByFloatRoundingOnly) {
  // The reused factorization applies a float copy of the Cholesky factor.
  // Rounding it (and the substitutions) to float perturbs the solution by
  // at most about cond(A) eps_float = 1e3 x 6e-8 (measured: 1.1e-7); a
  // difference below 1e-9 would mean the double factor was used.
  const double difference =
      float_against_double(grid_system(20, 16, 200.0, 0.0), Method::Cholesky, Method::Cholesky);
  EXPECT_LT(difference, 1e3 * 6e-8);
  EXPECT_GT(difference, 1e-9);
}

TEST(SparseFactorization, SupernodalLuAgreesWithUmfpackToFloatRounding) {
  // The LU on the Cholesky structure (no pivoting across supernodes,
  // computed and applied in float) against UMFPACK's pivoted LU in double,
  // for friction 5 % and 20 times the springs (the symmetric part then
  // indefinite; rows are pivoted within supernodes). A backward-stable solve
  // in float differs from the exact one by about cond(A) eps_float (Higham,
  // Accuracy and Stability of Numerical Algorithms, 2002, section 9.2): 1.7e-4
  // and 4.2e-3 here; measured 4.2e-5 and 9.8e-5. A wrong factor would be off
  // by O(1), a double one by less than 1e-9.
  for (const auto& [friction, condition] :
       {std::pair{0.05, kConditionFriction5}, std::pair{20.0, kConditionFriction20}}) {
    const double difference = float_against_double(grid_system(20, 16, 200.0, friction),
                                                   Method::PivotedLu, Method::SupernodalLu);
    EXPECT_LT(difference, condition * kFloatEpsilon) << "friction " << friction;
    EXPECT_GT(difference, 1e-9) << "friction " << friction;
  }
}

TEST(SparseFactorization, SupernodalLuPivotsWithinASupernode) {
  // Diagonal blocks whose first two unknowns are coupled only to each other
  // ([0 1; 1 0]) have a zero first pivot: an LU without pivoting breaks
  // down. The six unknowns of a block fall into one supernode, where the
  // rows are pivoted. Condition number 4.9: the float solve's residual is
  // below 1e-6 (measured 1.1e-7).
  GridSystem s = grid_system(12, 9, 0.1, 0.05);
  for (int i = 0; i < s.a.n_blocks(); ++i) {
    Matrix6& d = s.a.value(s.a.diagonal_index(i));
    d.topLeftCorner<2, 2>() << 0.0, 1.0, 1.0, 0.0;
  }
  SparseFactorization supernodal(true);
  supernodal.factorize(s.a, Method::SupernodalLu);
  Eigen::VectorXd z;
  supernodal.solve(s.b, z);
  EXPECT_LT(relative_residual(s.a, s.b, z), 1e-6);
}

TEST(SparseFactorization, SupernodalLuRefactorizesAnotherMatrixAndAfterAZeroPivot) {
  // One SparseFactorization reused, as the DDA solvers reuse theirs: the
  // panels of a factorization, whole or stopped by a zero pivot, must not
  // leak into the next. Factorized in turn: friction 5 %, a matrix whose
  // middle block has a zero row and column (a zero pivot), friction 20 times
  // the springs, friction 5 % again. Each solution must agree with UMFPACK's
  // to float rounding (cond(A) eps_float, as above); leftovers of the matrix
  // before would be off by O(1) (checked: without clearing the panels in
  // between, the zero pivot is not even found).
  const GridSystem first = grid_system(20, 16, 200.0, 0.05);
  const GridSystem last = grid_system(20, 16, 200.0, 20.0);
  GridSystem singular = grid_system(20, 16, 200.0, 0.05);
  const int middle = 10 + 20 * 8;
  const auto starts = singular.a.row_start();
  const auto columns = singular.a.columns();
  for (int i = 0; i < singular.a.n_blocks(); ++i)
    for (int b = starts[i]; b < starts[i + 1]; ++b)
      if (i == middle || columns[b] == middle) singular.a.value(b).setZero();

  SparseFactorization supernodal(true);
  const auto agrees_with_umfpack = [&](const GridSystem& s) {
    SparseFactorization umfpack(false);
    umfpack.factorize(s.a, Method::PivotedLu);
    Eigen::VectorXd expected, z;
    umfpack.solve(s.b, expected);
    supernodal.solve(s.b, z);
    return (z - expected).norm() / expected.norm();
  };
  supernodal.factorize(first.a, Method::SupernodalLu);
  EXPECT_LT(agrees_with_umfpack(first), kConditionFriction5 * kFloatEpsilon);
  EXPECT_THROW(supernodal.factorize(singular.a, Method::SupernodalLu), SolverError);
  EXPECT_TRUE(supernodal.empty());
  supernodal.factorize(last.a, Method::SupernodalLu);
  EXPECT_LT(agrees_with_umfpack(last), kConditionFriction20 * kFloatEpsilon);
  supernodal.factorize(first.a, Method::SupernodalLu);
  EXPECT_LT(agrees_with_umfpack(first), kConditionFriction5 * kFloatEpsilon);
}

TEST(BlockSolvers, ReusedFactorizationSolvesSlowlyChangingSystemsWithoutRefactorizing) {
  // Geometry drifting by 1e-6 per step: with the first factor as
  // preconditioner, one GMRES iteration per solve reduces the warm-started
  // residual (~1e-6) below the tolerance. The factor is applied in single
  // precision, so one iteration reduces the residual by ~4e-5 at best: the
  // first solve, from zero, needs two.
  std::unique_ptr<BlockSolver> solver = make_reused_factor_solver(kTolerance, 2000);
  Eigen::VectorXd x;
  for (int step = 0; step < 10; ++step) {
    GridSystem s = grid_system(20, 16, 200.0 * (1 + 1e-6 * step), 0.0);
    solver->analyze(s.a);
    solver->solve(s.a, s.symmetric(), s.b, x);
    EXPECT_LT(relative_residual(s.a, s.b, x), kTolerance) << "step " << step;
  }
  EXPECT_EQ(statistic(*solver, "factorizations"), 1);
  EXPECT_EQ(statistic(*solver, "iterations"), 11);
}

TEST(BlockSolvers, FrictionSystemsArePreconditionedByAnLuOfTheWholeMatrix) {
  // Friction 5 % of the springs makes A unsymmetric. The reused
  // factorization factorizes A itself (the supernodal LU), so that GMRES is
  // left only the float rounding of the factorization (one iteration gains
  // ~1e-4) and the drift: the first solve, from zero, needs three
  // iterations, each later warm-started one (residual ~1e-6 from the drift)
  // one; no fallback to UMFPACK.
  std::unique_ptr<BlockSolver> solver = make_reused_factor_solver(kTolerance, 2000);
  Eigen::VectorXd x;
  long before = 0;
  for (int step = 0; step < 10; ++step) {
    GridSystem s = grid_system(20, 16, 200.0 * (1 + 1e-6 * step), 0.05);
    solver->analyze(s.a);
    solver->solve(s.a, s.symmetric(), s.b, x);
    EXPECT_LT(relative_residual(s.a, s.b, x), kTolerance) << "step " << step;
    const long its = statistic(*solver, "iterations") - before;
    before += its;
    EXPECT_EQ(its, step == 0 ? 3 : 1) << "step " << step;
  }
  EXPECT_EQ(statistic(*solver, "factorizations"), 1);
  EXPECT_EQ(statistic(*solver, "lu_fallbacks"), 0);

  // When GMRES cannot converge within the allowed iterations on a fresh
  // factor, UMFPACK's pivoted LU of A (in double) is computed and solves at
  // once.
  std::unique_ptr<BlockSolver> capped = make_reused_factor_solver(kTolerance, 1);
  GridSystem s = grid_system(20, 16, 200.0, 0.05);
  capped->analyze(s.a);
  x.resize(0);
  capped->solve(s.a, s.symmetric(), s.b, x);
  EXPECT_LT(relative_residual(s.a, s.b, x), kTolerance);
  EXPECT_EQ(statistic(*capped, "lu_fallbacks"), 1);
}

TEST(BlockSolvers, AFactorIsKeptWhileReusingItCostsNoMoreIterationsThanAFreshOne) {
  // Strong friction (20 times the springs). Solving the same system again
  // from zero needs exactly the iterations of the solve after the
  // factorization, which is no rent: the factor is kept.
  std::unique_ptr<BlockSolver> solver = make_reused_factor_solver(kTolerance, 2000);
  GridSystem s = grid_system(20, 16, 200.0, 20.0);
  solver->analyze(s.a);
  Eigen::VectorXd x;
  long fresh = 0;
  for (int solve = 0; solve < 5; ++solve) {
    x.setZero(s.b.size());
    solver->solve(s.a, s.symmetric(), s.b, x);
    EXPECT_LT(relative_residual(s.a, s.b, x), kTolerance) << "solve " << solve;
    if (solve == 0) fresh = statistic(*solver, "iterations");
  }
  EXPECT_EQ(statistic(*solver, "factorizations"), 1);
  EXPECT_EQ(statistic(*solver, "iterations"), 5 * fresh);
}

TEST(BlockSolvers, ReusedFactorizationRenewsTheFactorWhenTheSystemChanges) {
  // Springs five times stiffer and a new pattern (a larger grid): the old
  // factor cannot serve (different size), then a changed system of the
  // same size is still solved to the tolerance.
  std::unique_ptr<BlockSolver> solver = make_reused_factor_solver(kTolerance, 2000);
  Eigen::VectorXd x;
  for (const auto& [nx, spring, friction] :
       {std::tuple{20, 200.0, 0.0}, std::tuple{24, 200.0, 0.0}, std::tuple{24, 1000.0, 0.05},
        std::tuple{24, 40.0, 0.0}}) {
    GridSystem s = grid_system(nx, 16, spring, friction);
    solver->analyze(s.a);
    solver->solve(s.a, s.symmetric(), s.b, x);
    EXPECT_LT(relative_residual(s.a, s.b, x), kTolerance) << nx << " " << spring;
  }
  EXPECT_GE(statistic(*solver, "factorizations"), 2);
}

TEST(BlockSolvers, AutoUsesBothLargeSystemBackEndsAndKeepsTheTolerance) {
  // Above 300 blocks `auto` lets pcg and the reused factorization compete on
  // measured cost; each is tried within the first solves.
  std::unique_ptr<BlockSolver> solver =
      make_block_solver(controls(LinearSolverControls::Type::Auto));
  Eigen::VectorXd x;
  for (int step = 0; step < 4; ++step) {
    GridSystem s = grid_system(20, 16, 200.0 * (1 + 0.01 * step), 0.0);
    solver->analyze(s.a);
    solver->solve(s.a, s.symmetric(), s.b, x);
    EXPECT_LT(relative_residual(s.a, s.b, x), kTolerance);
  }
  const nlohmann::json stats = solver->statistics();
  EXPECT_GT(stats["reused_factorization"]["solves"].get<long>(), 0);
  EXPECT_GT(stats["pcg"]["solves"].get<long>() + stats["pcg_fallbacks"].get<long>(), 0);
}

TEST(BlockSolvers, PcgGivesUpAtTheIterationLimitItIsGiven) {
  // auto lowers pcg's limit to what a factored solve costs; pcg must then
  // stop there with a SolverError, keeping its progress in x.
  GridSystem s = grid_system(20, 16, 200.0, 0.0);
  std::unique_ptr<BlockSolver> pcg = make_pcg_solver(kTolerance, 2000);
  Eigen::VectorXd x;
  pcg->solve(s.a, s.symmetric(), s.b, x);
  const long needed = statistic(*pcg, "iterations");
  ASSERT_GT(needed, 10);
  pcg->set_max_iterations(static_cast<int>(needed / 2));
  x.setZero(s.b.size());
  EXPECT_THROW(pcg->solve(s.a, s.symmetric(), s.b, x), SolverError);
  EXPECT_LT(relative_residual(s.a, s.b, x), 1.0);
  EXPECT_GT(relative_residual(s.a, s.b, x), kTolerance);
}

TEST(BlockSolvers, SingularSystemIsAClearErrorForEveryBackEnd) {
  GridSystem s = grid_system(4, 4, 1.0, 0.0);
  s.a.set_zero();  // no mass, no springs
  for (auto make : {+[] { return make_direct_solver(); },
                    +[] { return make_reused_factor_solver(kTolerance, 100); },
                    +[] { return make_pcg_solver(kTolerance, 100); }}) {
    std::unique_ptr<BlockSolver> solver = make();
    solver->analyze(s.a);
    Eigen::VectorXd x;
    EXPECT_THROW(solver->solve(s.a, true, s.b, x), SolverError) << solver->name();
    EXPECT_THROW(solver->solve(s.a, false, s.b, x), SolverError) << solver->name();
  }
}

}  // namespace
}  // namespace fissure
