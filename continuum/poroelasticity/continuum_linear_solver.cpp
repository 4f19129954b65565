#include "continuum/poroelasticity/continuum_linear_solver.h"

#include <Eigen/CholmodSupport>
#include <Eigen/UmfPackSupport>
#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include "core/base/errors.h"
#include "core/geometry/hilbert_key.h"
#include "core/linear/distributed_system.h"
#include "core/linear/petsc_session.h"
#include "core/parallel/mpi_world.h"

namespace fissure::continuum {

namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;
using Refinement = LinearSolverControls::Refinement;

/// UMFPACK's LU as the continuum sets it up, with the size of its factor.
/// * Ordering: METIS on the pattern of A + A^T instead of UMFPACK's default
///   AMD, whose result depends on the unknowns' numbering: on Mandel's
///   Taylor-Hood systems the AMD factor had 36-42 % more entries than the
///   same system's in dolfinx (issue 41); METIS's does not.
/// * Iterative refinement only where the factor needs it (UMFPACK's default
///   is up to two steps at every solve: a residual each, 68 % more solve
///   work at 1.5e5 unknowns, and the continuum's saddle points never took
///   one; turning it off moved the pressures by 3e-14 of p0). Each new
///   factor's componentwise backward error is measured on a solve with a
///   right-hand side of its own (check(), UMFPACK's measure): above
///   kBackwardErrorBound (a backward-stable LU gives a small multiple of
///   the machine epsilon; the CI scenes' systems measure 4e-16 to 7e-16,
///   Mandel's at 128 x 128 cells 1.8e-15; a check costs a solve) the
///   factor refines every solve from then on, which keeps the matrix;
///   below it the matrix goes. The scene's `solver.refinement` may ask for
///   refinement always (the check still measured, for summary.json) or
///   never (no check: one solve fewer per factorization).
/// * An analysis handed on (ContinuumLinearSolver::take_analysis) is used
///   as given (umfpack_dl_qsymbolic) instead of running METIS again: the
///   steps' system after the undrained start's, whose METIS order
///   restricted to the steps' unknowns gives the same factor; at 256 x 256
///   cells 1.3 s of analysis instead of 4.0 s. The symmetric strategy
///   (diagonal pivots first), which UMFPACK picks by itself for these
///   systems: with a given order its automatic choice went unsymmetric and
///   the factor grew tenfold. With a given order UMFPACK's estimate of its
///   workspace is an upper bound (3.8 GB reserved at 128 x 128 cells for a
///   factor of 0.2 GB): its first block is the memory the handed-on
///   factorization took (it grows the block when that is short).
class UmfPackFactor
    : public Eigen::UmfPackLU<Eigen::SparseMatrix<double, Eigen::ColMajor, SuiteSparse_long>> {
 public:
  explicit UmfPackFactor(Refinement refinement) : refinement_(refinement) {
    umfpackControl()(UMFPACK_ORDERING) = UMFPACK_ORDERING_METIS;
    umfpackControl()(UMFPACK_STRATEGY) = UMFPACK_STRATEGY_SYMMETRIC;
    umfpackControl()(UMFPACK_IRSTEP) = 0;
  }
  /// Analyses a's pattern, in `order` when it is given (a permutation of
  /// its columns), and factorizes; hides Eigen's compute().
  void compute(const UmfpackMatrixType& a, const ContinuumLinearSolver::Analysis& given) {
    if (given.column_order.size() != static_cast<std::size_t>(a.cols())) {
      analyzePattern(a);
    } else {
      if (m_numeric) umfpack_dl_free_numeric(&m_numeric);
      if (m_symbolic) umfpack_dl_free_symbolic(&m_symbolic);
      grab(a);
      if (given.memory > 0) m_control(UMFPACK_ALLOC_INIT) = -given.memory;
      m_fact_errorCode = umfpack_dl_qsymbolic(
          a.rows(), a.cols(), a.outerIndexPtr(), a.innerIndexPtr(), a.valuePtr(),
          given.column_order.data(), &m_symbolic, m_control.data(), m_umfpackInfo.data());
      m_isInitialized = true;
      m_info = m_fact_errorCode == UMFPACK_OK ? Eigen::Success : Eigen::InvalidInput;
      m_analysisIsOk = true;
      m_factorizationIsOk = false;
      m_extractedDataAreDirty = true;
    }
    if (m_info == Eigen::Success) factorize(a);
    memory_ = m_umfpackInfo(UMFPACK_PEAK_MEMORY);  // in UMFPACK's units
  }
  /// The last analysis: its column preordering, and the peak memory of the
  /// factorization that followed it.
  ContinuumLinearSolver::Analysis analysis() const {
    const long n = cols();
    std::vector<long> p(n), q(n), fronts(4 * (n + 1)), chains(3 * (n + 1));
    long rows_, columns, singletons, nonzeros, n_fronts, n_chains;
    if (!m_symbolic ||
        umfpack_dl_get_symbolic(&rows_, &columns, &singletons, &nonzeros, &n_fronts, &n_chains,
                                p.data(), q.data(), fronts.data(), fronts.data() + (n + 1),
                                fronts.data() + 2 * (n + 1), fronts.data() + 3 * (n + 1),
                                chains.data(), chains.data() + (n + 1), chains.data() + 2 * (n + 1),
                                m_symbolic) != UMFPACK_OK)
      return {};
    return {std::move(q), memory_};
  }
  static constexpr double kBackwardErrorBound = 1e-12;
  /// The matrix to factorize (its copy with 64-bit indices), held while
  /// the factor refines.
  UmfpackMatrixType& held_matrix() { return held_; }
  /// Factorizes held_matrix() in the pattern analysed before (hides
  /// Eigen's factorize()): a new factor, checked again.
  void factorize(const UmfpackMatrixType& a) {
    m_control(UMFPACK_IRSTEP) = 0;
    Eigen::UmfPackLU<UmfpackMatrixType>::factorize(a);
    if (info() == Eigen::Success) check();
  }
  /// Measures the new factor's backward error on A x = A x_t (x_t a fixed
  /// smooth vector; a right-hand side of the matrix alone, so that a
  /// restarted run decides as the uninterrupted one did); above the bound
  /// its solves refine from then on and the held matrix stays, below it
  /// goes.
  void check() {
    if (refinement_ == Refinement::Never) {
      release_matrix();
      return;
    }
    const Eigen::Index n = held_.rows();
    Eigen::VectorXd x_t(n);
    for (Eigen::Index i = 0; i < n; ++i) x_t(i) = 1 + 0.5 * std::sin(static_cast<double>(i));
    const Eigen::VectorXd b = held_ * x_t;
    const Eigen::VectorXd x = solve(b);
    // The componentwise backward error as UMFPACK measures it (Arioli,
    // Demmel and Duff 1989): Oettli and Prager's |r_i| / (|A| |x| + |b|)_i
    // on the rows where that denominator is not at round-off level, and
    // |r_i| / ((|A| |x|)_i + |A_i|_1 |x|_inf) on the others (rows whose
    // terms cancel). A normwise measure would hide the flow rows, whose
    // entries are 1e-21 of the stiffness rows'.
    const Eigen::VectorXd r = (b - held_ * x).cwiseAbs();
    const Eigen::VectorXd ax = held_.cwiseAbs() * x.cwiseAbs();
    const Eigen::VectorXd row_sums = held_.cwiseAbs() * Eigen::VectorXd::Ones(n);
    const double x_max = x.lpNorm<Eigen::Infinity>();
    double omega1 = 0, omega2 = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double tau = ax(i) + std::abs(b(i));
      const double round_off = 1000.0 * static_cast<double>(n) *
                               std::numeric_limits<double>::epsilon() *
                               (row_sums(i) * x_max + std::abs(b(i)));
      if (tau > round_off)
        omega1 = std::max(omega1, r(i) / tau);
      else if (tau > 0)
        omega2 = std::max(omega2, r(i) / (ax(i) + row_sums(i) * x_max));
    }
    backward_error_ = omega1 + omega2;
    if (backward_error_ > kBackwardErrorBound || refinement_ == Refinement::Always)
      m_control(UMFPACK_IRSTEP) = 2;
    else
      release_matrix();
  }
  /// Whether the last factor's solves refine.
  bool refines() const { return m_control(UMFPACK_IRSTEP) > 0; }
  /// Of the last numeric factorization (UMFPACK's Info array).
  ContinuumLinearSolver::FactorSize factor_size() const {
    return {m_umfpackInfo(UMFPACK_LNZ) + m_umfpackInfo(UMFPACK_UNZ) -
                m_umfpackInfo(UMFPACK_NROW),  // the diagonal is in both
            m_umfpackInfo(UMFPACK_FLOPS), backward_error_, refines()};
  }

