#include "core/linear/distributed_system.h"

#ifdef FISSURE_WITH_PETSC
#include <petscksp.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iterator>
#include <numeric>
#include <sstream>

#include "core/linear/petsc_session.h"

namespace fissure {

namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;
using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, PetscInt>;

/// The PETSc matrix of the shares `rows` (this rank's, in global rows and
/// columns), summed over the ranks, preallocated exactly by a symbolic first
/// pass (MATPREALLOCATOR).
Mat summed_matrix(PetscInt local_rows, PetscInt global_rows, const RowMatrix& rows,
                  bool symmetric) {
  auto insert = [&rows](Mat m) {
    for (PetscInt r = 0; r < rows.outerSize(); ++r) {
      const PetscInt n = rows.outerIndexPtr()[r + 1] - rows.outerIndexPtr()[r];
      if (n == 0) continue;
      const PetscInt offset = rows.outerIndexPtr()[r];
      FISSURE_PETSC_CALL(MatSetValues(m, 1, &r, n, rows.innerIndexPtr() + offset,
                                      rows.valuePtr() + offset, ADD_VALUES));
    }
    FISSURE_PETSC_CALL(MatAssemblyBegin(m, MAT_FINAL_ASSEMBLY));
    FISSURE_PETSC_CALL(MatAssemblyEnd(m, MAT_FINAL_ASSEMBLY));
  };
  Mat pattern = nullptr, m = nullptr;
  FISSURE_PETSC_CALL(MatCreate(PETSC_COMM_WORLD, &pattern));
  FISSURE_PETSC_CALL(MatSetType(pattern, MATPREALLOCATOR));
  FISSURE_PETSC_CALL(MatSetSizes(pattern, local_rows, local_rows, global_rows, global_rows));
  FISSURE_PETSC_CALL(MatSetUp(pattern));
  insert(pattern);
  FISSURE_PETSC_CALL(MatCreate(PETSC_COMM_WORLD, &m));
  FISSURE_PETSC_CALL(MatSetType(m, MATAIJ));
  FISSURE_PETSC_CALL(MatSetSizes(m, local_rows, local_rows, global_rows, global_rows));
  FISSURE_PETSC_CALL(MatPreallocatorPreallocate(pattern, PETSC_TRUE, m));
  FISSURE_PETSC_CALL(MatDestroy(&pattern));
  insert(m);
  if (symmetric) FISSURE_PETSC_CALL(MatSetOption(m, MAT_SYMMETRIC, PETSC_TRUE));
  return m;
}

/// `share`'s entries at the global rows and columns `to_global[]`, times
/// `factor(row, column)`, in rows.
template <class Factor>
RowMatrix mapped(const SparseMatrix& share, const std::vector<PetscInt>& row_of,
                 const std::vector<PetscInt>& col_of, PetscInt global_rows, Factor factor) {
  std::vector<Eigen::Triplet<double, PetscInt>> t;
  t.reserve(share.nonZeros());
  for (int k = 0; k < share.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(share, k); it; ++it)
      t.emplace_back(row_of[it.row()], col_of[it.col()],
                     factor(static_cast<int>(it.row()), static_cast<int>(it.col())) * it.value());
  RowMatrix rows(global_rows, global_rows);
  rows.setFromTriplets(t.begin(), t.end());
  return rows;
}

}  // namespace

/// The PETSc objects and this rank's part of the layout.
struct DistributedSystem::Petsc {
  int rank = 0, size = 1;
  PetscInt n = 0;                   ///< unknowns
  PetscInt local = 0;               ///< rows this rank owns
  std::vector<PetscInt> to_global;  ///< system index -> PETSc row
  std::vector<int> owned;           ///< this rank's rows, in order: their system indices
  /// Per field: its first owned row and count on this rank (PETSc rows).
  std::vector<std::pair<PetscInt, PetscInt>> field_rows;
  /// The second field's rows in the Schur preconditioner's numbering.
  std::vector<PetscInt> to_schur;
  PetscInt schur_n = 0;
  std::vector<int> field_of;  ///< per system index
  Mat a = nullptr, schur = nullptr;
  KSP ksp = nullptr;
  Vec b = nullptr, x = nullptr, all = nullptr;
  Vec residual = nullptr;  ///< of a factorization's solve (check_direct_residual)
  bool preonly = false;    ///< the options chose a factorization (-ksp_type preonly)
  VecScatter to_all = nullptr;
  IS is[2] = {nullptr, nullptr};

