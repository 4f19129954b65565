#include "thermal/conduction/conduction_solver.h"

#include "core/base/errors.h"
#include "core/base/stopwatch.h"
#include "core/linear/serial_cholmod.h"

namespace fissure::thermal {

void ConductionCholesky::compute(const SparseMatrix& a) {
  cholmod_common& c = cholmod();
  for (double& z : c.zrelax) z = 0;
  if (a.rows() >= kMetisFrom) {
    c.nmethods = 1;
    c.method[0].ordering = CHOLMOD_METIS;
  }
  Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower>::compute(a);
  // Simplicial LL^T, packed; where CHOLMOD cannot (memory), the supernodal
  // factor stays and solves as before.
  if (info() == Eigen::Success && m_cholmodFactor->is_super)
    cholmod_change_factor(CHOLMOD_REAL, 1, 0, 1, 1, m_cholmodFactor, &c);
}

ConductionSolver::ConductionSolver() {
  keep_cholmod_serial();
}

void ConductionSolver::set_matrix(SparseMatrix a, std::vector<bool> fixed, bool symmetric,
                                  bool counted) {
  counted_ = counted;
  a_ = std::move(a);
  symmetric_ = symmetric;
  const int n = static_cast<int>(a_.rows());
  std::vector<int> position(n);
  free_.clear();
  fixed_.clear();
  for (int i = 0; i < n; ++i) {
    position[i] = fixed[i] ? static_cast<int>(fixed_.size()) : static_cast<int>(free_.size());
    (fixed[i] ? fixed_ : free_).push_back(i);
  }
  using Triplet = Eigen::Triplet<double>;
  std::vector<Triplet> ff, fd;
  for (int col = 0; col < n; ++col)
    for (SparseMatrix::InnerIterator it(a_, col); it; ++it) {
      const int row = static_cast<int>(it.row());
      if (fixed[row]) continue;
      if (fixed[col])
        fd.emplace_back(position[row], position[col], it.value());
      else
        ff.emplace_back(position[row], position[col], it.value());
    }
  const int nf = static_cast<int>(free_.size()), nd = static_cast<int>(fixed_.size());
  a_free_.resize(nf, nf);
  a_free_.setFromTriplets(ff.begin(), ff.end());
  a_coupling_.resize(nf, nd);
  a_coupling_.setFromTriplets(fd.begin(), fd.end());
  stale_ = true;
}

void ConductionSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& t) {
  if (free_.empty()) return;
  if (stale_) {
    Stopwatch clock;
    if (symmetric_) {
      lu_.reset();
      llt_ = std::make_unique<ConductionCholesky>();
      llt_->compute(a_free_);
      FISSURE_CHECK(llt_->info() == Eigen::Success, SolverError,
                    "thermal: the conduction matrix is not positive definite (a block without "
                    "area, or a non-positive conductivity or capacity?)");
    } else {
      llt_.reset();
      lu_ = std::make_unique<Eigen::UmfPackLU<SparseMatrix>>();
      lu_->compute(a_free_);
      FISSURE_CHECK(lu_->info() == Eigen::Success, SolverError,
                    "thermal: the matrix of the blocks and the fracture water is singular");
    }
    if (counted_) ++factorizations_;
    stale_ = false;
    factor_seconds_ += clock.seconds();
  }
  Stopwatch clock;
  Eigen::VectorXd rhs(free_.size()), fixed_values(fixed_.size());
  for (std::size_t i = 0; i < free_.size(); ++i) rhs[i] = b[free_[i]];
  for (std::size_t i = 0; i < fixed_.size(); ++i) fixed_values[i] = t[fixed_[i]];
  if (!fixed_.empty()) rhs -= a_coupling_ * fixed_values;
  const Eigen::VectorXd x =
      symmetric_ ? Eigen::VectorXd(llt_->solve(rhs)) : Eigen::VectorXd(lu_->solve(rhs));
  for (std::size_t i = 0; i < free_.size(); ++i) t[free_[i]] = x[i];
  ++solves_;
  solve_seconds_ += clock.seconds();
}

double ConductionSolver::fixed_reaction(const Eigen::VectorXd& b, const Eigen::VectorXd& t) const {
  double sum = 0;
  if (!symmetric_) {
    const Eigen::VectorXd at = a_ * t;
    for (const int d : fixed_) sum += at[d] - b[d];
    return sum;
  }
  // Row d of the symmetric A is its column d.
  for (const int d : fixed_) sum += a_.col(d).dot(t) - b[d];
  return sum;
}

}  // namespace fissure::thermal
