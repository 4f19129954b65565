// Direct back end: CHOLMOD supernodal LL^T (symmetric systems) and UMFPACK LU
// (systems with implicit friction terms), both through Eigen's wrappers.
#include <Eigen/CholmodSupport>
#include <Eigen/UmfPackSupport>

#include "core/base/errors.h"
#include "core/linear/block_solver.h"
#include "core/linear/scalar_copy.h"

namespace fissure {

namespace {

class DirectBlockSolver final : public BlockSolver {
 public:
  DirectBlockSolver() {
    // The pattern is symmetric and the diagonal dominant (inertia, springs):
    // UMFPACK's symmetric strategy, no iterative refinement (the open-close
    // iteration re-solves anyway; refinement tripled the cost of each solve).
    lu_.umfpackControl()(UMFPACK_STRATEGY) = UMFPACK_STRATEGY_SYMMETRIC;
    lu_.umfpackControl()(UMFPACK_IRSTEP) = 0;
  }

  std::string name() const override { return "direct (CHOLMOD Cholesky / UMFPACK LU)"; }

  void analyze(const BlockSparseMatrix&) override {
    // Patterns are (re)built lazily, per kind, on the first solve after a change.
    lower_valid_ = full_valid_ = false;
  }

  void solve(const BlockSparseMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
             bool symmetric) override {
    if (symmetric) {
      if (!lower_valid_) {
        lower_.build_pattern(a, true);
        lower_.copy_values(a);
        llt_.analyzePattern(lower_.matrix());
        lower_valid_ = true;
        ++analyses_;
      }
      lower_.copy_values(a);
      llt_.factorize(lower_.matrix());
      FISSURE_CHECK(llt_.info() == Eigen::Success, SolverError,
                    "CHOLMOD: the DDA system matrix is not positive definite (a free block "
                    "without mass, or a non-physical material?)");
      x = llt_.solve(b);
      ++cholesky_;
    } else {
      if (!full_valid_) {
        full_.build_pattern(a, false);
        full_.copy_values(a);
        lu_.analyzePattern(full_.matrix());
        full_valid_ = true;
        ++analyses_;
      }
      full_.copy_values(a);
      lu_.factorize(full_.matrix());
      FISSURE_CHECK(lu_.info() == Eigen::Success, SolverError,
                    "UMFPACK: the DDA system matrix is singular");
      x = lu_.solve(b);
      ++lu_count_;
    }
  }

  nlohmann::json statistics() const override {
    return {{"type", "direct"},
            {"analyses", analyses_},
            {"cholesky_factorizations", cholesky_},
            {"lu_factorizations", lu_count_}};
  }

 private:
  ScalarCopy lower_, full_;
  bool lower_valid_ = false, full_valid_ = false;
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt_;
  Eigen::UmfPackLU<Eigen::SparseMatrix<double>> lu_;
  long analyses_ = 0, cholesky_ = 0, lu_count_ = 0;
};

}  // namespace

std::unique_ptr<BlockSolver> make_direct_solver() { return std::make_unique<DirectBlockSolver>(); }

}  // namespace fissure