  ~Petsc() {
    for (IS& i : is)
      if (i) ISDestroy(&i);
    if (to_all) VecScatterDestroy(&to_all);
    if (all) VecDestroy(&all);
    if (b) VecDestroy(&b);
    if (x) VecDestroy(&x);
    if (residual) VecDestroy(&residual);
    if (ksp) KSPDestroy(&ksp);
    if (a) MatDestroy(&a);
    if (schur) MatDestroy(&schur);
  }

  /// The entries `rows` of `full` (every rank's copy), this rank's part of
  /// a vector of `size` entries.
  Vec owned_vector(const Eigen::VectorXd& full, const std::vector<int>& rows, PetscInt size) {
    Vec v = nullptr;
    FISSURE_PETSC_CALL(
        VecCreateMPI(PETSC_COMM_WORLD, static_cast<PetscInt>(rows.size()), size, &v));
    PetscScalar* p = nullptr;
    FISSURE_PETSC_CALL(VecGetArray(v, &p));
    for (std::size_t k = 0; k < rows.size(); ++k) p[k] = full(rows[k]);
    FISSURE_PETSC_CALL(VecRestoreArray(v, &p));
    return v;
  }
};

DistributedSystem::DistributedSystem(DistributedSystemLayout layout,
                                     const LinearSolverControls& controls)
    : petsc_(std::make_unique<Petsc>()), layout_(std::move(layout)), controls_(controls) {
  ensure_petsc_initialized();
  Petsc& p = *petsc_;
  MPI_Comm_rank(PETSC_COMM_WORLD, &p.rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &p.size);
  const int fields = static_cast<int>(layout_.field_sizes.size());
  if (layout_.row_signs.empty()) layout_.row_signs.assign(fields, 1.0);
  p.n = std::accumulate(layout_.field_sizes.begin(), layout_.field_sizes.end(), PetscInt(0));
  p.to_global.assign(p.n, 0);
  p.field_of.assign(p.n, 0);

  // Each field's unknowns along the curve, cut into `size` equal runs; rank
  // r's rows are its runs of every field, one field after the other.
  std::vector<std::vector<int>> sorted(fields);
  std::vector<std::vector<PetscInt>> cut(fields, std::vector<PetscInt>(p.size + 1));
  int offset = 0;
  for (int f = 0; f < fields; ++f) {
    const int nf = layout_.field_sizes[f];
    sorted[f].resize(nf);
    std::iota(sorted[f].begin(), sorted[f].end(), offset);
    std::stable_sort(sorted[f].begin(), sorted[f].end(),
                     [this](int i, int j) { return layout_.keys[i] < layout_.keys[j]; });
    for (int r = 0; r <= p.size; ++r)
      cut[f][r] = static_cast<PetscInt>(static_cast<long long>(nf) * r / p.size);
    for (int i = offset; i < offset + nf; ++i) p.field_of[i] = f;
    offset += nf;
  }
  PetscInt row = 0, schur_row = 0;
  p.field_rows.assign(fields, {0, 0});
  for (int r = 0; r < p.size; ++r)
    for (int f = 0; f < fields; ++f) {
      if (r == p.rank) p.field_rows[f] = {row, cut[f][r + 1] - cut[f][r]};
      for (PetscInt k = cut[f][r]; k < cut[f][r + 1]; ++k) {
        p.to_global[sorted[f][k]] = row++;
        if (r == p.rank) p.owned.push_back(sorted[f][k]);
      }
    }
  if (fields == 2) {
    p.to_schur.assign(p.n, -1);
    for (int r = 0; r < p.size; ++r)
      for (PetscInt k = cut[1][r]; k < cut[1][r + 1]; ++k) p.to_schur[sorted[1][k]] = schur_row++;
    p.schur_n = schur_row;
  }
  p.local = static_cast<PetscInt>(p.owned.size());

  FISSURE_PETSC_CALL(VecCreateMPI(PETSC_COMM_WORLD, p.local, p.n, &p.b));
  FISSURE_PETSC_CALL(VecDuplicate(p.b, &p.x));
  FISSURE_PETSC_CALL(VecScatterCreateToAll(p.x, &p.to_all, &p.all));
  for (int f = 0; f < fields && fields > 1; ++f)
    FISSURE_PETSC_CALL(ISCreateStride(PETSC_COMM_WORLD, p.field_rows[f].second,
                                      p.field_rows[f].first, 1, &p.is[f]));

  // The solver: defaults first, the scene's options after them.
  const std::string& prefix = layout_.prefix;
#ifdef PETSC_HAVE_HYPRE
  const std::string amg = "-pc_type hypre -pc_hypre_type boomeramg";
#else
  const std::string amg = "-pc_type gamg";
#endif
  std::string defaults;
  if (fields == 1)
    defaults = "-ksp_type cg " + amg;
  else
    // Right-preconditioned GMRES (the true residual is what converges) with
    // the upper block-triangular Schur factorization: one AMG V-cycle on
    // each block (Elman, Silvester and Wathen; White et al. 2016).
    defaults =
        "-ksp_type gmres -ksp_gmres_restart 100 -ksp_pc_side right -pc_type fieldsplit "
        "-pc_fieldsplit_type schur -pc_fieldsplit_schur_fact_type upper "
        "-fieldsplit_0_ksp_type preonly -fieldsplit_1_ksp_type preonly " +
        petsc_options_with_prefix(amg, "fieldsplit_0_") + " " +
        petsc_options_with_prefix(amg, "fieldsplit_1_");
  // The environment's PETSC_OPTIONS (read when PETSc started) win over the
  // scene's, and the scene's over the defaults: each is set only where
  // nothing has set it before.
  options_.add(petsc_options_with_prefix(controls_.petsc_options, prefix));
  options_.add(petsc_options_with_prefix(defaults + " " + layout_.options, prefix));
}

