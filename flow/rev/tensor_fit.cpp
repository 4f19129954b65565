#include "flow/rev/tensor_fit.h"

#include <Eigen/Dense>
#include <cmath>
#include <numbers>

namespace fissure::flow {

void principal(const Eigen::Matrix2d& k, double& k_max, double& k_min, double& angle) {
  const double m = 0.5 * (k(0, 0) + k(1, 1));
  const double d = 0.5 * (k(0, 0) - k(1, 1));
  const double o = 0.5 * (k(0, 1) + k(1, 0));
  const double r = std::hypot(d, o);
  k_max = m + r;
  k_min = m - r;
  angle = 0.5 * std::atan2(2 * o, 2 * d);
}

Eigen::Matrix2d rotate_into(const Eigen::Matrix2d& k, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix2d r;
  r << c, -s, s, c;
  return r.transpose() * k * r;
}

TensorFit fit_tensor(std::span<const double> angles, std::span<const double> values) {
  const int n = static_cast<int>(angles.size());
  Eigen::MatrixXd a(n, 3);
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) {
    const double c = std::cos(angles[i]), s = std::sin(angles[i]);
    a.row(i) << c * c, 2 * s * c, s * s;
    b[i] = values[i];
  }
  TensorFit fit;
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  if (qr.rank() < 3) return fit;
  const Eigen::Vector3d x = qr.solve(b);
  fit.k << x[0], x[1], x[1], x[2];
  const double mean = b.mean();
  fit.misfit = mean != 0 ? std::sqrt((a * x - b).squaredNorm() / n) / std::abs(mean) : 0;
  principal(fit.k, fit.k_max, fit.k_min, fit.angle);
  return fit;
}

}  // namespace fissure::flow