 private:
  /// Lets the held matrix go: without iterative refinement UMFPACK's solve
  /// reads the factor only (A is read for the refinement's residuals
  /// alone, UMF_solve). An empty matrix of the same size stands in for it
  /// (Eigen sizes the solution by it).
  void release_matrix() {
    m_dummy.resize(rows(), cols());
    m_dummy.makeCompressed();
    grab(m_dummy);
    UmfpackMatrixType().swap(held_);
  }
  Refinement refinement_;
  double memory_ = 0;
  UmfpackMatrixType held_;
  double backward_error_ = 0;
};

/// CHOLMOD's supernodal Cholesky, with the size of its factor. A Cholesky
/// factor of an SPD matrix is backward stable without pivoting (Higham,
/// Accuracy and Stability of Numerical Algorithms, 10.1): no check; with
/// `refinement: always` DirectSolver refines its solves by one step.
class CholmodFactor : public Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> {
 public:
  explicit CholmodFactor(Refinement) {}
  /// CHOLMOD chooses its own order (no hand-on).
  void compute(const SparseMatrix& a, const ContinuumLinearSolver::Analysis&) {
    Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower>::compute(a);
  }
  ContinuumLinearSolver::Analysis analysis() const { return {}; }
  ContinuumLinearSolver::FactorSize factor_size() { return {cholmod().lnz, cholmod().fl}; }
};

