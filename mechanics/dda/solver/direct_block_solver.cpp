// Direct back end: a fresh sparse factorization per solve (CHOLMOD Cholesky
// for symmetric systems, UMFPACK LU for those with implicit friction terms).
#include "core/linear/sparse_factorization.h"
#include "mechanics/dda/solver/block_solver.h"

#include "core/io/checkpoint.h"

namespace fissure {

namespace {

class DirectBlockSolver final : public BlockSolver {
 public:
  std::string name() const override { return "direct (CHOLMOD Cholesky / UMFPACK LU)"; }

  void analyze(const BlockSparseMatrix&) override { factor_.pattern_changed(); }

  void solve(const BlockSparseMatrix& a, bool symmetric, const Eigen::VectorXd& b,
             Eigen::VectorXd& x) override {
    factor_.factorize(a, symmetric ? SparseFactorization::Method::Cholesky
                                   : SparseFactorization::Method::PivotedLu);
    factor_.solve(b, x);
  }

  nlohmann::json statistics() const override {
    return {{"type", "direct"},
            {"analyses", factor_.analyses()},
            {"cholesky_factorizations", factor_.cholesky_count()},
            {"lu_factorizations", factor_.lu_count()}};
  }

  // Factorized for every solve: only its counters carry over.
  void save(CheckpointWriter& out) const override {
    SparseFactorization::checkpoint_counters(factor_, out);
  }
  void restore(CheckpointReader& in) override {
    SparseFactorization::checkpoint_counters(factor_, in);
  }

 private:
  SparseFactorization factor_;
};

}  // namespace

std::unique_ptr<BlockSolver> make_direct_solver() {
  return std::make_unique<DirectBlockSolver>();
}

}  // namespace fissure
