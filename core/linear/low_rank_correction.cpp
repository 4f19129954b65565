#include "core/linear/low_rank_correction.h"

#include <algorithm>

namespace fissure {

namespace {

/// y = the term's u (or v) scattered into a vector of n entries.
void scatter(const RankOneTerm& t, const Vector12& values, Eigen::Ref<Eigen::VectorXd> y) {
  if (t.block_i >= 0) y.segment<6>(6 * t.block_i) += values.head<6>();
  if (t.block_j >= 0) y.segment<6>(6 * t.block_j) += values.tail<6>();
}

template <class Vector>
double dot(const RankOneTerm& t, const Vector12& values, const Vector& z) {
  double s = 0;
  if (t.block_i >= 0)
    s += values.head<6>().dot(z.template segment<6>(6 * t.block_i).template cast<double>());
  if (t.block_j >= 0)
    s += values.tail<6>().dot(z.template segment<6>(6 * t.block_j).template cast<double>());
  return s;
}

/// Columns solved at a time: enough for matrix products, few enough that
/// the right-hand sides stay small (n x 32 doubles: 15 MB at 10,000 blocks).
constexpr int kChunk = 32;

}  // namespace

int LowRankCorrection::set_up(const SolveMany& solve_f, const LowRankUpdate& terms,
                              Eigen::Index n) {
  // Columns of W for terms the last set-up had (same factor) are kept.
  std::vector<int> kept(terms.size(), -1);
  std::vector<int> fresh;
  for (std::size_t k = 0; k < terms.size(); ++k) {
    const auto it = std::find(known_terms_.begin(), known_terms_.end(), terms[k]);
    if (it != known_terms_.end() && known_w_.rows() == n)
      kept[k] = static_cast<int>(it - known_terms_.begin());
    else
      fresh.push_back(static_cast<int>(k));
  }
  rank_ = static_cast<int>(terms.size());
  Eigen::MatrixXf w(n, rank_);
  for (int k = 0; k < rank_; ++k)
    if (kept[k] >= 0) w.col(k) = known_w_.col(kept[k]);
  Eigen::MatrixXd u, solved;
  for (std::size_t first = 0; first < fresh.size(); first += kChunk) {
    const int count = static_cast<int>(std::min<std::size_t>(kChunk, fresh.size() - first));
    u.setZero(n, count);
    for (int f = 0; f < count; ++f)
      scatter(terms[fresh[first + f]], terms[fresh[first + f]].u, u.col(f));
    solve_f(u, solved);
    for (int f = 0; f < count; ++f) w.col(fresh[first + f]) = solved.col(f).cast<float>();
  }
  known_terms_ = terms;
  known_w_ = std::move(w);
  if (rank_ == 0) return 0;
  Eigen::MatrixXd h = Eigen::MatrixXd::Identity(rank_, rank_);
  for (int k = 0; k < rank_; ++k)
    for (int m = 0; m < rank_; ++m)
      h(k, m) += dot(known_terms_[k], known_terms_[k].v, known_w_.col(m));
  h_.compute(h);
  return static_cast<int>(fresh.size());
}

bool LowRankCorrection::well_conditioned() const {
  // Numerically singular only: a merely ill-conditioned correction is a
  // poor preconditioner, which GMRES finds out within its budget.
  constexpr double kLeastReciprocalCondition = 1e-12;
  return rank_ == 0 || h_.rcond() > kLeastReciprocalCondition;
}

void LowRankCorrection::forget() {
  rank_ = 0;
  known_terms_.clear();
  known_w_.resize(0, 0);
}

Eigen::VectorXd LowRankCorrection::project(const Eigen::VectorXd& z) const {
  Eigen::VectorXd y(rank_);
  for (int k = 0; k < rank_; ++k) y(k) = dot(known_terms_[k], known_terms_[k].v, z);
  return y;
}

void LowRankCorrection::correct(Eigen::VectorXd& z) const {
  if (rank_ == 0) return;
  // Accumulated in double: the correction can be larger than z itself
  // (stiff springs), and rounding it to float cost an iteration.
  const Eigen::VectorXd c = h_.solve(project(z));
  for (int k = 0; k < rank_; ++k) z -= c(k) * known_w_.col(k).cast<double>();
}

}  // namespace fissure
