// PETSc back end of the network solvers: AIJ matrix of the symmetrically
// diagonal-scaled system, KSP CG + hypre BoomerAMG by default (theory.md 3.3:
// conductances span ~1e9, so scale, then CG + AMG). KSPSetFromOptions comes
// after the defaults, so the scene's `flow.solver.petsc_options` (prefix
// flow_) win, and the environment's PETSC_OPTIONS over them.
#include "flow/network/spd_solver.h"

#ifdef FISSURE_WITH_PETSC
#include <petscksp.h>

#include <cctype>
#include <cmath>
#include <sstream>
#include <vector>

#include "core/base/errors.h"
#include "core/linear/petsc_options.h"
#include "core/linear/petsc_session.h"

namespace fissure::flow {

namespace {

class PetscSpdSolver final : public SpdSolver {
 public:
  explicit PetscSpdSolver(const LinearSolverControls& c) {
    ensure_petsc_initialized();
    options_.add(petsc_options_with_prefix(c.petsc_options, "flow_"));
    FISSURE_PETSC_CALL(KSPCreate(PETSC_COMM_SELF, &ksp_));
    FISSURE_PETSC_CALL(KSPSetOptionsPrefix(ksp_, "flow_"));
    FISSURE_PETSC_CALL(KSPSetType(ksp_, KSPCG));
    PC pc;
    FISSURE_PETSC_CALL(KSPGetPC(ksp_, &pc));
#ifdef PETSC_HAVE_HYPRE
    FISSURE_PETSC_CALL(PCSetType(pc, PCHYPRE));
    FISSURE_PETSC_CALL(PCHYPRESetType(pc, "boomeramg"));
#else
    FISSURE_PETSC_CALL(PCSetType(pc, PCGAMG));
#endif
    FISSURE_PETSC_CALL(
        KSPSetTolerances(ksp_, c.relative_tolerance, 1e-300, PETSC_DEFAULT, c.max_iterations));
    FISSURE_PETSC_CALL(KSPSetInitialGuessNonzero(ksp_, PETSC_TRUE));
    check_scene_options_call(KSPSetFromOptions(ksp_), "KSPSetFromOptions", c);
  }

  ~PetscSpdSolver() override {
    if (matrix_) MatDestroy(&matrix_);
    if (b_) VecDestroy(&b_);
    if (x_) VecDestroy(&x_);
    KSPDestroy(&ksp_);
  }

  std::string name() const override {
    KSPType type;
    PC pc;
    PCType pc_type;
    KSPGetType(ksp_, &type);
    KSPGetPC(ksp_, &pc);
    PCGetType(pc, &pc_type);
    return std::string("petsc (KSP ") + (type ? type : "?") + " + PC " + (pc_type ? pc_type : "?") +
           ", diagonal scaling)";
  }

  void analyze(const SparseMatrix& a) override {
    if (matrix_) FISSURE_PETSC_CALL(MatDestroy(&matrix_));
    if (b_) FISSURE_PETSC_CALL(VecDestroy(&b_));
    if (x_) FISSURE_PETSC_CALL(VecDestroy(&x_));
    const PetscInt n = a.rows();
    std::vector<PetscInt> nnz(n);
    // Column j of the (symmetric) CSC matrix is row j.
    for (PetscInt j = 0; j < n; ++j) nnz[j] = a.outerIndexPtr()[j + 1] - a.outerIndexPtr()[j];
    FISSURE_PETSC_CALL(MatCreateSeqAIJ(PETSC_COMM_SELF, n, n, 0, nnz.data(), &matrix_));
    FISSURE_PETSC_CALL(MatSetOption(matrix_, MAT_SYMMETRIC, PETSC_TRUE));
    FISSURE_PETSC_CALL(MatSetOption(matrix_, MAT_SPD, PETSC_TRUE));
    FISSURE_PETSC_CALL(MatCreateVecs(matrix_, &x_, &b_));
  }

  void factorize(const SparseMatrix& a) override {
    const PetscInt n = a.rows();
    scale_.resize(n);
    for (PetscInt j = 0; j < n; ++j) scale_[j] = 1 / std::sqrt(a.coeff(j, j));
    std::vector<PetscInt> cols;
    std::vector<PetscScalar> values;
    for (PetscInt j = 0; j < n; ++j) {
      cols.clear();
      values.clear();
      for (SparseMatrix::InnerIterator it(a, j); it; ++it) {
        cols.push_back(it.row());
        values.push_back(it.value() * scale_[j] * scale_[it.row()]);
      }
      FISSURE_PETSC_CALL(MatSetValues(matrix_, 1, &j, static_cast<PetscInt>(cols.size()),
                                      cols.data(), values.data(), INSERT_VALUES));
    }
    FISSURE_PETSC_CALL(MatAssemblyBegin(matrix_, MAT_FINAL_ASSEMBLY));
    FISSURE_PETSC_CALL(MatAssemblyEnd(matrix_, MAT_FINAL_ASSEMBLY));
    FISSURE_PETSC_CALL(KSPSetOperators(ksp_, matrix_, matrix_));
    FISSURE_PETSC_CALL(KSPSetUp(ksp_));
    ++setups_;
  }

  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    const PetscInt n = b.size();
    const bool guess = x.size() == n;
    PetscScalar *pb, *px;
    FISSURE_PETSC_CALL(VecGetArray(b_, &pb));
    FISSURE_PETSC_CALL(VecGetArray(x_, &px));
    for (PetscInt i = 0; i < n; ++i) {
      pb[i] = b[i] * scale_[i];
      px[i] = guess ? x[i] / scale_[i] : 0.0;
    }
    FISSURE_PETSC_CALL(VecRestoreArray(b_, &pb));
    FISSURE_PETSC_CALL(VecRestoreArray(x_, &px));
    FISSURE_PETSC_CALL(KSPSolve(ksp_, b_, x_));
    KSPConvergedReason reason;
    PetscInt its = 0;
    FISSURE_PETSC_CALL(KSPGetConvergedReason(ksp_, &reason));
    FISSURE_PETSC_CALL(KSPGetIterationNumber(ksp_, &its));
    FISSURE_CHECK(reason > 0, SolverError,
                  "flow: PETSc KSP did not converge (reason "
                      << reason << " after " << its
                      << " iterations); raise flow.solver.max_iterations or use type direct");
    iterations_ += its;
    ++solves_;
    x.resize(n);
    const PetscScalar* cx;
    FISSURE_PETSC_CALL(VecGetArrayRead(x_, &cx));
    for (PetscInt i = 0; i < n; ++i) x[i] = cx[i] * scale_[i];
    FISSURE_PETSC_CALL(VecRestoreArrayRead(x_, &cx));
  }

  nlohmann::json statistics() const override {
    return {{"setups", setups_}, {"solves", solves_}, {"iterations", iterations_}};
  }

 private:
  PetscOptionsLease options_;  ///< the scene's petsc_options, while the solver lives
  KSP ksp_ = nullptr;
  Mat matrix_ = nullptr;
  Vec b_ = nullptr, x_ = nullptr;
  std::vector<double> scale_;
  long setups_ = 0, solves_ = 0, iterations_ = 0;
};

}  // namespace

std::unique_ptr<SpdSolver> make_petsc_spd_solver(const LinearSolverControls& controls) {
  return std::make_unique<PetscSpdSolver>(controls);
}

}  // namespace fissure::flow

#else
namespace fissure::flow {
std::unique_ptr<SpdSolver> make_petsc_spd_solver(const LinearSolverControls&) {
  return make_direct_spd_solver();
}
}  // namespace fissure::flow
#endif