/// A sparse factorization on one rank: Cholesky for the SPD systems, LU
/// for the saddle point, with 64-bit indices where the factor may pass
/// UMFPACK's 32-bit workspace (2 GB: a monolithic system of 1e6 unknowns).
/// An empty system (every unknown prescribed) has the empty solution;
/// CHOLMOD and UMFPACK do not take it.
template <class Factor>
class DirectSolver final : public ContinuumLinearSolver {
 public:
  DirectSolver(int n, const char* what, Refinement refinement)
      : n_(n), what_(what), refinement_(refinement) {}
  void set_matrix(SparseMatrix&& a, const SparseMatrix*) override {
    if (n_ == 0) return;
    // A matrix of the pattern factorized before (a new step size, tensors
    // that follow the stress) keeps the ordering and the symbolic analysis:
    // the same factor, without AMD and the elimination tree again.
    const bool same_pattern = factor_ && a.isCompressed() && same_pattern_as(a);
    if (!same_pattern) {
      factor_ = std::make_unique<Factor>(refinement_);
      outer_.assign(a.outerIndexPtr(), a.outerIndexPtr() + a.outerSize() + 1);
      inner_.assign(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros());
      if (!a.isCompressed()) outer_.clear();  // never matched
    }
    if constexpr (std::is_same_v<typename Factor::MatrixType, SparseMatrix>) {
      factorize(a, same_pattern);
      if (refinement_ == Refinement::Always) held_.swap(a);  // for the residuals
    } else {
      // UMFPACK with 64-bit indices factorizes a copy of that type, which
      // it holds while the factor refines; the given matrix is let go
      // first.
      typename Factor::MatrixType& wide = factor_->held_matrix();
      typename Factor::MatrixType(a).swap(wide);
      SparseMatrix().swap(a);
      factorize(wide, same_pattern);
    }
    size_ = factor_->factor_size();
    if (held_.rows() == n_) size_.refined = true;
    FISSURE_CHECK(factor_->info() == Eigen::Success, SolverError,
                  "the continuum's "
                      << what_ << " matrix (" << n_
                      << " unknowns) could not be factorized: singular or not positive definite "
                         "(check its boundary conditions), or its factor is beyond the memory; "
                         "expected solver.type: petsc for a system this large");
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b, const Eigen::VectorXd&) override {
    if (n_ == 0) return Eigen::VectorXd(0);
    Eigen::VectorXd x = factor_->solve(b);
    // One step of refinement in working precision (UMFPACK refines inside
    // its own solve): x += A^-1 (b - A x).
    if (held_.rows() == n_) {
      const Eigen::VectorXd r = b - held_.template selfadjointView<Eigen::Lower>() * x;
      x += factor_->solve(r);
    }
    return x;
  }
  int size() const override { return n_; }
  long iterations() const override { return 0; }
  bool takes_a_guess() const override { return false; }
  std::string describe() const override { return "direct"; }
  FactorSize factor_size() const override { return size_; }
  Analysis analysis() const override { return factor_ ? factor_->analysis() : Analysis{}; }
  void take_analysis(Analysis given) override { given_ = std::move(given); }