DistributedSystem::~DistributedSystem() = default;

void DistributedSystem::set_matrix(const SparseMatrix& share, const SparseMatrix* schur_share) {
  Petsc& p = *petsc_;
  // A new solver for new matrices (a new step size): the field split keeps
  // blocks of the old ones.
  if (p.ksp) FISSURE_PETSC_CALL(KSPDestroy(&p.ksp));
  if (p.a) FISSURE_PETSC_CALL(MatDestroy(&p.a));
  if (p.schur) FISSURE_PETSC_CALL(MatDestroy(&p.schur));
  FISSURE_PETSC_CALL(KSPCreate(PETSC_COMM_WORLD, &p.ksp));
  FISSURE_PETSC_CALL(KSPSetOptionsPrefix(p.ksp, layout_.prefix.c_str()));
  FISSURE_PETSC_CALL(KSPSetTolerances(p.ksp, controls_.relative_tolerance, 1e-300, PETSC_DEFAULT,
                                      controls_.max_iterations));
  // The diagonal scaling, from the summed diagonals.
  const int n0 = layout_.field_sizes[0];
  Eigen::VectorXd diagonal = share.diagonal();
  if (schur_share && layout_.field_sizes.size() > 1)
    diagonal.tail(p.n - n0) = schur_share->diagonal();
  if (p.size > 1)
    MPI_Allreduce(MPI_IN_PLACE, diagonal.data(), static_cast<int>(diagonal.size()), MPI_DOUBLE,
                  MPI_SUM, PETSC_COMM_WORLD);
  scale_ = Eigen::VectorXd::Ones(p.n);
  for (PetscInt i = 0; i < p.n; ++i)
    if (std::abs(diagonal(i)) > 0) scale_(i) = 1 / std::sqrt(std::abs(diagonal(i)));
  const auto factor = [this, &p](int i, int j) {
    return layout_.row_signs[p.field_of[i]] * scale_(i) * scale_(j);
  };
  p.a = summed_matrix(p.local, p.n, mapped(share, p.to_global, p.to_global, p.n, factor),
                      layout_.symmetric_positive);
  if (layout_.symmetric_positive) FISSURE_PETSC_CALL(MatSetOption(p.a, MAT_SPD, PETSC_TRUE));

  // The near-null space, orthonormal (MatNullSpaceCreate), on the rows of
  // the first field: of the matrix, or of the field split's first block.
  std::vector<Eigen::VectorXd> modes;
  for (const Eigen::VectorXd& v : layout_.near_null_space) {
    Eigen::VectorXd w = Eigen::VectorXd::Zero(p.n);
    w.head(v.size()) = v.cwiseQuotient(scale_.head(v.size()));  // in the scaled unknowns
    for (const Eigen::VectorXd& m : modes) w -= m.dot(w) * m;
    if (w.norm() > 1e-12 * v.norm()) modes.push_back(w / w.norm());
  }
  MatNullSpace near_null = nullptr;
  if (!modes.empty()) {
    const bool split = layout_.field_sizes.size() > 1;
    std::vector<int> rows(p.owned.begin(), p.owned.begin() + p.field_rows[0].second);
    const PetscInt size = split ? layout_.field_sizes[0] : p.n;
    std::vector<Vec> vecs;
    for (const Eigen::VectorXd& m : modes)
      vecs.push_back(p.owned_vector(m, split ? rows : p.owned, size));
    FISSURE_PETSC_CALL(MatNullSpaceCreate(PETSC_COMM_WORLD, PETSC_FALSE,
                                          static_cast<PetscInt>(vecs.size()), vecs.data(),
                                          &near_null));
    for (Vec& v : vecs) FISSURE_PETSC_CALL(VecDestroy(&v));
    if (split)
      FISSURE_PETSC_CALL(
          PetscObjectCompose((PetscObject)p.is[0], "nearnullspace", (PetscObject)near_null));
    else
      FISSURE_PETSC_CALL(MatSetNearNullSpace(p.a, near_null));
    FISSURE_PETSC_CALL(MatNullSpaceDestroy(&near_null));
  }

  PC pc = nullptr;
  FISSURE_PETSC_CALL(KSPGetPC(p.ksp, &pc));
  if (layout_.field_sizes.size() > 1) {
    // The Schur preconditioner on the second field's own numbering.
    FISSURE_CHECK(schur_share, SolverError, "a saddle-point system needs its Schur preconditioner");
    std::vector<PetscInt> rows(p.n, -1);
    for (PetscInt i = 0; i < p.n; ++i)
      if (p.field_of[i] == 1) rows[i - n0] = p.to_schur[i];
    const auto schur_factor = [this, n0](int i, int j) { return scale_(n0 + i) * scale_(n0 + j); };
    p.schur = summed_matrix(p.field_rows[1].second, p.schur_n,
                            mapped(*schur_share, rows, rows, p.schur_n, schur_factor), true);
    FISSURE_PETSC_CALL(KSPSetOperators(p.ksp, p.a, p.a));
    FISSURE_PETSC_CALL(PCSetType(pc, PCFIELDSPLIT));
    FISSURE_PETSC_CALL(PCFieldSplitSetIS(pc, "0", p.is[0]));
    FISSURE_PETSC_CALL(PCFieldSplitSetIS(pc, "1", p.is[1]));
    FISSURE_PETSC_CALL(PCFieldSplitSetSchurPre(pc, PC_FIELDSPLIT_SCHUR_PRE_USER, p.schur));
  } else {
    FISSURE_PETSC_CALL(KSPSetOperators(p.ksp, p.a, p.a));
  }
  check_scene_options_call(KSPSetFromOptions(p.ksp), "KSPSetFromOptions", controls_);
  // A factorization chosen by the options (-ksp_type preonly) takes no guess.
  PetscBool preonly = PETSC_FALSE;
  FISSURE_PETSC_CALL(PetscObjectTypeCompare((PetscObject)p.ksp, KSPPREONLY, &preonly));
  p.preonly = preonly == PETSC_TRUE;
  FISSURE_PETSC_CALL(KSPSetInitialGuessNonzero(p.ksp, preonly ? PETSC_FALSE : PETSC_TRUE));
  check_scene_options_call(KSPSetUp(p.ksp), "KSPSetUp", controls_);
}

