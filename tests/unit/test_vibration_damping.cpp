// Vibration damping of DDA blocks and contacts (mechanics/dda/vibration_damping.h):
// the lowest strain frequency of a block against the closed form of a
// rectangle, and the viscous time that tops Newmark gamma = 1's numerical
// damping (equivalent to b = dt / 2) up to the damping ratio.
#include <gtest/gtest.h>

#include <cmath>

#include "mechanics/dda/vibration_damping.h"
#include "tests/support/dda_scenes.h"

namespace fissure::dda {
namespace {

constexpr double kDensity = 2700, kYoung = 10e9, kPoisson = 0.25;

TEST(VibrationDamping, LowestStrainFrequencyOfARectangle) {
  // A w x h rectangle: the strain mass is rho diag(Ix, Iy, (Ix + Iy) / 4)
  // (Ix = h w^3 / 12, Iy = w h^3 / 12), the stiffness A C with the plane
  // strain elasticity C = [[a, b, 0], [b, a, 0], [0, 0, G]]. Shear is a mode
  // of its own, w^2 = A G / (rho (Ix + Iy) / 4); ex and ey couple through b:
  // det(A [[a, b], [b, a]] - w^2 rho diag(Ix, Iy)) = 0.
  const double w = 1.0, h = 0.5, area = w * h;
  const SectionProperties s = section_properties(testing::rectangle(w, h, 0.3, Vec2(4, 7)));
  const Matrix6 mass = mass_matrix(kDensity, s);
  const Eigen::Matrix3d c = elastic_matrix({"rock", kDensity, kYoung, kPoisson}, PlaneMode::Strain);
  const double a = c(0, 0), b = c(0, 1), g = c(2, 2);
  const double ix = kDensity * h * w * w * w / 12, iy = kDensity * w * h * h * h / 12;
  const double shear = area * g / ((ix + iy) / 4);
  // ix iy L^2 - area a (ix + iy) L + area^2 (a^2 - b^2) = 0, smaller root.
  const double qa = ix * iy, qb = -area * a * (ix + iy), qc = area * area * (a * a - b * b);
  const double normal = (-qb - std::sqrt(qb * qb - 4 * qa * qc)) / (2 * qa);
  const double expected = std::sqrt(std::min(shear, normal));
  // The block is rotated by 0.3 rad: the frequencies do not depend on it.
  EXPECT_NEAR(lowest_strain_frequency(mass, area * c), expected, 1e-9 * expected);
  EXPECT_GT(expected, 6000);  // 6.8e3 rad/s: a 1 m block of 10 GPa rings at ~1 kHz
  EXPECT_LT(expected, 7500);
}

TEST(VibrationDampingTime, TopsTheIntegratorsDampingUpToTheRatio) {
  const double w = 4000, zeta = 0.1;
  // Steps of the period's order: Newmark gamma = 1 damps enough by itself.
  EXPECT_EQ(viscous_time(w, zeta, 4 * zeta / w), 0.0);
  EXPECT_EQ(viscous_time(w, zeta, 1e-3), 0.0);
  // Shorter steps: viscous plus numerical (dt / 2) is 2 zeta / w, whatever dt.
  for (const double dt : {1e-5, 1e-6, 1e-7})
    EXPECT_NEAR(viscous_time(w, zeta, dt) + dt / 2, 2 * zeta / w, 1e-15);
  EXPECT_EQ(viscous_time(w, 0.0, 1e-6), 0.0);  // damping switched off
  EXPECT_EQ(viscous_time(0.0, zeta, 1e-6), 0.0);
}

TEST(VibrationDampingTime, ContactsUseTheReducedMass) {
  const double k = 1e10, zeta = 0.1, dt = 1e-7;
  // Against a fixed block: the free block's mass.
  EXPECT_NEAR(contact_damping_time(k, 1350, 0, zeta, dt) + dt / 2, 2 * zeta / std::sqrt(k / 1350),
              1e-15);
  EXPECT_EQ(contact_damping_time(k, 0, 1350, zeta, dt), contact_damping_time(k, 1350, 0, zeta, dt));
  // Two equal blocks: half the mass.
  EXPECT_NEAR(contact_damping_time(k, 1350, 1350, zeta, dt) + dt / 2, 2 * zeta / std::sqrt(k / 675),
              1e-15);
}

}  // namespace
}  // namespace fissure::dda