 private:
  template <class Matrix>
  void factorize(const Matrix& a, bool same_pattern) {
    if (same_pattern) {
      factor_->factorize(a);
    } else {
      factor_->compute(a, given_);
      given_ = {};
    }
  }

  bool same_pattern_as(const SparseMatrix& a) const {
    return static_cast<std::size_t>(a.outerSize()) + 1 == outer_.size() &&
           static_cast<std::size_t>(a.nonZeros()) == inner_.size() &&
           std::equal(outer_.begin(), outer_.end(), a.outerIndexPtr()) &&
           std::equal(inner_.begin(), inner_.end(), a.innerIndexPtr());
  }

  int n_;
  const char* what_;
  Refinement refinement_;
  SparseMatrix held_;  ///< the matrix, where the Cholesky factor's solves refine
  std::unique_ptr<Factor> factor_;
  std::vector<int> outer_, inner_;  ///< the pattern of the matrix factor_ analysed
  FactorSize size_;
  Analysis given_;  ///< for the next analysis (take_analysis)
};

/// The sum of every rank's `share`, added in rank order on rank 0, so that
/// the same shares give the same bits; the other ranks get nothing.
SparseMatrix summed_on_root(const SparseMatrix& share) {
  if (!share.isCompressed()) return summed_on_root(SparseMatrix(share));
  const int columns = static_cast<int>(share.cols());
  const auto nonzeros = static_cast<std::size_t>(share.nonZeros());
  const std::vector<int> outer = parallel::gather_ints_to_root(
      std::vector<int>(share.outerIndexPtr(), share.outerIndexPtr() + columns + 1));
  const std::vector<int> inner = parallel::gather_ints_to_root(
      std::vector<int>(share.innerIndexPtr(), share.innerIndexPtr() + nonzeros));
  const std::vector<double> values =
      parallel::gather_to_root(std::vector<double>(share.valuePtr(), share.valuePtr() + nonzeros));
  SparseMatrix sum;
  if (parallel::rank() != 0) return sum;
  std::size_t entries = 0;
  for (int r = 0; r < parallel::size(); ++r) {
    const int* columns_of_r = outer.data() + static_cast<std::size_t>(r) * (columns + 1);
    const int count = columns_of_r[columns];
    const Eigen::Map<const SparseMatrix> part(share.rows(), columns, count, columns_of_r,
                                              inner.data() + entries, values.data() + entries);
    sum = r == 0 ? SparseMatrix(part) : SparseMatrix(sum + part);
    entries += static_cast<std::size_t>(count);
  }
  return sum;
}

Eigen::VectorXd summed_on_root(const Eigen::VectorXd& share) {
  const std::vector<double> all =
      parallel::gather_to_root(std::vector<double>(share.data(), share.data() + share.size()));
  if (parallel::rank() != 0) return Eigen::VectorXd();
  Eigen::VectorXd sum = Eigen::VectorXd::Map(all.data(), share.size());
  for (int r = 1; r < parallel::size(); ++r)
    sum += Eigen::VectorXd::Map(all.data() + r * share.size(), share.size());
  return sum;
}

