// PETSc back end: AIJ matrix with block size 6, KSP configured in code
// (cg, gmres when implicit friction makes the system unsymmetric, with
// ILU(0); the scene's tolerance) and then from the scene's `petsc_options`
// (prefix dda_), so that users can pick e.g. hypre. GAMG diverged on the
// unsymmetric friction systems of a settling wall (docs/performance.md).
#include "core/base/errors.h"
#include "core/io/checkpoint.h"
#include "mechanics/dda/solver/block_solver.h"

#ifdef FISSURE_WITH_PETSC
#include <petscksp.h>

#include <sstream>

#include "core/linear/petsc_options.h"
#include "core/linear/petsc_session.h"

namespace fissure {

namespace {

class PetscBlockSolver final : public BlockSolver {
 public:
  explicit PetscBlockSolver(const LinearSolverControls& c) : controls_(c) {
    ensure_petsc_initialized();
    options_.add(petsc_options_with_prefix(c.petsc_options, "dda_"));
    FISSURE_PETSC_CALL(KSPCreate(PETSC_COMM_SELF, &ksp_));
    FISSURE_PETSC_CALL(KSPSetOptionsPrefix(ksp_, "dda_"));
    FISSURE_PETSC_CALL(KSPSetType(ksp_, KSPCG));
    PC pc;
    FISSURE_PETSC_CALL(KSPGetPC(ksp_, &pc));
    FISSURE_PETSC_CALL(PCSetType(pc, PCILU));
    FISSURE_PETSC_CALL(
        KSPSetTolerances(ksp_, c.relative_tolerance, 1e-300, PETSC_DEFAULT, c.max_iterations));
    FISSURE_PETSC_CALL(KSPSetInitialGuessNonzero(ksp_, PETSC_TRUE));
    check_scene_options_call(KSPSetFromOptions(ksp_), "KSPSetFromOptions", c);
    KSPType type;
    FISSURE_PETSC_CALL(KSPGetType(ksp_, &type));
    symmetric_type_ = type;
  }

  ~PetscBlockSolver() override {
    if (matrix_) MatDestroy(&matrix_);
    KSPDestroy(&ksp_);
  }

  std::string name() const override { return "petsc (KSP, AIJ with block size 6)"; }

  void analyze(const BlockSparseMatrix& a) override {
    if (matrix_) FISSURE_PETSC_CALL(MatDestroy(&matrix_));
    // AIJ with block size 6 (every PC, GAMG included, can use it); blocks
    // are still inserted whole with MatSetValuesBlocked.
    const int n = a.n_blocks();
    std::vector<PetscInt> nnz(6 * n);
    for (int i = 0; i < n; ++i)
      for (int r = 0; r < 6; ++r) nnz[6 * i + r] = 6 * (a.row_start()[i + 1] - a.row_start()[i]);
    FISSURE_PETSC_CALL(MatCreate(PETSC_COMM_SELF, &matrix_));
    FISSURE_PETSC_CALL(MatSetSizes(matrix_, 6 * n, 6 * n, 6 * n, 6 * n));
    FISSURE_PETSC_CALL(MatSetType(matrix_, MATSEQAIJ));
    FISSURE_PETSC_CALL(MatSetBlockSize(matrix_, 6));
    FISSURE_PETSC_CALL(MatSeqAIJSetPreallocation(matrix_, 0, nnz.data()));
    FISSURE_PETSC_CALL(
        MatSetOption(matrix_, MAT_ROW_ORIENTED, PETSC_FALSE));  // Eigen is column-major
  }

  void solve(const BlockSparseMatrix& a, bool symmetric, const Eigen::VectorXd& b,
             Eigen::VectorXd& x) override {
    // Implicit friction makes the system unsymmetric: CG is replaced by GMRES.
    FISSURE_PETSC_CALL(MatSetOption(matrix_, MAT_SPD, symmetric ? PETSC_TRUE : PETSC_FALSE));
    FISSURE_PETSC_CALL(KSPSetType(ksp_, symmetric ? symmetric_type_.c_str() : KSPGMRES));
    const auto start = a.row_start();
    const auto cols = a.columns();
    for (PetscInt i = 0; i < a.n_blocks(); ++i)
      for (int k = start[i]; k < start[i + 1]; ++k) {
        const PetscInt j = cols[k];
        FISSURE_PETSC_CALL(
            MatSetValuesBlocked(matrix_, 1, &i, 1, &j, a.value(k).data(), INSERT_VALUES));
      }
    FISSURE_PETSC_CALL(MatAssemblyBegin(matrix_, MAT_FINAL_ASSEMBLY));
    FISSURE_PETSC_CALL(MatAssemblyEnd(matrix_, MAT_FINAL_ASSEMBLY));
    FISSURE_PETSC_CALL(KSPSetOperators(ksp_, matrix_, matrix_));

    if (x.size() != b.size()) x = Eigen::VectorXd::Zero(b.size());
    Vec vb, vx;
    FISSURE_PETSC_CALL(VecCreateSeqWithArray(PETSC_COMM_SELF, 6, b.size(), b.data(), &vb));
    FISSURE_PETSC_CALL(VecCreateSeqWithArray(PETSC_COMM_SELF, 6, x.size(), x.data(), &vx));
    const PetscErrorCode solve_error = KSPSolve(ksp_, vb, vx);
    VecDestroy(&vb);
    VecDestroy(&vx);
    FISSURE_CHECK(solve_error == 0, SolverError,
                  "PETSc KSPSolve failed (error " << solve_error << ")");
    KSPConvergedReason reason;
    PetscInt its = 0;
    FISSURE_PETSC_CALL(KSPGetConvergedReason(ksp_, &reason));
    FISSURE_PETSC_CALL(KSPGetIterationNumber(ksp_, &its));
    iterations_ += its;
    ++solves_;
    FISSURE_CHECK(reason > 0, SolverError,
                  "PETSc KSP did not converge (" << KSPConvergedReasons[reason] << " after " << its
                                                 << " iterations)");
  }

  nlohmann::json statistics() const override {
    return {{"type", "petsc"},
            {"solves", solves_},
            {"iterations", iterations_},
            {"options", controls_.petsc_options}};
  }

  // Warm-started from the caller's x; the preconditioner is set up again
  // for every solve: only the counters carry over.
  void save(CheckpointWriter& out) const override {
    out("solves", solves_);
    out("iterations", iterations_);
  }
  void restore(CheckpointReader& in) override {
    in("solves", solves_);
    in("iterations", iterations_);
  }

 private:
  PetscOptionsLease options_;  ///< the scene's petsc_options, while the solver lives
  LinearSolverControls controls_;
  KSP ksp_ = nullptr;
  std::string symmetric_type_;
  Mat matrix_ = nullptr;
  long solves_ = 0, iterations_ = 0;
};

}  // namespace

std::unique_ptr<BlockSolver> make_petsc_solver(const LinearSolverControls& c) {
  return std::make_unique<PetscBlockSolver>(c);
}

}  // namespace fissure

#else

namespace fissure {
std::unique_ptr<BlockSolver> make_petsc_solver(const LinearSolverControls&) {
  throw SolverError("this build of Fissure has no PETSc (configure with -DFISSURE_WITH_PETSC=ON)");
}
}  // namespace fissure

#endif
