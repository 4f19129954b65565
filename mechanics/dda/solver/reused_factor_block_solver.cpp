// GMRES preconditioned by a sparse factorization of A (Cholesky, or LU with
// sliding friction) that is reused across solves. Between open-close
// iterations only the springs of contacts that change state differ, and
// between time steps the geometry moves little: the factorization of an
// earlier system then preconditions the current one so well that GMRES needs
// one or two iterations (the preconditioned operator is the identity plus a
// low-rank term plus a small perturbation). This is the lagged-Jacobian
// practice of modified Newton methods (SUNDIALS' msbp, PETSc's
// -snes_lag_preconditioner), with the lag decided by cost. Costs are the
// model costs of core/linear/linear_cost.h (from the factor's size and the
// iteration counts), never measured times, so that the same scene makes the
// same choices on every run (reproducible to the bit):
//  * rent or buy: iterations beyond those a fresh factor needed are "rent";
//    the factor is renewed once the rent since it was computed has cost as
//    much as computing it did (at most twice the cost of the better choice).
//    An attempt's budget is thus what a fresh factor needed plus the rent
//    still affordable (when only S was factorized, a fresh factor needed ~15
//    iterations with friction, and a budget without them made every reuse
//    fail);
//  * an attempt is given up, once it has had the iterations a fresh factor
//    needed, as soon as its mean convergence rate cannot reach the tolerance
//    within the budget (many contacts changed; GMRES on a stale factor starts
//    slowly and then speeds up, so earlier judgements gave up good factors);
//  * after consecutive failures (the impact transient of a settling scene)
//    the next 1, 3, 7 solves refactorize without trying.
// When the caller tells how the system differs from the factorized one
// (expect(): the springs of contacts that changed state, a few rank-one
// terms each), the factor is corrected by them (low_rank_correction.h)
// instead of being renewed: a corrected factor preconditions as a fresh one
// does, up to the drift of the rest. Updates with more terms than a
// factorization costs in new columns are refactorized.
// With sliding friction A = S + F is unsymmetric. Factorizing only S (CHOLMOD)
// left F to GMRES: ~10 iterations per solve on the settled brick walls even
// with a fresh factor. A is therefore factorized itself, by an LU on the
// supernodal structure of S's Cholesky analysis (supernodal_lu.h; A has S's
// pattern), computed in float: a fresh factor needs two or three
// iterations, a stale one more, and the factorization costs about half a
// Cholesky one (settled 1,000-brick wall: 512 -> 141 iterations in 40 steps
// against the Cholesky of S). Should GMRES fail with a fresh factor,
// UMFPACK's pivoted LU is the fallback. Factors are applied in single
// precision (single_precision_factor.h): an iteration streams the factor and
// is memory-bound.
#include <algorithm>
#include <cmath>

#include "core/base/errors.h"
#include "core/base/stopwatch.h"
#include "core/io/checkpoint.h"
#include "core/linear/linear_cost.h"
#include "core/linear/low_rank_correction.h"
#include "core/linear/sparse_factorization.h"
#include "mechanics/dda/solver/block_solver.h"

namespace fissure {

namespace {

class ReusedFactorBlockSolver final : public BlockSolver {
 public:
  ReusedFactorBlockSolver(double tolerance, int max_iterations)
      : tolerance_(tolerance), max_iterations_(max_iterations), factor_(true) {}

  std::string name() const override { return "gmres with a reused factorization"; }

  // The factor stays usable as a preconditioner when the pattern changes;
  // only the next factorization needs a new analysis.
  void analyze(const BlockSparseMatrix&) override { factor_.pattern_changed(); }

  void expect(const LowRankUpdate* update) override { update_ = update; }
  bool factorized() const override { return factorized_; }
  /// As many terms as a factorization costs new columns of the correction
  /// (kFirstCorrectionRank until a correction was set up).
  int max_update_terms() const override {
    if (factor_cost_ == 0 || column_cost_ == 0) return kFirstCorrectionRank;
    return static_cast<int>(std::clamp(factor_cost_ / column_cost_, 1.0 * kMinCorrectionRank,
                                       1.0 * kMaxCorrectionRank));
  }

  double last_solve_cost() const override { return last_cost_; }

  void save(CheckpointWriter& out) const override { checkpoint(*this, out); }
  /// The factor is computed again from the matrix it stands for: the same
  /// matrix and pattern give the same factor to the bit. Its next
  /// factorization analyses its pattern again (the same pattern gives the
  /// same ordering; only the count of analyses can differ by one).
  void restore(CheckpointReader& in) override {
    checkpoint(*this, in);
    if (factored_matrix_.n_blocks() > 0) {
      factor_.pattern_changed();
      factor_.factorize(factored_matrix_, factored_method_);
      factor_.pattern_changed();
    }
    auto counters = in.section("factor_counters");
    SparseFactorization::checkpoint_counters(factor_, counters);
  }