/// A direct solver on several ranks: rank 0 factorizes the sum of the
/// shares with the one-rank solvers and gives every rank the solution, the
/// same bits in every run. MUMPS, which shares the factorization among the
/// ranks, adds the parts of a front in the order they arrive: two 2-rank
/// runs of the same scene differed from the first frame, by up to 4e-8 Pa
/// in stress (docs/continuum.md 3, "MPI").
class RootDirectSolver final : public ContinuumLinearSolver {
 public:
  /// `root`: the one-rank solver, on rank 0 only (null on the others).
  RootDirectSolver(std::unique_ptr<ContinuumLinearSolver> root, int n)
      : root_(std::move(root)), n_(n) {}
  void set_matrix(SparseMatrix&& share, const SparseMatrix*) override {
    if (n_ == 0) return;
    SparseMatrix sum = summed_on_root(share);
    SparseMatrix().swap(share);
    std::string failure;
    if (root_) try {
        root_->set_matrix(std::move(sum));
      } catch (const SolverError& e) {
        failure = e.what();
      }
    // Every rank stops where rank 0's factorization failed (rank 0 reports).
    FISSURE_CHECK(
        parallel::broadcast(failure.empty() ? 1 : 0) == 1, SolverError,
        (failure.empty() ? "rank 0 could not factorize the continuum's matrix" : failure));
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& share, const Eigen::VectorXd&) override {
    if (n_ == 0) return Eigen::VectorXd(0);
    const Eigen::VectorXd b = summed_on_root(share);
    Eigen::VectorXd x = root_ ? root_->solve(b, Eigen::VectorXd()) : Eigen::VectorXd(n_);
    parallel::broadcast(x);
    return x;
  }
  int size() const override { return n_; }
  long iterations() const override { return 0; }
  bool takes_a_guess() const override { return false; }
  std::string describe() const override { return "direct on rank 0"; }
  FactorSize factor_size() const override { return root_ ? root_->factor_size() : FactorSize{}; }
  Analysis analysis() const override { return root_ ? root_->analysis() : Analysis{}; }
  void take_analysis(Analysis given) override {
    if (root_) root_->take_analysis(std::move(given));
  }

 private:
  std::unique_ptr<ContinuumLinearSolver> root_;
  int n_;
};

#ifdef FISSURE_WITH_PETSC
class PetscSolver final : public ContinuumLinearSolver {
 public:
  PetscSolver(DistributedSystemLayout layout, const LinearSolverControls& c)
      : n_(static_cast<int>(layout.keys.size())), system_(std::move(layout), c) {}
  void set_matrix(SparseMatrix&& a, const SparseMatrix* schur) override {
    if (n_ > 0) system_.set_matrix(a, schur);
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b, const Eigen::VectorXd& guess) override {
    return n_ > 0 ? system_.solve(b, guess) : Eigen::VectorXd(0);
  }
  int size() const override { return n_; }
  long iterations() const override { return system_.iterations(); }
  bool takes_a_guess() const override { return true; }
  std::string describe() const override { return system_.describe(); }

 private:
  int n_;
  DistributedSystem system_;
};

/// Where each free unknown of `f` is (its first entry's node; `per_node`
/// entries per node), along the Hilbert curve of the mesh's bounding box.
void append_keys(const ContinuumMesh& mesh, const FieldNumbering& f, int per_node,
                 std::vector<double>& keys) {
  Eigen::AlignedBox2d box;
  for (const Vec2& x : mesh.nodes) box.extend(x);
  const std::size_t first = keys.size();
  keys.resize(first + f.n_free, -1);
  for (std::size_t e = 0; e < f.free_index.size(); ++e) {
    const int j = f.free_index[e];
    if (j < 0 || keys[first + j] >= 0) continue;
    const Vec2& x = mesh.nodes[e / per_node];
    keys[first + j] =
        hilbert_key(x.x(), x.y(), box.min().x(), box.min().y(), box.max().x(), box.max().y());
  }
}

/// The rigid-body modes of the displacement's free unknowns: the
/// translations and the rotation in plane strain, the axial translation of
/// an axisymmetric model (a radial motion strains the hoop).
std::vector<Eigen::VectorXd> rigid_body_modes(const ContinuumMesh& mesh, const FieldNumbering& u,
                                              bool axisymmetric) {
  Vec2 centre = Vec2::Zero();
  for (const Vec2& x : mesh.nodes) centre += x;
  centre /= std::max<std::size_t>(1, mesh.nodes.size());
  const int modes = axisymmetric ? 1 : 3;
  std::vector<Eigen::VectorXd> v(modes, Eigen::VectorXd::Zero(u.n_free));
  std::vector<char> seen(u.n_free, 0);
  for (std::size_t e = 0; e < u.free_index.size(); ++e) {
    const int j = u.free_index[e];
    if (j < 0 || seen[j]) continue;
    seen[j] = 1;
    const int component = static_cast<int>(e % 2);
    const Vec2 x = mesh.nodes[e / 2] - centre;
    if (axisymmetric) {
      v[0](j) = component == 1;
    } else {
      v[0](j) = component == 0;
      v[1](j) = component == 1;
      v[2](j) = component == 0 ? -x.y() : x.x();
    }
  }
  return v;
}
#endif

}  // namespace

