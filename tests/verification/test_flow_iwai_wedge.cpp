// verification.md (e): Iwai's hydraulic aperture of a wedge, e^3 =
// 2 ea^2 eb^2 / (ea + eb) = em^3 16 r^2 / (1 + r)^4. For ea = 0.1 mm and
// eb = 0.3 mm, e = 0.165096 mm. Closed form: 1e-12 (two algebraically equal
// formulas in double precision). Numerical variant: the wedge as n uniform
// sub-segments in series (midpoint apertures), solved as a network: the
// midpoint rule of the resistance integral is second order, 3.6e-3 at n = 10
// and 3.7e-5 at n = 100 (tolerance 5e-5 at n = 100, as verification.md).
#include <gtest/gtest.h>

#include <cmath>

#include "flow/network/apertures.h"
#include "flow/network/steady_solver.h"
#include "tests/support/flow_networks.h"

namespace fissure::flow {
namespace {

constexpr double kEa = 0.1e-3, kEb = 0.3e-3, kMu = 1e-3, kL = 1, kDp = 1e5;

TEST(flow_iwai_wedge, ClosedForm) {
  const double e = iwai_aperture(kEa, kEb);
  const double em = 0.5 * (kEa + kEb), r = kEa / kEb;
  EXPECT_NEAR(e, em * std::cbrt(16 * r * r / std::pow(1 + r, 4)), 1e-12 * e);
  EXPECT_NEAR(e, 0.165096e-3, 5e-6 * e);  // the catalogue's 6 digits (half a unit of the last)
  EXPECT_DOUBLE_EQ(iwai_aperture(kEa, kEa), kEa);
  EXPECT_NEAR(iwai_aperture(kEb, kEa), e, 1e-15);  // symmetric
  // The conductance of a wedge segment uses it: c = e^3 / (12 mu L).
  EXPECT_NEAR(segment_conductance(kEa, kEb, kL, kMu), e * e * e / (12 * kMu * kL),
              1e-12 * e * e * e / (12 * kMu * kL));
}

/// Hydraulic aperture of the wedge as n uniform sub-segments in series.
double wedge_as_chain(int n) {
  FractureGraph g = testing::chain_network(n, Vec2(0, 0), Vec2(kL, 0), 0);
  std::vector<double> c(n);
  for (int k = 0; k < n; ++k) {
    const double e = kEa + (kEb - kEa) * (k + 0.5) / n;  // midpoint aperture
    c[k] = segment_conductance(e, e, g.length(k), kMu);
  }
  NodeConditions bc(n + 1);
  bc.fixed_pressure[0] = kDp;
  bc.fixed_pressure[n] = 0;
  SteadySolver solver({});
  const NetworkSolution sol = solver.solve(g, c, bc, FluidProperties{}, Vec2::Zero());
  return std::cbrt(sol.flux[0] * 12 * kMu * kL / kDp);
}

TEST(flow_iwai_wedge, SubSegmentsConvergeAtSecondOrder) {
  const double exact = iwai_aperture(kEa, kEb);
  const double err10 = std::abs(wedge_as_chain(10) - exact) / exact;
  const double err100 = std::abs(wedge_as_chain(100) - exact) / exact;
  EXPECT_NEAR(err10, 3.6e-3, 0.1e-3);
  EXPECT_LT(err100, 5e-5);
  EXPECT_NEAR(err100, 3.7e-5, 0.1e-5);
  const double order = std::log10(err10 / err100);
  EXPECT_NEAR(order, 2.0, 0.05);
  std::printf("Iwai wedge: relative error %.3e (n = 10), %.3e (n = 100), order %.3f\n", err10,
              err100, order);
}

TEST(flow_iwai_wedge, WedgeSegmentInANetworkUsesIwai) {
  // One segment with end apertures ea, eb between two fixed pressures.
  const FractureGraph g = testing::chain_network(1, Vec2(0, 0), Vec2(kL, 0), 0);
  const std::vector<double> c = {segment_conductance(kEa, kEb, kL, kMu)};
  NodeConditions bc(2);
  bc.fixed_pressure[0] = kDp;
  bc.fixed_pressure[1] = 0;
  SteadySolver solver({});
  const NetworkSolution sol = solver.solve(g, c, bc, FluidProperties{}, Vec2::Zero());
  const double e = iwai_aperture(kEa, kEb);
  const double q = e * e * e * kDp / (12 * kMu * kL);
  EXPECT_NEAR(sol.flux[0], q, 1e-12 * q);
}

}  // namespace
}  // namespace fissure::flow
