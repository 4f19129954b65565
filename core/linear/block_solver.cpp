#include "core/linear/block_solver.h"

#include <algorithm>

#include "core/base/errors.h"
#include "core/base/stopwatch.h"
#include "core/linear/cheaper_of_two.h"

namespace fissure {

namespace {

/// `auto`: the direct solver for small systems. Above the threshold two
/// back ends compete on measured cost, because neither wins everywhere:
/// block-Jacobi Krylov is cheapest when inertia dominates (small dt, dynamic
/// runs: tens of iterations), the reused factorization when contact springs
/// dominate (dt near the static limit: block-Jacobi needs hundreds of
/// iterations; docs/performance.md "dda_scaling"). Each solve goes to the back
/// end with the lower running mean cost per solve; every kProbeEvery-th solve
/// goes to the other one, so that its estimate follows the changing system.
/// A Krylov solve that does not converge within kPcgCap iterations is
/// finished by the factorization.
class AutoBlockSolver final : public BlockSolver {
 public:
  explicit AutoBlockSolver(const LinearSolverControls& c)
      : direct_(make_direct_solver()),
        factored_(make_reused_factor_solver(c.relative_tolerance, c.max_iterations)),
        iterative_(make_pcg_solver(c.relative_tolerance, std::min(c.max_iterations, kPcgCap))) {}

  std::string name() const override {
    return "auto (direct below 300 blocks, else the cheaper of pcg and a reused factorization)";
  }

  void analyze(const BlockSparseMatrix& a) override {
    use_direct_ = a.n_blocks() < kDirectBelow;
    direct_->analyze(a);
    factored_->analyze(a);
    iterative_->analyze(a);
  }

  void solve(const BlockSparseMatrix& a, const BlockSparseMatrix* spd_part,
             const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    if (use_direct_) {
      direct_->solve(a, spd_part, b, x);
      return;
    }
    Stopwatch clock;
    if (choice_.pick() == kIterative) {
      try {
        iterative_->solve(a, spd_part, b, x);
        choice_.record(kIterative, clock.seconds());
        return;
      } catch (const SolverError&) {
        ++fallbacks_;  // not converged within kPcgCap iterations
        choice_.record(kIterative, clock.seconds());
      }
    }
    clock.restart();
    factored_->solve(a, spd_part, b, x);
    choice_.record(kFactored, clock.seconds());
  }

  nlohmann::json statistics() const override {
    return {{"type", "auto"},
            {"direct", direct_->statistics()},
            {"reused_factorization", factored_->statistics()},
            {"pcg", iterative_->statistics()},
            {"pcg_fallbacks", fallbacks_}};
  }

 private:
  enum { kFactored, kIterative };

  static constexpr int kDirectBelow = 300;
  // Beyond this many iterations a factorization is cheaper than going on.
  static constexpr int kPcgCap = 300;
  static constexpr long kProbeEvery = 8;
  std::unique_ptr<BlockSolver> direct_, factored_, iterative_;
  bool use_direct_ = true;
  CheaperOfTwo choice_{kProbeEvery};
  long fallbacks_ = 0;
};

}  // namespace

std::unique_ptr<BlockSolver> make_block_solver(const LinearSolverControls& c) {
  switch (c.type) {
    case LinearSolverControls::Type::Auto:
      return std::make_unique<AutoBlockSolver>(c);
    case LinearSolverControls::Type::Direct:
      return make_direct_solver();
    case LinearSolverControls::Type::Pcg:
      return make_pcg_solver(c.relative_tolerance, c.max_iterations);
    case LinearSolverControls::Type::Petsc:
      return make_petsc_solver(c);
  }
  throw SolverError("unknown linear solver type");
}

}  // namespace fissure
