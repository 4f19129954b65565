// Correcting a reused factorization by a low-rank update instead of
// refactorizing (core/linear/low_rank_correction.h): the Woodbury identity
// against a dense solve, the multi-column float solve against single ones,
// and the reused-factorization back end on systems that differ from the
// factorized one by added and removed stiff springs.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "core/linear/low_rank_correction.h"
#include "core/linear/sparse_factorization.h"
#include "mechanics/dda/solver/block_solver.h"
#include "tests/support/block_systems.h"

namespace fissure {
namespace {

constexpr double kTolerance = 1e-10;

/// A spring of stiffness k between random points of blocks i and j:
/// k w w^T, with w a random 12-vector (fixed seed per term).
RankOneTerm spring(int i, int j, double k, unsigned seed) {
  std::srand(seed);
  RankOneTerm t;
  t.block_i = i;
  t.block_j = j;
  t.v = Vector12::Random();
  t.u = k * t.v;
  return t;
}

TEST(LowRankCorrection, AppliesTheInverseOfTheUpdatedMatrix) {
  // F: a dense, well-conditioned 30 x 30 matrix (five blocks), solved
  // exactly; the update: two stiff springs, one on a single block (a
  // block of -1 has no unknowns), and an unsymmetric term. The identity is
  // exact; W = F^-1 U is kept in float (the reused factor's solves are
  // float anyway), so the result is exact to cond x eps_float (cond ~1e2:
  // 1e-5), while F alone misses by O(1).
  const Eigen::Index n = 30;
  std::srand(7);
  const Eigen::MatrixXd f = Eigen::MatrixXd::Random(n, n) + 10 * Eigen::MatrixXd::Identity(n, n);
  const Eigen::PartialPivLU<Eigen::MatrixXd> f_lu(f);
  LowRankUpdate terms{spring(0, 3, 50.0, 1), spring(2, -1, 80.0, 2), spring(4, 1, 30.0, 3)};
  terms[2].u.setRandom();
  const auto solve_many = [&](const Eigen::MatrixXd& r, Eigen::MatrixXd& z) { z = f_lu.solve(r); };
  LowRankCorrection correction;
  EXPECT_EQ(correction.set_up(solve_many, terms, n), 3);
  const Eigen::VectorXd r = Eigen::VectorXd::Random(n);
  Eigen::VectorXd z;
  z = f_lu.solve(r);
  correction.correct(z);
  const Eigen::VectorXd exact = (f + testing::dense(terms, n)).partialPivLu().solve(r);
  EXPECT_LT((z - exact).norm() / exact.norm(), 1e-5);
  EXPECT_GT((f_lu.solve(r) - exact).norm() / exact.norm(), 1e-2);

  // A later set-up with one more term solves for that term's column only
  // and is as exact.
  terms.push_back(spring(1, 2, 60.0, 4));
  EXPECT_EQ(correction.set_up(solve_many, terms, n), 1);
  z = f_lu.solve(r);
  correction.correct(z);
  const Eigen::VectorXd exact4 = (f + testing::dense(terms, n)).partialPivLu().solve(r);
  EXPECT_LT((z - exact4).norm() / exact4.norm(), 1e-5);
  // After forget() (a new F) every column is solved again.
  correction.forget();
  EXPECT_EQ(correction.set_up(solve_many, terms, n), 4);
}

TEST(SparseFactorization, SeveralRightHandSidesAreSolvedAsEachAlone) {
  // The multi-column float solve (matrix products per panel) against one
  // column at a time (matrix-vector products): the same arithmetic in
  // another order, so they differ by float rounding only (cond x eps_float,
  // cond ~1e3 here: 1e-4 at most; measured ~1e-7).
  using Method = SparseFactorization::Method;
  for (const double friction : {0.0, 0.05}) {
    const testing::BlockSystem s =
        testing::block_system(12 * 10, testing::grid_pairs(12, 10), 200.0, friction);
    SparseFactorization factor(true);
    factor.factorize(s.a, friction > 0 ? Method::SupernodalLu : Method::Cholesky);
    std::srand(11);
    const Eigen::MatrixXd r = Eigen::MatrixXd::Random(s.b.size(), 5);
    Eigen::MatrixXd z;
    factor.solve(r, z);
    for (int k = 0; k < 5; ++k) {
      Eigen::VectorXd zk;
      factor.solve(r.col(k), zk);
      const double difference = (z.col(k) - zk).norm() / zk.norm();
      EXPECT_LT(difference, 1e-4) << "friction " << friction << " column " << k;
    }
  }
}

/// The grid system of the reused-factorization tests, plus the terms.
testing::BlockSystem with_terms(testing::BlockSystem s, const LowRankUpdate& terms) {
  for (const RankOneTerm& t : terms) {
    const int blocks[2] = {t.block_i, t.block_j};
    for (int p = 0; p < 2; ++p)
      for (int q = 0; q < 2; ++q) {
        const Matrix6 block = t.u.segment<6>(6 * p) * t.v.segment<6>(6 * q).transpose();
        const int index = s.a.find(blocks[p], blocks[q]);
        EXPECT_GE(index, 0) << "blocks " << t.block_i << ", " << t.block_j << " not neighbours";
        if (index >= 0) s.a.add(index, block);
      }
  }
  s.friction = true;  // the terms are unsymmetric in general
  return s;
}

/// Factorizes `factorized`, then solves `changed` from zero, told (or not)
/// that it is `factorized` plus `update`. Returns the iterations of the
/// second solve, or -1 if it factorized again.
long second_solve_iterations(const testing::BlockSystem& factorized,
                             const testing::BlockSystem& changed, const LowRankUpdate* update) {
  std::unique_ptr<BlockSolver> solver = make_reused_factor_solver(kTolerance, 2000);
  solver->analyze(factorized.a);
  Eigen::VectorXd x;
  solver->solve(factorized.a, factorized.symmetric(), factorized.b, x);
  EXPECT_TRUE(solver->factorized());
  // three from zero: the factorization in float gains ~1e-4 per iteration
  EXPECT_EQ(solver->statistics()["iterations"].get<long>(), 3);
  const long before = solver->statistics()["iterations"].get<long>();
  solver->expect(update);
  x.setZero(changed.b.size());
  solver->solve(changed.a, changed.symmetric(), changed.b, x);
  EXPECT_LT(testing::relative_residual(changed.a, changed.b, x), kTolerance);
  EXPECT_EQ(solver->statistics()["failed_corrections"].get<long>(), 0);
  return solver->factorized() ? -1 : solver->statistics()["iterations"].get<long>() - before;
}

TEST(BlockSolvers, AReusedFactorIsCorrectedForAnExpectedUpdateInsteadOfRenewed) {
  // Eight contact springs 20 times the grid's, added to the factorized
  // system or removed from it, and the solver told so: corrected by the
  // update, the factor preconditions the changed system about as a fresh
  // factor would (three iterations from zero, for the float rounding of the
  // factorization), and there is no new factorization. Told nothing, the
  // factor alone needs more iterations (GMRES must find the eight
  // directions itself) or is renewed.
  const testing::BlockSystem base =
      testing::block_system(20 * 16, testing::grid_pairs(20, 16), 200.0, 0.05);
  LowRankUpdate added;
  for (int k = 0; k < 8; ++k) added.push_back(spring(21 * k, 21 * k + 1, 4000.0, 100 + k));
  LowRankUpdate removed = added;
  for (RankOneTerm& t : removed) t.u = -t.u;
  const testing::BlockSystem stiffer = with_terms(base, added);

  EXPECT_EQ(second_solve_iterations(base, stiffer, &added), 3);
  // Removing springs subtracts from the factor's own stiffness: H = I +
  // V^T F^-1 U cancels to within the remaining stiffness (1/20 of the
  // removed), which magnifies the float rounding of F^-1 U twentyfold: one
  // more iteration at most.
  EXPECT_LE(second_solve_iterations(stiffer, base, &removed), 4);
  const long untold = second_solve_iterations(base, stiffer, nullptr);
  EXPECT_TRUE(untold == -1 || untold > 3) << untold;
}

TEST(BlockSolvers, AWrongUpdateCostsAFactorizationButNotTheSolve) {
  // The update claims that column 0 of the factorized matrix was removed
  // (A_f + U V^T singular: H = 1 - e_0^T F^-1 F e_0 = 0 up to the float
  // rounding of F), while the system is in fact unchanged. The corrected
  // factor is useless; the attempt is given up, the factor renewed, and
  // the system solved to the tolerance all the same.
  const testing::BlockSystem s = testing::block_system(2, {{0, 1}}, 200.0, 0.05);
  RankOneTerm wrong;
  wrong.block_i = 0;
  wrong.block_j = 1;
  wrong.v(0) = 1;
  for (int row = 0; row < 12; ++row) {
    const int index = s.a.find(row < 6 ? 0 : 1, 0);
    wrong.u(row) = -s.a.value(index)(row % 6, 0);
  }
  const LowRankUpdate update{wrong};
  std::unique_ptr<BlockSolver> solver = make_reused_factor_solver(kTolerance, 2000);
  solver->analyze(s.a);
  Eigen::VectorXd x;
  solver->solve(s.a, s.symmetric(), s.b, x);
  solver->expect(&update);
  x.setZero(s.b.size());
  solver->solve(s.a, s.symmetric(), s.b, x);
  EXPECT_LT(testing::relative_residual(s.a, s.b, x), kTolerance);
  EXPECT_EQ(solver->statistics()["failed_corrections"].get<long>(), 1);
  EXPECT_EQ(solver->statistics()["factorizations"].get<long>(), 2);
}

}  // namespace
}  // namespace fissure
