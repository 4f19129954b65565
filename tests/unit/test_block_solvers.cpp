// The DDA linear-solver back ends on penalty-coupled block systems shaped like
// a settling wall: mass on the diagonal, contact springs 200 times stiffer
// between neighbours on a grid, optionally an unsymmetric friction term.
// Every back end must reach its tolerance; the reused factorization must
// solve slowly changing systems without refactorizing and still solve a
// system that has changed completely.
#include <gtest/gtest.h>

#include "core/base/errors.h"
#include "core/linear/block_solver.h"

namespace fissure {
namespace {

constexpr double kTolerance = 1e-10;

struct GridSystem {
  BlockSparseMatrix a;
  Eigen::VectorXd b;
};

/// nx x ny blocks; `spring` scales the couplings, `friction` adds an
/// unsymmetric term to each coupling (as implicit sliding friction does).
GridSystem grid_system(int nx, int ny, double spring, double friction) {
  const int n = nx * ny;
  std::vector<std::pair<int, int>> pairs;
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x) {
      if (x + 1 < nx) pairs.emplace_back(y * nx + x, y * nx + x + 1);
      if (y + 1 < ny) pairs.emplace_back(y * nx + x, (y + 1) * nx + x);
    }
  GridSystem s;
  s.a.set_pattern(n, pairs);
  // A fixed symmetric positive definite spring coupling the six unknowns.
  Matrix6 g = Matrix6::Identity();
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c) g(r, c) += 0.1 * std::sin(1.0 + r + 7.0 * c);
  const Matrix6 k = spring * g * g.transpose();
  Matrix6 skew = Matrix6::Zero();
  skew(0, 1) = 1, skew(1, 0) = -0.5, skew(2, 4) = 0.3;
  for (int i = 0; i < n; ++i) s.a.value(s.a.diagonal_index(i)) = Matrix6::Identity();  // mass
  for (const auto& [i, j] : pairs) {
    s.a.value(s.a.diagonal_index(i)) += k;
    s.a.value(s.a.diagonal_index(j)) += k;
    s.a.add_pair(s.a.find(i, j), s.a.find(j, i), -k);
    s.a.add(s.a.find(i, j), friction * spring * skew);
  }
  s.b.resize(6 * n);
  for (int r = 0; r < 6 * n; ++r) s.b(r) = std::cos(0.37 * r) + (r % 6 == 1 ? -2.0 : 0.0);
  return s;
}

double relative_residual(const BlockSparseMatrix& a, const Eigen::VectorXd& b,
                         const Eigen::VectorXd& x) {
  Eigen::VectorXd ax;
  a.multiply(x, ax);
  return (b - ax).norm() / b.norm();
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
    const bool symmetric = friction == 0;
    for (auto type : {LinearSolverControls::Type::Direct, LinearSolverControls::Type::Pcg,
                      LinearSolverControls::Type::Auto}) {
      std::unique_ptr<BlockSolver> solver = make_block_solver(controls(type));
      solver->analyze(s.a);
      Eigen::VectorXd x;
      solver->solve(s.a, s.b, x, symmetric);
      // The direct solve is exact to rounding (condition number ~1e3).
      EXPECT_LT(relative_residual(s.a, s.b, x), kTolerance) << solver->name();
    }
    std::unique_ptr<BlockSolver> reused = make_reused_factor_solver(kTolerance, 2000);
    reused->analyze(s.a);
    Eigen::VectorXd x;
    reused->solve(s.a, s.b, x, symmetric);
    EXPECT_LT(relative_residual(s.a, s.b, x), kTolerance);
  }
}

TEST(BlockSolvers, ReusedFactorizationSolvesSlowlyChangingSystemsWithoutRefactorizing) {
  // Geometry drifting by 1e-6 per step: with the first factor as
  // preconditioner, one GMRES iteration per solve reduces the warm-started
  // residual (~1e-6) below the tolerance.
  for (double friction : {0.0, 0.05}) {
    std::unique_ptr<BlockSolver> solver = make_reused_factor_solver(kTolerance, 2000);
    Eigen::VectorXd x;
    for (int step = 0; step < 10; ++step) {
      GridSystem s = grid_system(20, 16, 200.0 * (1 + 1e-6 * step), friction);
      solver->analyze(s.a);
      solver->solve(s.a, s.b, x, friction == 0);
      EXPECT_LT(relative_residual(s.a, s.b, x), kTolerance) << "step " << step;
    }
    EXPECT_EQ(statistic(*solver, "factorizations"), 1);
    EXPECT_EQ(statistic(*solver, "iterations"), 10);
  }
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
    solver->solve(s.a, s.b, x, friction == 0);
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
    solver->solve(s.a, s.b, x, true);
    EXPECT_LT(relative_residual(s.a, s.b, x), kTolerance);
  }
  const nlohmann::json stats = solver->statistics();
  EXPECT_GT(stats["reused_factorization"]["solves"].get<long>(), 0);
  EXPECT_GT(stats["pcg"]["solves"].get<long>() + stats["pcg_fallbacks"].get<long>(), 0);
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
    EXPECT_THROW(solver->solve(s.a, s.b, x, true), SolverError) << solver->name();
    EXPECT_THROW(solver->solve(s.a, s.b, x, false), SolverError) << solver->name();
  }
}

}  // namespace
}  // namespace fissure