Eigen::VectorXd DistributedSystem::solve(const Eigen::VectorXd& share,
                                         const Eigen::VectorXd& guess) {
  Petsc& p = *petsc_;
  // The shares summed on every rank (a few MB even at 1e6 unknowns).
  Eigen::VectorXd sum = share;
  if (p.size > 1)
    MPI_Allreduce(MPI_IN_PLACE, sum.data(), static_cast<int>(sum.size()), MPI_DOUBLE, MPI_SUM,
                  PETSC_COMM_WORLD);
  PetscScalar *pb = nullptr, *px = nullptr;
  FISSURE_PETSC_CALL(VecGetArray(p.b, &pb));
  FISSURE_PETSC_CALL(VecGetArray(p.x, &px));
  for (PetscInt k = 0; k < p.local; ++k) {
    const int i = p.owned[k];
    pb[k] = layout_.row_signs[p.field_of[i]] * scale_(i) * sum(i);
    px[k] = guess.size() == p.n ? guess(i) / scale_(i) : 0.0;
  }
  FISSURE_PETSC_CALL(VecRestoreArray(p.b, &pb));
  FISSURE_PETSC_CALL(VecRestoreArray(p.x, &px));
  FISSURE_PETSC_CALL(KSPSolve(p.ksp, p.b, p.x));
  KSPConvergedReason reason;
  PetscInt its = 0;
  FISSURE_PETSC_CALL(KSPGetConvergedReason(p.ksp, &reason));
  FISSURE_PETSC_CALL(KSPGetIterationNumber(p.ksp, &its));
  last_iterations_ = its;
  iterations_ += its;
  // Located at the scene's `solver` map where it has one (its options, its
  // tolerance or its limit decided this; found by the long fuzz run: case
  // 3107, `-ksp_rtol nan`).
  FISSURE_CHECK(reason > 0, SolverError,
                (controls_.location.empty() ? "" : controls_.location + ": ")
                    << "the " << layout_.prefix << " system (" << p.n << " unknowns, " << describe()
                    << ") did not converge: PETSc reason " << reason << " after " << its
                    << " iterations; expected a larger solver.max_iterations, a looser "
                       "solver.relative_tolerance, or solver.type: direct");
  check_direct_residual();
  FISSURE_PETSC_CALL(VecScatterBegin(p.to_all, p.x, p.all, INSERT_VALUES, SCATTER_FORWARD));
  FISSURE_PETSC_CALL(VecScatterEnd(p.to_all, p.x, p.all, INSERT_VALUES, SCATTER_FORWARD));
  Eigen::VectorXd x(p.n);
  const PetscScalar* pa = nullptr;
  FISSURE_PETSC_CALL(VecGetArrayRead(p.all, &pa));
  for (PetscInt i = 0; i < p.n; ++i) x(i) = scale_(i) * pa[p.to_global[i]];
  FISSURE_PETSC_CALL(VecRestoreArrayRead(p.all, &pa));
  return x;
}

