#include "mechanics/dda/vibration_damping.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace fissure::dda {

double viscous_time(double w, double zeta, double dt) {
  if (zeta <= 0 || !(w > 0)) return 0;
  return std::max(0.0, 2 * zeta / w - dt / 2);
}

double lowest_strain_frequency(const Matrix6& mass, const Eigen::Matrix3d& stiffness) {
  // K x = w^2 M x on the strain unknowns; the smallest eigenvalue is w_min^2.
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix3d> modes(
      stiffness, mass.block<3, 3>(3, 3), Eigen::EigenvaluesOnly);
  return std::sqrt(std::max(modes.eigenvalues()(0), 0.0));
}

double contact_damping_time(double stiffness, double mass_i, double mass_j, double zeta,
                            double dt) {
  if (zeta <= 0) return 0;
  const double mass = mass_i <= 0   ? mass_j
                      : mass_j <= 0 ? mass_i
                                    : mass_i * mass_j / (mass_i + mass_j);
  return viscous_time(std::sqrt(stiffness / mass), zeta, dt);
}

void set_contact_damping(std::vector<DdaContact>& contacts, const RockMass& state,
                         double normal_penalty, double zeta, double dt) {
  const auto mass = [&](int b) {
    const Block& block = state.blocks[b];
    if (block.fixed) return 0.0;
    return current_density(block, state.materials[block.material].density) * block.section.area;
  };
  for (DdaContact& c : contacts)
    c.spring_factor = 1 + contact_damping_time(normal_penalty, mass(c.key.block_i),
                                               mass(c.key.block_j), zeta, dt) /
                              dt;
}

}  // namespace fissure::dda
