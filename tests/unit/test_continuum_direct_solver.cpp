// The continuum's sparse LU checks each new factor and refines only where
// the factor needs it (continuum_linear_solver.cpp, issue 41): UMFPACK's
// componentwise backward error on a solve of the factor's own, refinement
// above 1e-12.
#include <gtest/gtest.h>

#include <Eigen/SparseLU>
#include <cmath>
#include <vector>

#include "continuum/poroelasticity/continuum_constraints.h"
#include "continuum/poroelasticity/continuum_linear_solver.h"
#include "continuum/poroelasticity/continuum_mesh.h"

namespace fissure::continuum {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

using Refinement = LinearSolverControls::Refinement;

LinearSolverControls direct(Refinement refinement) {
  LinearSolverControls c{LinearSolverControls::Type::Direct, 1e-10, 2000, {}, {}, {}};
  c.refinement = refinement;
  return c;
}

/// The saddle-point solver of n_u + n_p unknowns, direct.
std::unique_ptr<ContinuumLinearSolver> direct_lu(const ContinuumMesh& mesh, const FieldNumbering& u,
                                                 const FieldNumbering& p,
                                                 Refinement refinement = Refinement::Auto) {
  return make_linear_solver(SystemKind::SaddlePoint, "test", mesh, false, u, &p,
                            direct(refinement));
}

/// Wilkinson's growth matrix: 1 on the diagonal, -1 everywhere below it, 1 in the
/// last column. Elimination on the diagonal doubles the last column at
/// every step: growth 2^(n-1), and so a backward error far above
/// round-off, which refinement repairs (the matrix is well conditioned).
SparseMatrix wilkinson(int n) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 1.0);
    for (int j = 0; j < i; ++j) t.emplace_back(i, j, -1.0);
    if (i < n - 1) t.emplace_back(i, n - 1, 1.0);
  }
  SparseMatrix a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

/// A symmetric quasi-definite saddle point: [[K, B], [B^T, -C]], K of
/// stiffness size (4e9), C of storage size (1e-10).
SparseMatrix quasi_definite(int nu, int np) {
  const int n = nu + np;
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < nu; ++i) {
    t.emplace_back(i, i, 4.0e9);
    if (i > 0) t.emplace_back(i, i - 1, -1.0e9), t.emplace_back(i - 1, i, -1.0e9);
  }
  for (int k = 0; k < np; ++k) {
    t.emplace_back(nu + k, nu + k, -1e-10);
    for (int i : {4 * k, 4 * k + 1}) t.emplace_back(i, nu + k, 0.5), t.emplace_back(nu + k, i, 0.5);
  }
  SparseMatrix a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

TEST(ContinuumDirectSolver, AWellBehavedFactorIsCheckedAndNotRefined) {
  const int nu = 40, np = 10, n = nu + np;
  const SparseMatrix a = quasi_definite(nu, np);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  const ContinuumMesh mesh;
  const FieldNumbering u = free_numbering(nu), p = free_numbering(np);
  auto solver = direct_lu(mesh, u, p);
  SparseMatrix copy = a;
  solver->set_matrix(std::move(copy));
  const Eigen::VectorXd x = solver->solve(b, Eigen::VectorXd());
  const ContinuumLinearSolver::FactorSize f = solver->factor_size();
  EXPECT_GT(f.backward_error, 0) << "each new factor is measured";
  EXPECT_LT(f.backward_error, 1e-14);
  EXPECT_FALSE(f.refined);
  EXPECT_LT((a * x - b).norm(), 1e-12 * b.norm() * 4e9);
}

TEST(ContinuumDirectSolver, ALargeBackwardErrorSwitchesRefinementOn) {
  const int n = 60;  // growth 2^59
  const SparseMatrix a = wilkinson(n);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 3.0);
  Eigen::SparseLU<SparseMatrix> reference(a);  // partial pivoting: no growth
  const Eigen::VectorXd exact = reference.solve(b);

  const ContinuumMesh mesh;
  const FieldNumbering u = free_numbering(n - 1), p = free_numbering(1);
  auto solver = direct_lu(mesh, u, p);
  SparseMatrix copy = a;
  solver->set_matrix(std::move(copy));
  const Eigen::VectorXd x = solver->solve(b, Eigen::VectorXd());
  const ContinuumLinearSolver::FactorSize f = solver->factor_size();
  EXPECT_GT(f.backward_error, 1e-12) << "the factor's growth shows";
  EXPECT_TRUE(f.refined);
  // The refined solution (and the next solve's) against partial pivoting.
  EXPECT_LT((x - exact).lpNorm<Eigen::Infinity>(), 1e-10 * exact.lpNorm<Eigen::Infinity>());
  const Eigen::VectorXd y = solver->solve(2 * b, Eigen::VectorXd());
  EXPECT_LT((y - 2 * exact).lpNorm<Eigen::Infinity>(), 1e-10 * exact.lpNorm<Eigen::Infinity>());
}