void DistributedSystem::check_direct_residual() {
  // A factorization chosen by the options (-ksp_type preonly) checks
  // nothing: one that does not suit the matrix returns an answer all the
  // same (PETSc's Cholesky of the monolithic system, whose flow rows are
  // negated and so not symmetric, gave Mandel's centre a pressure of
  // -7.8e43 Pa; issue 41). Its relative residual on the scaled system is
  // measured: a factorization leaves round-off, a wrong one order one;
  // 1e-6 parts them with room.
  Petsc& p = *petsc_;
  if (!p.preonly) return;
  if (!p.residual) FISSURE_PETSC_CALL(VecDuplicate(p.b, &p.residual));
  PetscReal residual = 0, rhs = 0;
  FISSURE_PETSC_CALL(MatMult(p.a, p.x, p.residual));
  FISSURE_PETSC_CALL(VecAYPX(p.residual, -1.0, p.b));
  FISSURE_PETSC_CALL(VecNorm(p.residual, NORM_2, &residual));
  FISSURE_PETSC_CALL(VecNorm(p.b, NORM_2, &rhs));
  constexpr double kDirectResidual = 1e-6;
  FISSURE_CHECK(std::isfinite(residual) && residual <= kDirectResidual * rhs, SolverError,
                (controls_.location.empty() ? "" : controls_.location + ": ")
                    << "the " << layout_.prefix << " system (" << p.n << " unknowns, " << describe()
                    << ") was solved by the options' factorization to a relative residual of "
                    << residual / (rhs > 0 ? rhs : 1.0)
                    << ", which is no solution; expected a factorization that suits the matrix "
                       "(-pc_type lu: the monolithic system is not symmetric), or solver.type: "
                       "direct");
}

std::string DistributedSystem::describe() const {
  KSPType ksp = nullptr;
  PCType pc = nullptr;
  PC p = nullptr;
  KSPGetType(petsc_->ksp, &ksp);
  KSPGetPC(petsc_->ksp, &p);
  if (p) PCGetType(p, &pc);
  std::ostringstream out;
  out << "petsc KSP " << (ksp ? ksp : "?") << " + PC " << (pc ? pc : "?") << " on " << petsc_->size
      << (petsc_->size == 1 ? " rank" : " ranks");
  return out.str();
}

}  // namespace fissure
#endif