std::unique_ptr<ContinuumLinearSolver> make_linear_solver(SystemKind kind, const char* name,
                                                          const ContinuumMesh& mesh,
                                                          bool axisymmetric,
                                                          const FieldNumbering& first,
                                                          const FieldNumbering* second,
                                                          const LinearSolverControls& controls) {
  using Type = LinearSolverControls::Type;
  const int n = first.n_free + (second ? second->n_free : 0);
  const bool several_ranks = parallel::size() > 1;
  const bool direct =
      controls.type == Type::Direct || (controls.type == Type::Auto && n <= kAutoIterativeUnknowns);
  if (direct) {
    // On several ranks rank 0 factorizes (RootDirectSolver); MUMPS is
    // reached as `petsc` with its options (docs/continuum.md 3).
    std::unique_ptr<ContinuumLinearSolver> serial;
    if (parallel::rank() == 0) {
      if (kind == SystemKind::SaddlePoint)
        serial = std::make_unique<DirectSolver<UmfPackFactor>>(n, name, controls.refinement);
      else
        serial = std::make_unique<DirectSolver<CholmodFactor>>(n, name, controls.refinement);
    }
    if (!several_ranks) return serial;
    return std::make_unique<RootDirectSolver>(std::move(serial), n);
  }
#ifdef FISSURE_WITH_PETSC
  DistributedSystemLayout layout;
  layout.prefix = std::string("continuum_") + name + "_";
  const int per_node = kind == SystemKind::Diffusion ? 1 : 2;
  layout.field_sizes = {first.n_free};
  append_keys(mesh, first, per_node, layout.keys);
  if (kind == SystemKind::SaddlePoint) {
    layout.field_sizes.push_back(second->n_free);
    append_keys(mesh, *second, 1, layout.keys);
    // -(flow rows): the Schur complement S + dt H + Q^T K^-1 Q is then SPD.
    layout.row_signs = {1.0, -1.0};
    layout.symmetric_positive = false;
  }
  if (kind != SystemKind::Diffusion) {
    layout.near_null_space = rigid_body_modes(mesh, first, axisymmetric);
    // BoomerAMG on vector elasticity: a strong-connection threshold of 0.7
    // (hypre's advice for elasticity; 0.25, its default for scalar
    // problems, took 4 to 10 times the iterations on Mandel's P2 mesh), HMIS
    // coarsening with extended+i interpolation, aggressive coarsening on the
    // first level and at most 4 interpolation weights per row (hypre's
    // advice with HMIS; issue 41: a Mandel step 1.9 times faster at 3.7e4
    // and 1.5e5 unknowns, 56 -> 48 and 83 -> 71 iterations, measured with
    // PETSC_OPTIONS, docs/performance.md "continuum_vs_fenicsx"). GAMG with the rigid-body
    // modes (`-continuum_monolithic_fieldsplit_0_pc_type gamg`) took fewer
    // iterations on some meshes (156 against 282 at 1.6e5 unknowns) but 1,570
    // on another (1e5): not robust enough for a default
    // (docs/performance.md, "continuum_scaling").
    const std::string amg =
        "-pc_hypre_boomeramg_strong_threshold 0.7 -pc_hypre_boomeramg_coarsen_type HMIS "
        "-pc_hypre_boomeramg_interp_type ext+i -pc_hypre_boomeramg_agg_nl 1 "
        "-pc_hypre_boomeramg_P_max 4";
    layout.options =
        kind == SystemKind::SaddlePoint ? petsc_options_with_prefix(amg, "fieldsplit_0_") : amg;
  }
  return std::make_unique<PetscSolver>(std::move(layout), controls);
#else
  LinearSolverControls direct = controls;
  direct.type = LinearSolverControls::Type::Direct;
  return make_linear_solver(kind, name, mesh, axisymmetric, first, second, direct);
#endif
}

}  // namespace fissure::continuum
