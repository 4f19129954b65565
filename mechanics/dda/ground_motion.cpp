#include "mechanics/dda/ground_motion.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

namespace fissure::dda {

namespace {

nlohmann::json vec(const Vec2& v) {
  return {v.x(), v.y()};
}

}  // namespace

GroundMotion::GroundMotion(const GroundMotionRecord& record, double start, bool baseline_correction)
    : start_(start), quantity_(record.quantity), source_(record.source) {
  const std::size_t n = record.time.size();
  if (n == 0) return;
  time_.resize(n);
  for (std::size_t k = 0; k < n; ++k) time_[k] = start + record.time[k];
  samples_.assign(n, Sample{Vec2::Zero(), Vec2::Zero(), Vec2::Zero(), Vec2::Zero()});
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2& value = record.values[k];
    if (quantity_ == MotionQuantity::Acceleration) samples_[k].a = value;
    if (quantity_ == MotionQuantity::Velocity) samples_[k].v = value;
    // The base starts where it is: displacements from the first sample's.
    if (quantity_ == MotionQuantity::Displacement) samples_[k].u = value - record.values[0];
  }
  integrate();
  if (quantity_ != MotionQuantity::Acceleration) return;
  raw_end_velocity_ = samples_.back().v;
  raw_end_displacement_ = samples_.back().u;
  if (!baseline_correction || n < 3) return;

  // Least squares of v(tau) ~ b1 tau + b2 tau^2 with the samples'
  // trapezoid weights (records need not be evenly sampled), constrained to
  // pass through the end velocity so that the corrected ground ends at rest:
  // the KKT system [N c; c^T 0] [b; lambda] = [B^T W v; v_end].
  Eigen::Matrix3d kkt = Eigen::Matrix3d::Zero();
  Eigen::Matrix<double, 3, 2> right = Eigen::Matrix<double, 3, 2>::Zero();  // x, y
  for (std::size_t k = 0; k < n; ++k) {
    const double w =
        (k > 0 ? time_[k] - time_[k - 1] : 0.0) + (k + 1 < n ? time_[k + 1] - time_[k] : 0.0);
    const double tau = time_[k] - time_[0];
    const Eigen::Vector2d basis(tau, tau * tau);
    kkt.topLeftCorner<2, 2>().noalias() += w * basis * basis.transpose();
    right.topRows<2>().noalias() += w * basis * samples_[k].v.transpose();
  }
  const double end = time_.back() - time_[0];
  kkt(0, 2) = kkt(2, 0) = end;
  kkt(1, 2) = kkt(2, 1) = end * end;
  right.row(2) = samples_.back().v.transpose();
  const Eigen::Matrix<double, 3, 2> b = kkt.fullPivLu().solve(right);  // rows b1, b2, lambda
  baseline_b1_ = b.row(0).transpose();
  baseline_b2_ = b.row(1).transpose();
  for (std::size_t k = 0; k < n; ++k) {
    const double tau = time_[k] - time_[0];
    samples_[k].a -= baseline_b1_ + 2 * tau * baseline_b2_;
  }
  integrate();
  corrected_ = true;
}

void GroundMotion::integrate() {
  std::vector<Sample>& s = samples_;
  const std::size_t n = s.size();
  if (quantity_ == MotionQuantity::Acceleration) {
    s[0].u = s[0].v = Vec2::Zero();
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const double h = time_[k + 1] - time_[k];
      s[k].jerk = (s[k + 1].a - s[k].a) / h;
      s[k + 1].v = s[k].v + h * s[k].a + h * h / 2 * s[k].jerk;
      s[k + 1].u = s[k].u + h * s[k].v + h * h / 2 * s[k].a + h * h * h / 6 * s[k].jerk;
    }
  } else if (quantity_ == MotionQuantity::Velocity) {
    s[0].u = Vec2::Zero();
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const double h = time_[k + 1] - time_[k];
      s[k].a = (s[k + 1].v - s[k].v) / h;
      s[k + 1].u = s[k].u + h * s[k].v + h * h / 2 * s[k].a;
    }
  } else {
    for (std::size_t k = 0; k + 1 < n; ++k)
      s[k].v = (s[k + 1].u - s[k].u) / (time_[k + 1] - time_[k]);
  }
  // After the record (Sample::after): no acceleration; the velocity of its
  // end is kept, none after a displacement record.
  s[n - 1].jerk = Vec2::Zero();
  if (quantity_ == MotionQuantity::Displacement) s[n - 1].v = Vec2::Zero();
}

GroundMotion::Sample GroundMotion::at(double t, double& s) const {
  const auto after = std::upper_bound(time_.begin(), time_.end(), t);
  const auto k = after - time_.begin() - 1;
  if (k < 0) {  // before the record: at rest
    s = 0;
    return Sample{Vec2::Zero(), Vec2::Zero(), Vec2::Zero(), Vec2::Zero()};
  }
  s = t - time_[k];
  Sample m = samples_[k];
  if (t > time_.back()) m.a = Vec2::Zero();  // after the record
  return m;
}

Vec2 GroundMotion::acceleration(double t) const {
  double s = 0;
  const Sample m = at(t, s);
  return m.a + s * m.jerk;
}

Vec2 GroundMotion::velocity(double t) const {
  double s = 0;
  const Sample m = at(t, s);
  return m.v + s * m.a + s * s / 2 * m.jerk;
}

Vec2 GroundMotion::displacement(double t) const {
  double s = 0;
  const Sample m = at(t, s);
  return m.u + s * m.v + s * s / 2 * m.a + s * s * s / 6 * m.jerk;
}

nlohmann::json GroundMotion::report() const {
  if (empty()) return nullptr;
  Vec2 pga = Vec2::Zero(), pgv = Vec2::Zero(), pgd = Vec2::Zero();
  for (const Sample& m : samples_) {
    pga = pga.cwiseMax(m.a.cwiseAbs());
    pgv = pgv.cwiseMax(m.v.cwiseAbs());
    pgd = pgd.cwiseMax(m.u.cwiseAbs());
  }
  nlohmann::json r = {
      {"source", source_},
      {"quantity", name_of(kMotionQuantityNames, quantity_)},
      {"start", start_},
      {"end", time_.back()},
      {"samples", time_.size()},
      {"peak_acceleration", vec(pga)},
      {"peak_velocity", vec(pgv)},
      {"peak_displacement", vec(pgd)},
      {"end_velocity", vec(samples_.back().v)},
      {"end_displacement", vec(samples_.back().u)},
  };
  if (quantity_ == MotionQuantity::Acceleration)
    r["baseline_correction"] = {{"applied", corrected_},
                                {"b1", vec(baseline_b1_)},
                                {"b2", vec(baseline_b2_)},
                                {"uncorrected_end_velocity", vec(raw_end_velocity_)},
                                {"uncorrected_end_displacement", vec(raw_end_displacement_)}};
  return r;
}

}  // namespace fissure::dda