  void solve(const BlockSparseMatrix& a, bool symmetric, const Eigen::VectorXd& b,
             Eigen::VectorXd& x) override {
    factorized_ = false;
    if (x.size() != b.size()) x = Eigen::VectorXd::Zero(b.size());
    const double b_norm = b.norm();
    if (b_norm == 0) {
      x.setZero();
      return;
    }
    ++solves_;
    last_cost_ = 0;
    correction_.clear();
    const bool usable = !factor_.empty() && factor_.rows() == b.size();
    int its = -1;
    if (usable && update_) {
      // The factor corrected for the contacts that changed since; a failed
      // attempt leaves nothing better to try than a fresh factor.
      if (static_cast<int>(update_->size()) <= max_update_terms())
        its = try_corrected(a, b, x, b_norm);
    } else if (usable && (skip_ == 0 || --skip_ == 0) && rent_ < factor_cost_) {
      its = try_reused(a, b, x, b_norm);
    }
    if (its < 0) its = solve_with_a_fresh_factor(a, symmetric, b, x, b_norm);
    iterations_ += its;
  }

  nlohmann::json statistics() const override {
    return {{"type", "reused factorization"},
            {"solves", solves_},
            {"iterations", iterations_},
            {"factorizations", factor_.cholesky_count() + factor_.lu_count()},
            {"failed_reuses", failed_reuses_},
            {"cholesky_factorizations", factor_.cholesky_count()},
            {"lu_factorizations", factor_.lu_count()},
            {"lu_fallbacks", lu_fallbacks_},
            {"corrected_solves", corrected_solves_},
            {"failed_corrections", failed_corrections_},
            {"corrected_rank", corrected_rank_},
            {"new_columns", new_columns_},
            {"correction_seconds", correction_seconds_},
            {"factorization_seconds", total_factor_seconds_},
            {"gmres_seconds", total_gmres_seconds_},
            // What the choices were made with (linear_cost.h), against the
            // measured times above.
            {"model_seconds",
             {{"factorization", model_factor_total_},
              {"gmres", model_gmres_total_},
              {"correction", model_correction_total_}}}};
  }

 private:
  /// Iterations beyond those a fresh factor needed that the rent still
  /// affords, at least `least`.
  int budget(int least) const {
    return std::clamp(fresh_iterations_ + static_cast<int>((factor_cost_ - rent_) /
                                                           std::max(iteration_cost_, 1e-12)),
                      least, max_iterations_);
  }

  /// GMRES preconditioned by the factor as it is; -1 when it gives up.
  int try_reused(const BlockSparseMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                 double b_norm) {
    const int its = gmres(a, b, x, b_norm, budget(2), fresh_iterations_);
    if (its < 0) {
      ++failed_reuses_;
      failures_in_a_row_ = std::min(failures_in_a_row_ + 1, 3);
      skip_ = (1 << failures_in_a_row_) - 1;
    } else {  // a failure renews the factor, which clears the rent
      charge_rent(its);
      failures_in_a_row_ = 0;
    }
    return its;
  }

  /// The iterations a solve took beyond those a fresh factor needed.
  void charge_rent(int its) { rent_ += std::max(its - fresh_iterations_, 0) * iteration_cost_; }

  /// GMRES preconditioned by the factor corrected by the expected update
  /// (low_rank_correction.h); -1 when it gives up.
  int try_corrected(const BlockSparseMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                    double b_norm) {
    const Stopwatch clock;
    const int columns = correction_.set_up(
        [this](const Eigen::MatrixXd& r, Eigen::MatrixXd& z) { factor_.solve(r, z); }, *update_,
        b.size());
    correction_seconds_ += clock.seconds();
    new_columns_ += columns;
    if (columns > 0) {
      const double cost = factor_.solve_cost(columns);
      last_cost_ += cost;
      model_correction_total_ += cost;
      column_cost_ = cost / columns;
    }
    ++corrected_solves_;
    // A correction that (nearly) cancels the factor's own stiffness leaves
    // H singular; GMRES would then fail on non-finite numbers. Either way the
    // attempt is given up and the iterate restored.
    int its = -1;
    if (correction_.well_conditioned()) {
      const Eigen::VectorXd start = x;
      try {
        its = gmres(a, b, x, b_norm, budget(fresh_iterations_ + 2), fresh_iterations_);
      } catch (const SolverError&) {
        x = start;
      }
    }
    if (its < 0) {
      ++failed_corrections_;
      correction_.clear();
      return its;
    }
    charge_rent(its);
    corrected_rank_ += correction_.rank();
    return its;
  }

