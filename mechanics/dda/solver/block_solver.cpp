#include "mechanics/dda/solver/block_solver.h"

#include <algorithm>

#include "core/base/errors.h"
#include "core/io/checkpoint.h"
#include "core/linear/cheaper_of_two.h"

namespace fissure {

namespace {

/// `auto`: the direct solver for small systems. Above the threshold two
/// back ends compete on cost, because neither wins everywhere: block-Jacobi
/// Krylov is cheapest when inertia dominates (small dt, dynamic runs: tens
/// of iterations), the reused factorization when contact springs dominate
/// (dt near the static limit: block-Jacobi needs hundreds of iterations;
/// docs/performance.md "dda_scaling"). Each solve goes to the back end with
/// the lower running mean cost per solve; the other one is probed every
/// kProbeEvery solves times the ratio of the two costs (CheaperOfTwo), so
/// that its estimate follows the changing system. Costs are the back ends'
/// model costs (core/linear/linear_cost.h: operation and memory counts),
/// not clocks: the same scene takes the same choices on every run, whatever
/// the load of the machine, and its results are the same to the bit.
/// A Krylov solve is given up, and finished by the factorization, once it
/// has cost what a factored solve costs on average (rent or buy again: a
/// losing probe costs at most twice the better choice; with a fixed cap of
/// 300 iterations a probe on the settled 10,000-brick wall cost ~1.3 s
/// against ~0.5 s for a factored solve), and after kPcgCap iterations at most.
class AutoBlockSolver final : public BlockSolver {
 public:
  explicit AutoBlockSolver(const LinearSolverControls& c)
      : direct_(make_direct_solver()),
        factored_(make_reused_factor_solver(c.relative_tolerance, c.max_iterations)),
        iterative_(make_pcg_solver(c.relative_tolerance, std::min(c.max_iterations, kPcgCap))),
        max_cap_(std::min(c.max_iterations, kPcgCap)) {}

  std::string name() const override {
    return "auto (direct below 300 blocks, else the cheaper of pcg and a reused factorization)";
  }

  void analyze(const BlockSparseMatrix& a) override {
    use_direct_ = a.n_blocks() < kDirectBelow;
    direct_->analyze(a);
    factored_->analyze(a);
    iterative_->analyze(a);
  }

  void expect(const LowRankUpdate* update) override { factored_->expect(update); }
  bool factorized() const override { return factorized_; }
  int max_update_terms() const override { return use_direct_ ? 0 : factored_->max_update_terms(); }

  void solve(const BlockSparseMatrix& a, bool symmetric, const Eigen::VectorXd& b,
             Eigen::VectorXd& x) override {
    factorized_ = false;
    if (use_direct_) {
      direct_->solve(a, symmetric, b, x);
      return;
    }
    double given_up = 0;  // cost of a Krylov attempt that did not converge
    if (choice_.pick() == kIterative) {
      const int cap = iteration_cap();
      iterative_->set_max_iterations(cap);
      const long before = iterative_->statistics()["iterations"].get<long>();
      try {
        iterative_->solve(a, symmetric, b, x);
        const double cost = iterative_->last_solve_cost();
        choice_.record(kIterative, cost);
        const long its = iterative_->statistics()["iterations"].get<long>() - before;
        if (its > 0) iteration_cost_ = cost / its;
        return;
      } catch (const SolverError&) {
        ++fallbacks_;  // not converged within the cap
        given_up = iterative_->last_solve_cost();
        iteration_cost_ = given_up / cap;
      }
    }
    factored_->solve(a, symmetric, b, x);
    factorized_ = factored_->factorized();
    const double factored = factored_->last_solve_cost();
    choice_.record(kFactored, factored);
    // Choosing the Krylov solver cost both when it gave up.
    if (given_up > 0) choice_.record(kIterative, given_up + factored);
  }

  nlohmann::json statistics() const override {
    return {{"type", "auto"},
            {"direct", direct_->statistics()},
            {"reused_factorization", factored_->statistics()},
            {"pcg", iterative_->statistics()},
            {"pcg_fallbacks", fallbacks_}};
  }

  void save(CheckpointWriter& out) const override { checkpoint(*this, out); }
  void restore(CheckpointReader& in) override { checkpoint(*this, in); }

 private:
  enum { kFactored, kIterative };

  template <class Self, class Archive>
  static void checkpoint(Self& self, Archive& a) {
    a("use_direct", self.use_direct_);
    a("iteration_cost", self.iteration_cost_);
    a("fallbacks", self.fallbacks_);
    a("factorized", self.factorized_);
    auto choice = a.section("choice");
    CheaperOfTwo::checkpoint(self.choice_, choice);
    checkpoint_part(a, "direct", *self.direct_);
    checkpoint_part(a, "reused_factorization", *self.factored_);
    checkpoint_part(a, "pcg", *self.iterative_);
  }
  static void checkpoint_part(CheckpointWriter& a, const char* name, const BlockSolver& s) {
    auto section = a.section(name);
    s.save(section);
  }
  static void checkpoint_part(CheckpointReader& a, const char* name, BlockSolver& s) {
    auto section = a.section(name);
    s.restore(section);
  }

  /// Iterations of the Krylov back end that cost what a factored solve does
  /// on average (the largest cap until both have been costed).
  int iteration_cap() const {
    const double factored = choice_.cost(kFactored);
    if (factored == 0 || iteration_cost_ == 0) return max_cap_;
    const double affordable = factored / iteration_cost_;
    return std::min(max_cap_, std::max(kMinPcgCap, static_cast<int>(std::min(affordable, 1e6))));
  }

  static constexpr int kDirectBelow = 300;
  // The most Krylov iterations a solve in auto may take; the affordable cap
  // (iteration_cap) is usually lower.
  static constexpr int kPcgCap = 300;
  static constexpr int kMinPcgCap = 10;
  static constexpr long kProbeEvery = 8;
  std::unique_ptr<BlockSolver> direct_, factored_, iterative_;
  const int max_cap_;  ///< the user's max_iterations, at most kPcgCap
  bool use_direct_ = true;
  CheaperOfTwo choice_{kProbeEvery};
  double iteration_cost_ = 0;  ///< model cost of one Krylov iteration, last solve
  long fallbacks_ = 0;
  bool factorized_ = false;  ///< by the reused factorization in the last solve
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