// `solver.refinement: always` refines a factor the check finds well
// behaved (the check still measured); `never` neither checks nor refines,
// and Wilkinson's matrix then keeps its growth's error.
TEST(ContinuumDirectSolver, TheSceneCanAskForRefinementOrNone) {
  const ContinuumMesh mesh;
  {
    const int nu = 40, np = 10, n = nu + np;
    const SparseMatrix a = quasi_definite(nu, np);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
    auto solver = direct_lu(mesh, free_numbering(nu), free_numbering(np), Refinement::Always);
    SparseMatrix copy = a;
    solver->set_matrix(std::move(copy));
    const Eigen::VectorXd x = solver->solve(b, Eigen::VectorXd());
    const ContinuumLinearSolver::FactorSize f = solver->factor_size();
    EXPECT_GT(f.backward_error, 0);
    EXPECT_LT(f.backward_error, 1e-14);
    EXPECT_TRUE(f.refined);
    EXPECT_LT((a * x - b).norm(), 1e-12 * b.norm() * 4e9);
  }
  const int n = 60;
  const SparseMatrix a = wilkinson(n);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 3.0);
  const Eigen::VectorXd exact = Eigen::SparseLU<SparseMatrix>(a).solve(b);
  auto solver = direct_lu(mesh, free_numbering(n - 1), free_numbering(1), Refinement::Never);
  SparseMatrix copy = a;
  solver->set_matrix(std::move(copy));
  const Eigen::VectorXd x = solver->solve(b, Eigen::VectorXd());
  const ContinuumLinearSolver::FactorSize f = solver->factor_size();
  EXPECT_EQ(f.backward_error, 0) << "not measured";
  EXPECT_FALSE(f.refined);
  EXPECT_GT((x - exact).lpNorm<Eigen::Infinity>(), 1e-10 * exact.lpNorm<Eigen::Infinity>())
      << "the growth's error, which the automatic check would have refined away";
}

// A Cholesky factor (the SPD systems) refines one step per solve when the
// scene asks: the same solution, a residual at round-off, and summary.json
// says so.
TEST(ContinuumDirectSolver, ACholeskyFactorRefinesWhenAsked) {
  const int n = 200;
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 2.0 + 1e-6);
    if (i > 0) t.emplace_back(i, i - 1, -1.0), t.emplace_back(i - 1, i, -1.0);
  }
  SparseMatrix a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  const ContinuumMesh mesh;
  Eigen::VectorXd x[2];
  for (const Refinement r : {Refinement::Auto, Refinement::Always}) {
    auto solver = make_linear_solver(SystemKind::Diffusion, "test", mesh, false, free_numbering(n),
                                     nullptr, direct(r));
    SparseMatrix copy = a;
    solver->set_matrix(std::move(copy));
    x[r == Refinement::Always] = solver->solve(b, Eigen::VectorXd());
    EXPECT_EQ(solver->factor_size().refined, r == Refinement::Always);
    EXPECT_EQ(solver->factor_size().backward_error, 0);
  }
  // cond(A) ~ 1.6e4 (the smallest eigenvalue ~ (pi / n)^2 + 1e-6): the two
  // solutions within cond x eps; the refined residual within a few eps of
  // |A| |x| + |b| (the componentwise backward error refinement gives).
  const double x_max = x[0].lpNorm<Eigen::Infinity>(), b_max = b.lpNorm<Eigen::Infinity>();
  EXPECT_LT((x[1] - x[0]).lpNorm<Eigen::Infinity>(), 1e-10 * x_max);
  EXPECT_LT((a * x[1] - b).lpNorm<Eigen::Infinity>(), 10 * 2.2e-16 * (4 * x_max + b_max));
}

}  // namespace
}  // namespace fissure::continuum
