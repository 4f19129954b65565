// Iterative back end on the block matrix itself (no scalar copy), with the
// inverse 6x6 diagonal blocks as preconditioner (block Jacobi): conjugate
// gradients for symmetric systems, BiCGStab when implicit friction makes the
// system unsymmetric. Best when inertia dominates (small dt, dynamic runs);
// near-static systems need many iterations and the direct solver wins.
#include <cmath>

#include "core/base/errors.h"
#include "core/io/checkpoint.h"
#include "core/linear/linear_cost.h"
#include "mechanics/dda/solver/block_solver.h"

namespace fissure {

namespace {

class PcgBlockSolver final : public BlockSolver {
 public:
  PcgBlockSolver(double tolerance, int max_iterations)
      : tolerance_(tolerance), max_iterations_(max_iterations) {}

  std::string name() const override { return "pcg (block-Jacobi CG / BiCGStab)"; }

  void analyze(const BlockSparseMatrix&) override {}

  void solve(const BlockSparseMatrix& a, bool symmetric, const Eigen::VectorXd& b,
             Eigen::VectorXd& x) override {
    a.invert_diagonal_blocks(diag_);
    if (x.size() != b.size()) x = Eigen::VectorXd::Zero(b.size());
    const double b_norm = b.norm();
    if (b_norm == 0) {
      x.setZero();
      return;
    }
    // A failed solve (SolverError) has cost all its iterations.
    const double per_iteration = iteration_cost(a, symmetric);
    last_cost_ = max_iterations_ * per_iteration;
    model_total_ += last_cost_;
    const int it = symmetric ? conjugate_gradients(a, b, x, b_norm) : bicgstab(a, b, x, b_norm);
    last_cost_ = it * per_iteration;
    model_total_ += last_cost_ - max_iterations_ * per_iteration;
    iterations_ += it;
    ++solves_;
  }

  double last_solve_cost() const override { return last_cost_; }

  nlohmann::json statistics() const override {
    return {{"type", "pcg"},
            {"solves", solves_},
            {"iterations", iterations_},
            {"model_seconds", model_total_}};
  }

  void set_max_iterations(int n) override { max_iterations_ = n; }

  // Warm-started from the caller's x: only its counters carry over.
  void save(CheckpointWriter& out) const override { counters(*this, out); }
  void restore(CheckpointReader& in) override { counters(*this, in); }

 private:
  template <class Self, class Archive>
  static void counters(Self& self, Archive& a) {
    a("solves", self.solves_);
    a("iterations", self.iterations_);
    a("last_cost", self.last_cost_);
    a("model_total", self.model_total_);
  }

  void precondition(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
    z.resize(r.size());
    for (std::size_t i = 0; i < diag_.size(); ++i)
      z.segment<6>(6 * i).noalias() = diag_[i] * r.segment<6>(6 * i);
  }

  /// Model cost (linear_cost.h) of one iteration: CG takes a product with A,
  /// a block-Jacobi application and five vector operations; BiCGStab twice
  /// the products and applications and about ten vector operations.
  static double iteration_cost(const BlockSparseMatrix& a, bool symmetric) {
    const double products = symmetric ? 1 : 2;
    return products * (linear_cost::block_product(a.n_stored_blocks()) +
                       linear_cost::block_product(a.n_blocks())) +
           linear_cost::vector_operations(products * 5, a.n_rows());
  }

  void fail(double residual) const {
    throw SolverError("pcg: no convergence in " + std::to_string(max_iterations_) +
                      " iterations (relative residual " + std::to_string(residual) + ")");
  }

  int conjugate_gradients(const BlockSparseMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                          double b_norm) const {
    Eigen::VectorXd r(b.size()), z, p, q;
    a.multiply(x, q);
    r = b - q;
    precondition(r, z);
    p = z;
    double rz = r.dot(z);
    for (int it = 0; it < max_iterations_; ++it) {
      if (r.norm() <= tolerance_ * b_norm) return it;
      a.multiply(p, q);
      const double pq = p.dot(q);
      FISSURE_CHECK(pq > 0 && std::isfinite(pq), SolverError,
                    "pcg: the DDA system matrix is not positive definite");
      const double alpha = rz / pq;
      x += alpha * p;
      r -= alpha * q;
      precondition(r, z);
      const double rz_new = r.dot(z);
      p = z + (rz_new / rz) * p;
      rz = rz_new;
    }
    if (r.norm() > tolerance_ * b_norm) fail(r.norm() / b_norm);
    return max_iterations_;
  }

  // Right-preconditioned BiCGStab (van der Vorst). A breakdown (r0 . r or
  // omega vanishing, e.g. when s is already converged or r has become
  // orthogonal to the shadow residual) restarts from the current residual
  // instead of failing.
  int bicgstab(const BlockSparseMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
               double b_norm) const {
    Eigen::VectorXd r(b.size()), q;
    a.multiply(x, q);
    r = b - q;
    const double target = tolerance_ * b_norm;
    Eigen::VectorXd r0, p, v, s, t, y, z;
    double rho = 1, alpha = 1, omega = 1;
    bool restart = true;
    for (int it = 0; it < max_iterations_; ++it) {
      if (r.norm() <= target) return it;
      if (restart) {
        r0 = r, p = r, v = Eigen::VectorXd::Zero(b.size());
        rho = alpha = omega = 1;
        restart = false;
      }
      const double rho_new = r0.dot(r);
      if (std::abs(rho_new) <= 1e-30 * r0.norm() * r.norm()) {
        restart = true;  // the shadow residual is orthogonal to r
        continue;
      }
      p = r + (rho_new / rho) * (alpha / omega) * (p - omega * v);
      rho = rho_new;
      precondition(p, y);
      a.multiply(y, v);
      const double r0v = r0.dot(v);
      if (r0v == 0 || !std::isfinite(r0v)) {
        restart = true;
        continue;
      }
      alpha = rho / r0v;
      s = r - alpha * v;
      if (s.norm() <= target) {  // converged on the half step
        x += alpha * y;
        return it + 1;
      }
      precondition(s, z);
      a.multiply(z, t);
      const double tt = t.dot(t);
      omega = tt > 0 ? t.dot(s) / tt : 0;
      x += alpha * y + omega * z;
      r = s - omega * t;
      FISSURE_CHECK(r.allFinite(), SolverError, "bicgstab: non-finite residual");
      if (omega == 0) restart = true;
    }
    if (r.norm() > target) fail(r.norm() / b_norm);
    return max_iterations_;
  }

  double tolerance_;
  int max_iterations_;
  Matrix6List diag_;  ///< inverses of the diagonal blocks
  long solves_ = 0, iterations_ = 0;
  double last_cost_ = 0;
  double model_total_ = 0;  ///< of every solve (linear_cost.h)
};

}  // namespace

std::unique_ptr<BlockSolver> make_pcg_solver(double relative_tolerance, int max_iterations) {
  return std::make_unique<PcgBlockSolver>(relative_tolerance, max_iterations);
}

}  // namespace fissure
