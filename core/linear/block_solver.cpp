#include "core/linear/block_solver.h"

#include <algorithm>

#include "core/base/errors.h"

namespace fissure {

namespace {

/// `auto`: the direct solver for small systems; above the threshold block-
/// Jacobi Krylov (its cost grows linearly with the system), falling back to
/// the direct solver for a solve that does not converge (very stiff steps).
class AutoBlockSolver final : public BlockSolver {
 public:
  explicit AutoBlockSolver(const LinearSolverControls& c)
      : direct_(make_direct_solver()),
        iterative_(make_pcg_solver(c.relative_tolerance, std::min(c.max_iterations, kPcgCap))) {}

  std::string name() const override { return "auto (direct below 300 blocks, else pcg)"; }

  void analyze(const BlockSparseMatrix& a) override {
    use_direct_ = a.n_blocks() < kDirectBelow;
    direct_->analyze(a);
    iterative_->analyze(a);
  }

  void solve(const BlockSparseMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
             bool symmetric) override {
    if (!use_direct_) {
      try {
        iterative_->solve(a, b, x, symmetric);
        return;
      } catch (const SolverError&) {
        ++fallbacks_;  // not converged within max_iterations: solve directly
      }
    }
    direct_->solve(a, b, x, symmetric);
  }

  nlohmann::json statistics() const override {
    return {{"type", "auto"},
            {"direct", direct_->statistics()},
            {"pcg", iterative_->statistics()},
            {"pcg_fallbacks_to_direct", fallbacks_}};
  }

 private:
  static constexpr int kDirectBelow = 300;
  // Beyond this many iterations a direct solve is cheaper than going on.
  static constexpr int kPcgCap = 300;
  std::unique_ptr<BlockSolver> direct_, iterative_;
  bool use_direct_ = true;
  long fallbacks_ = 0;
};

}  // namespace

std::unique_ptr<BlockSolver> make_block_solver(const LinearSolverControls& c) {
  switch (c.type) {
    case LinearSolverControls::Type::Auto: return std::make_unique<AutoBlockSolver>(c);
    case LinearSolverControls::Type::Direct: return make_direct_solver();
    case LinearSolverControls::Type::Pcg: return make_pcg_solver(c.relative_tolerance, c.max_iterations);
    case LinearSolverControls::Type::Petsc: return make_petsc_solver(c);
  }
  throw SolverError("unknown linear solver type");
}

}  // namespace fissure