  /// Factorizes A (Cholesky when symmetric, else the supernodal LU) and
  /// solves; UMFPACK's pivoted LU if that fails.
  int solve_with_a_fresh_factor(const BlockSparseMatrix& a, bool symmetric,
                                const Eigen::VectorXd& b, Eigen::VectorXd& x, double b_norm) {
    int its = -1;
    try {
      factorize(a, symmetric ? Method::Cholesky : Method::SupernodalLu);
      its = gmres(a, b, x, b_norm, max_iterations_);
    } catch (const SolverError&) {  // a zero pivot without pivoting across supernodes
      if (symmetric) throw;
    }
    if (its < 0) {
      ++lu_fallbacks_;
      factorize(a, Method::PivotedLu);
      its = gmres(a, b, x, b_norm, max_iterations_);
    }
    FISSURE_CHECK(its >= 0, SolverError,
                  "gmres with a fresh factorization did not converge in " << max_iterations_
                                                                          << " iterations");
    fresh_iterations_ = its;
    return its;
  }

  using Method = SparseFactorization::Method;

  template <class Self, class Archive>
  static void checkpoint(Self& self, Archive& a) {
    auto matrix = a.section("factored_matrix");
    BlockSparseMatrix::checkpoint(self.factored_matrix_, matrix);
    a("factored_method", self.factored_method_);
    if constexpr (!Archive::reading) {
      auto counters = a.section("factor_counters");
      SparseFactorization::checkpoint_counters(self.factor_, counters);
    }
    auto correction = a.section("correction");
    LowRankCorrection::checkpoint(self.correction_, correction);
    a("factor_cost", self.factor_cost_);
    a("iteration_cost", self.iteration_cost_);
    a("last_cost", self.last_cost_);
    a("done", self.done_);
    a("model_factor_total", self.model_factor_total_);
    a("model_gmres_total", self.model_gmres_total_);
    a("model_correction_total", self.model_correction_total_);
    a("rent", self.rent_);
    a("fresh_iterations", self.fresh_iterations_);
    a("failures_in_a_row", self.failures_in_a_row_);
    a("skip", self.skip_);
    a("factorized", self.factorized_);
    a("column_cost", self.column_cost_);
    a("new_columns", self.new_columns_);
    a("corrected_solves", self.corrected_solves_);
    a("failed_corrections", self.failed_corrections_);
    a("corrected_rank", self.corrected_rank_);
    a("solves", self.solves_);
    a("iterations", self.iterations_);
    a("failed_reuses", self.failed_reuses_);
    a("lu_fallbacks", self.lu_fallbacks_);
  }

  void factorize(const BlockSparseMatrix& a, Method method) {
    Stopwatch clock;
    factor_.factorize(a, method);
    factored_matrix_ = a;  // for a checkpoint: the factor is not stored
    factored_method_ = method;
    total_factor_seconds_ += clock.seconds();
    factor_cost_ = factor_.factorization_cost();
    last_cost_ += factor_cost_;
    model_factor_total_ += factor_cost_;
    factorized_ = true;
    correction_.forget();
    rent_ = 0;
  }

  /// gmres_iterations, with the model cost of an iteration (the unit of the
  /// rent): a product with A, an application of the factor and of the
  /// correction, and the vector work of a few Gram-Schmidt steps.
  int gmres(const BlockSparseMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd& x, double b_norm,
            int limit, int judge_after = 0) {
    const double n = b.size();
    iteration_cost_ =
        linear_cost::block_product(a.n_stored_blocks()) + factor_.solve_cost() +
        linear_cost::vector_operations(kVectorOperationsPerIteration + correction_.rank(), n);
    Stopwatch clock;
    const int its = gmres_iterations(a, b, x, b_norm, limit, judge_after);
    total_gmres_seconds_ += clock.seconds();
    last_cost_ += (done_ + 1) * iteration_cost_;  // and the first residual's product
    model_gmres_total_ += (done_ + 1) * iteration_cost_;
    return its;
  }

