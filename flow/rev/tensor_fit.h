// The permeability tensor from directional values (theory.md 3.7 steps 4-5):
// least-squares fit of k_g(b) = k11 cos^2 b + 2 k12 sin b cos b + k22 sin^2 b
// to the values measured along directions b_i, its misfit (1/sqrt(k_g) must
// lie on an ellipse), principal values and direction.
#pragma once

#include <Eigen/Core>
#include <span>

namespace fissure::flow {

struct TensorFit {
  Eigen::Matrix2d k = Eigen::Matrix2d::Zero();  ///< fitted, symmetric (m^2)
  /// RMS of (measured - fitted) over the mean measured value: 0 for an exact
  /// tensor; the REV criterion's "ellipse misfit".
  double misfit = 0;
  double k_max = 0, k_min = 0;  ///< principal values
  double angle = 0;             ///< direction of k_max (rad, in (-pi/2, pi/2])
};

/// Fits to values[i] measured along angles[i] (rad). At least three distinct
/// directions modulo pi are needed (else the fit is singular and k is zero).
TensorFit fit_tensor(std::span<const double> angles, std::span<const double> values);

/// Principal values and direction of a symmetric 2x2 tensor.
void principal(const Eigen::Matrix2d& k, double& k_max, double& k_min, double& angle);

/// k' = R(angle)^T k R(angle): the tensor seen in axes rotated by `angle`.
Eigen::Matrix2d rotate_into(const Eigen::Matrix2d& k, double angle);

}  // namespace fissure::flow
