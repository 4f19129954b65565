// verification.md (g): a regular orthogonal network in a 10 m square, set 1
// along x' (e1 = 100 um, s1 = 1 m), set 2 along y' (e2 = 50 um, s2 = 0.5 m).
// k1 = e1^3/(12 s1) = 8.33333e-14 m^2, k2 = e2^3/(12 s2) = 2.08333e-14 m^2;
// rotated by 30 deg: kxx = 6.77083, kyy = 3.64583, kxy = 2.70633 (1e-14 m^2).
// With a linear pressure on all four sides and fractures that cross the
// whole square, the linear field is the exact discrete solution, and the
// chord lengths of each set sum to A/s exactly for 0, 30, 60 deg (L sin or
// L cos of the angle is a multiple of the spacing), so the REV tool's tensor
// is exact to round-off: tolerance 1e-8 relative (verification.md; the issue
// asks 1e-6), pressures 1e-10 of the pressure drop.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "flow/network/apertures.h"
#include "flow/network/steady_solver.h"
#include "flow/rev/permeability.h"
#include "flow/rev/rev_output.h"
#include "flow/rev/rev_study.h"
#include "tests/support/run_scene.h"

namespace fissure::flow {
namespace {

constexpr double kDeg = std::numbers::pi / 180;
constexpr double kE1 = 100e-6, kS1 = 1, kE2 = 50e-6, kS2 = 0.5, kL = 10, kMu = 1e-3;
const double kK1 = kE1 * kE1 * kE1 / (12 * kS1), kK2 = kE2 * kE2 * kE2 / (12 * kS2);

ParallelSetsSource sets(double rotation) {
  return ParallelSetsSource(
      {{rotation, kS1, kE1, kS1 / 2}, {rotation + 90 * kDeg, kS2, kE2, kS2 / 2}});
}

Eigen::Matrix2d expected(double rotation) {
  const Vec2 t1(std::cos(rotation), std::sin(rotation)),
      t2(-std::sin(rotation), std::cos(rotation));
  return kK1 * t1 * t1.transpose() + kK2 * t2 * t2.transpose();
}

void expect_tensor(const Eigen::Matrix2d& k, const Eigen::Matrix2d& ref, double tol) {
  const double scale = ref.norm();
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) EXPECT_NEAR(k(i, j), ref(i, j), tol * scale) << i << "," << j;
}

TEST(flow_orthogonal_network, ReferenceValues) {
  EXPECT_NEAR(kK1, 8.33333e-14, 1e-19);
  EXPECT_NEAR(kK2, 2.08333e-14, 1e-19);
  const Eigen::Matrix2d k = expected(30 * kDeg);
  EXPECT_NEAR(k(0, 0), 6.77083e-14, 1e-19);
  EXPECT_NEAR(k(1, 1), 3.64583e-14, 1e-19);
  EXPECT_NEAR(k(0, 1), 2.70633e-14, 1e-19);
}

TEST(flow_orthogonal_network, PressuresAreTheLinearField) {
  for (double rotation : {0.0, 30 * kDeg}) {
    const FractureGraph g = sets(rotation).domain(0, kL, 0);
    const double dp = 1e6;
    NodeConditions bc(g.n_nodes());
    for (const auto& [name, nodes] : g.boundary_nodes)
      for (int v : nodes) bc.fixed_pressure[v] = dp * (0.5 - g.nodes[v].x() / kL);
    std::vector<double> c(g.n_segments());
    for (int s = 0; s < g.n_segments(); ++s)
      c[s] = segment_conductance(g.segments[s].aperture, g.segments[s].aperture, g.length(s), kMu);
    SteadySolver solver({});
    const NetworkSolution sol =
        solver.solve(g, c, bc, FluidProperties{1000, kMu, 2.2e9}, Vec2::Zero());
    EXPECT_GT(sol.n_unknowns, 100);
    for (int v = 0; v < g.n_nodes(); ++v)
      EXPECT_NEAR(sol.pressure[v], dp * (0.5 - g.nodes[v].x() / kL), 1e-10 * dp);
  }
}

TEST(flow_orthogonal_network, DomainTensorAlignedAndRotated) {
  for (double rotation : {0.0, 30 * kDeg}) {
    const DomainPermeability k = domain_permeability(sets(rotation).domain(0, kL, 0), kL, kMu);
    EXPECT_TRUE(k.connected);
    expect_tensor(k.k, expected(rotation), 1e-8);
  }
}

TEST(flow_orthogonal_network, RevToolReturnsTheTensor) {
  for (double rotation : {0.0, 30 * kDeg}) {
    RevStudyConfig config;
    config.sizes = {kL};
    config.realizations = 1;
    config.threads = 2;
    const RevStudyResult r = run_rev_study(config, sets(rotation));
    ASSERT_EQ(r.fits.size(), 1u);
    ASSERT_EQ(r.domains.size(), 12u);
    const TensorFit& fit = r.fits[0].fit;
    expect_tensor(fit.k, expected(rotation), 1e-8);
    EXPECT_NEAR(fit.k_max, kK1, 1e-8 * kK1);
    EXPECT_NEAR(fit.k_min, kK2, 1e-8 * kK1);
    EXPECT_NEAR(std::remainder(fit.angle - rotation, std::numbers::pi), 0, 1e-6);
    EXPECT_LT(fit.misfit, 1e-8);
    EXPECT_LT(r.fits[0].asymmetry, 1e-8);
    // Every rotated square's tensor is the rotated tensor (catalogue table).
    for (const DomainResult& d : r.domains)
      expect_tensor(d.k, rotate_into(expected(rotation), d.angle), 1e-8);
    ASSERT_TRUE(r.rev_size.has_value());
    EXPECT_EQ(*r.rev_size, kL);
    if (rotation > 0) {
      // Directional k_g(beta) = n^T k n of verification.md (g), beta = 0, 30, ..., 150 deg.
      const double table[] = {6.7708, 8.3333, 6.7708, 3.6458, 2.0833, 3.6458};
      for (int b = 0; b < 6; ++b) EXPECT_NEAR(r.domains[b].k(0, 0) / 1e-14, table[b], 1e-4);
      write_rev_output(r, testing::scratch_dir("flow_orthogonal_network"));
    }
  }
}

}  // namespace
}  // namespace fissure::flow