  /// Right-preconditioned restarted GMRES (Saad, Iterative Methods for Sparse
  /// Linear Systems, 2003, Alg. 9.5), started from x. Returns the iteration
  /// count, or -1 when the relative residual cannot reach the tolerance
  /// within `limit` iterations (judged from the convergence rate once
  /// `judge_after` iterations are done).
  int gmres_iterations(const BlockSparseMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                       double b_norm, int limit, int judge_after) {
    const double target = tolerance_ * b_norm;
    const Eigen::Index n = b.size();
    Eigen::VectorXd r(n), w(n);
    int total = 0;
    while (true) {
      a.multiply(x, w);
      r = b - w;
      const double beta = r.norm();
      FISSURE_CHECK(std::isfinite(beta), SolverError, "gmres: non-finite residual");
      if (beta <= target) return done_ = total;
      if (total >= limit) {
        done_ = total;
        return -1;
      }
      const int m = std::min(kRestart, limit - total);
      basis_.resize(n, m + 1);
      directions_.resize(n, m);  // preconditioned basis vectors
      hessenberg_.setZero(m + 1, m);
      Eigen::VectorXd g = Eigen::VectorXd::Zero(m + 1), cs(m), sn(m);
      basis_.col(0) = r / beta;
      g(0) = beta;
      int j = 0;
      while (j < m) {
        factor_.solve(basis_.col(j), z_);
        correction_.correct(z_);
        directions_.col(j) = z_;
        a.multiply(z_, w);
        auto h = hessenberg_.col(j);
        for (int i = 0; i <= j; ++i) {  // modified Gram-Schmidt
          h(i) = w.dot(basis_.col(i));
          w -= h(i) * basis_.col(i);
        }
        h(j + 1) = w.norm();
        if (h(j + 1) > 0) basis_.col(j + 1) = w / h(j + 1);
        for (int i = 0; i < j; ++i) {  // earlier Givens rotations
          const double t = cs(i) * h(i) + sn(i) * h(i + 1);
          h(i + 1) = -sn(i) * h(i) + cs(i) * h(i + 1);
          h(i) = t;
        }
        const double d = std::hypot(h(j), h(j + 1));
        FISSURE_CHECK(d > 0, SolverError, "gmres: the DDA system matrix is singular");
        const bool breakdown = h(j + 1) == 0;
        cs(j) = h(j) / d;
        sn(j) = h(j + 1) / d;
        h(j) = d;
        h(j + 1) = 0;
        g(j + 1) = -sn(j) * g(j);
        g(j) = cs(j) * g(j);
        ++j, ++total;
        const double residual = std::abs(g(j));
        if (residual <= target || breakdown) break;
        // The mean rate so far cannot reach the target within the limit.
        const double rate = std::pow(residual / beta, 1.0 / j);
        if (total >= judge_after &&
            (rate >= 1 || total + std::log(target / residual) / std::log(rate) > limit)) {
          done_ = total;
          return -1;
        }
      }
      const Eigen::VectorXd y =
          hessenberg_.topLeftCorner(j, j).triangularView<Eigen::Upper>().solve(g.head(j));
      x += directions_.leftCols(j) * y;
    }
  }

  static constexpr int kRestart = 40;
  // Bounds of the rank of a correction (the r x r matrix H is dense).
  static constexpr int kFirstCorrectionRank = 64, kMinCorrectionRank = 8, kMaxCorrectionRank = 256;

  double tolerance_;
  int max_iterations_;
  SparseFactorization factor_;         ///< applied in single precision
  BlockSparseMatrix factored_matrix_;  ///< the matrix factor_ stands for
  Method factored_method_ = Method::Cholesky;
  // Gram-Schmidt against a few basis vectors, norms and updates.
  static constexpr int kVectorOperationsPerIteration = 8;

  double factor_cost_ = 0;     ///< model cost of the last factorization
  double iteration_cost_ = 0;  ///< model cost of one gmres iteration
  double last_cost_ = 0;       ///< model cost of the last solve
  int done_ = 0;               ///< iterations of the last gmres_iterations, given up or not
  double total_factor_seconds_ = 0, total_gmres_seconds_ = 0;  ///< measured, for statistics
  double model_factor_total_ = 0, model_gmres_total_ = 0, model_correction_total_ = 0;
  double rent_ = 0;           ///< model cost of the extra iterations since the factorization
  int fresh_iterations_ = 0;  ///< iterations the solve after the factorization took
  int failures_in_a_row_ = 0, skip_ = 0;
  const LowRankUpdate* update_ = nullptr;  ///< A - (the factorized system), if known
  bool factorized_ = false;                ///< in the last solve
  LowRankCorrection correction_;
  double correction_seconds_ = 0;  ///< measured, for statistics
  double column_cost_ = 0;         ///< model set-up cost per new column of the last correction
  long new_columns_ = 0;
  long corrected_solves_ = 0, failed_corrections_ = 0, corrected_rank_ = 0;
  Eigen::MatrixXd basis_, directions_, hessenberg_;
  Eigen::VectorXd z_;
  long solves_ = 0, iterations_ = 0, failed_reuses_ = 0, lu_fallbacks_ = 0;
};

}  // namespace

std::unique_ptr<BlockSolver> make_reused_factor_solver(double relative_tolerance,
                                                       int max_iterations) {
  return std::make_unique<ReusedFactorBlockSolver>(relative_tolerance, max_iterations);
}

}  // namespace fissure
