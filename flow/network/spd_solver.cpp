// Direct (CHOLMOD) and Jacobi-PCG back ends, and the choice among the three.
#include "flow/network/spd_solver.h"

#include <Eigen/CholmodSupport>
#include <Eigen/IterativeLinearSolvers>

#include "core/base/errors.h"
#include "core/linear/serial_cholmod.h"

namespace fissure::flow {

namespace {

class DirectSpdSolver final : public SpdSolver {
 public:
  DirectSpdSolver() {
    keep_cholmod_serial();
    llt_.cholmod().print = 0;  // a failure is reported by factorize(), once, not on stderr
  }

  std::string name() const override { return "direct (CHOLMOD Cholesky)"; }

  void analyze(const SparseMatrix& a) override {
    llt_.analyzePattern(a);
    ++analyses_;
  }

  void factorize(const SparseMatrix& a) override {
    llt_.factorize(a);
    FISSURE_CHECK(llt_.info() == Eigen::Success, SolverError,
                  "CHOLMOD: the flow network matrix is not positive definite (a segment with a "
                  "negative or non-finite conductance?)");
    ++factorizations_;
  }

  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    x = llt_.solve(b);
    ++solves_;
  }

  nlohmann::json statistics() const override {
    return {{"analyses", analyses_}, {"factorizations", factorizations_}, {"solves", solves_}};
  }

 private:
  Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower> llt_;
  long analyses_ = 0, factorizations_ = 0, solves_ = 0;
};

class PcgSpdSolver final : public SpdSolver {
 public:
  PcgSpdSolver(double tolerance, int max_iterations) {
    cg_.setTolerance(tolerance);
    cg_.setMaxIterations(max_iterations);
  }
  std::string name() const override { return "pcg (Eigen CG, Jacobi preconditioner)"; }
  void analyze(const SparseMatrix&) override {}
  void factorize(const SparseMatrix& a) override { cg_.compute(a); }
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    if (x.size() != b.size()) x = Eigen::VectorXd::Zero(b.size());
    x = cg_.solveWithGuess(b, x);
    FISSURE_CHECK(cg_.info() == Eigen::Success, SolverError,
                  "flow: conjugate gradients did not converge in "
                      << cg_.iterations() << " iterations (relative residual " << cg_.error()
                      << "); raise flow.solver.max_iterations or use type direct");
    ++solves_;
    iterations_ += cg_.iterations();
  }
  nlohmann::json statistics() const override {
    return {{"solves", solves_}, {"iterations", iterations_}};
  }

 private:
  Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper> cg_;
  long solves_ = 0, iterations_ = 0;
};

}  // namespace

std::unique_ptr<SpdSolver> make_direct_spd_solver() {
  return std::make_unique<DirectSpdSolver>();
}

std::unique_ptr<SpdSolver> make_pcg_spd_solver(double relative_tolerance, int max_iterations) {
  return std::make_unique<PcgSpdSolver>(relative_tolerance, max_iterations);
}

std::unique_ptr<SpdSolver> make_spd_solver(const LinearSolverControls& c, int n_unknowns,
                                           bool allow_petsc) {
  using Type = LinearSolverControls::Type;
  switch (c.type) {
    case Type::Direct:
      return make_direct_spd_solver();
    case Type::Pcg:
      return make_pcg_spd_solver(c.relative_tolerance, c.max_iterations);
    case Type::Petsc:
#ifdef FISSURE_WITH_PETSC
      if (allow_petsc) return make_petsc_spd_solver(c);
#endif
      return make_direct_spd_solver();
    case Type::Auto:
#ifdef FISSURE_WITH_PETSC
      if (allow_petsc && n_unknowns >= kAutoPetscUnknowns) return make_petsc_spd_solver(c);
#endif
      return make_direct_spd_solver();
  }
  return make_direct_spd_solver();
}

}  // namespace fissure::flow
