// The continuum's stress-dependent permeability (docs/continuum.md section
// 9, docs/verification.md (ak)): 1D consolidation whose permeability falls
// exponentially with the mean effective stress, against an independent fine
// finite-volume solution of the nonlinear diffusion equation
// (tests/support/nonlinear_consolidation.h, 2000 cells, BDF2: 1.5e-6 p_u).
#include <gtest/gtest.h>

#include <cmath>

#include "continuum/poroelasticity/permeability_law.h"
#include "tests/support/continuum_runs.h"
#include "tests/support/nonlinear_consolidation.h"

namespace fissure {
namespace {

using continuum::StressPermeabilityLaw;
using testing::continuum_scene;
using testing::ContinuumRun;

// configs/continuum_terzaghi.yaml: E = 1 GPa, nu = 0.25 (lambda = G =
// 0.4 GPa), alpha = 1, M = 10 GPa, 1 MPa on the drained top, rollers on the
// sides. In the oedometer sigma_yy = -q and eps_xx = 0, so
//   sigma' = -(sxx + syy)/2 - p = (1 + r)/2 (q - p),  r = lambda / (lambda + 2G) = 1/3,
// and S = 1/M + alpha^2 / (lambda + 2G). The law k = 1e-15 exp(-3/MPa sigma')
// falls by a factor of 6 from the undrained (sigma' = 0.07 MPa) to the
// drained state (0.67 MPa).
constexpr double kLoad = 1e6, kBeta = 3e-6, kRef = 1e-15;
constexpr double kLambda = 0.4e9, kShear = 0.4e9, kBiotModulus = 10e9;

test::NonlinearConsolidation reference() {
  const double r = kLambda / (kLambda + 2 * kShear), constrained = kLambda + 2 * kShear;
  test::NonlinearConsolidation c;
  c.height = 10;
  c.storage = 1 / kBiotModulus + 1 / constrained;
  c.viscosity = 1e-3;
  c.undrained_pressure = kBiotModulus * kLoad / (constrained + kBiotModulus);
  c.k_ref = kRef;
  c.beta = kBeta;
  c.sigma_ref = 0;
  c.a = 0.5 * (1 + r) * kLoad;
  c.b = -0.5 * (1 + r);
  return c;
}

Scene stress_dependent(double beta) {
  Scene scene = continuum_scene("continuum_terzaghi.yaml");
  ContinuumControls& c = continuum_controls(scene);
  c.scheme = ContinuumControls::Scheme::Monolithic;
  c.materials[0].permeability_law =
      StressPermeabilityLaw::exponential({kRef, kRef}, {beta, beta}, 0, 0);
  return scene;
}

/// The largest pressure error (relative to p_u) at y = 0, 2.5, 5, 7.5 m and
/// T = t / T_c = 0.05, 0.2, 0.5, 1 of a run with steps of dt.
double largest_error(double beta, double dt, int cells = 40) {
  const test::NonlinearConsolidation c = reference();
  const double tc = test::nonlinear_consolidation_time(c);
  Scene scene = stress_dependent(beta);
  continuum_controls(scene).divisions = {1, cells};
  ContinuumRun run(scene);
  const std::vector<double> heights = {0, 2.5, 5, 7.5};
  double worst = 0;
  for (double tv : {0.05, 0.2, 0.5, 1.0}) {
    run.advance_to(tv * tc, dt);
    const std::vector<double> exact = test::nonlinear_consolidation_pressure(c, tv * tc, heights);
    for (std::size_t i = 0; i < heights.size(); ++i)
      worst = std::max(
          worst, std::abs(run.at({0.5, heights[i]}).pressure - exact[i]) / c.undrained_pressure);
  }
  return worst;
}

// The mesh and step of the Terzaghi test (40 cells of 0.25 m, 100 s =
// 1.07e-3 T_c), where the constant-k error is ~1e-3 p_u: with the law
// 2.1e-3 p_u, within the catalogue's Terzaghi tolerance of 1 %. Halving the
// cells and quartering the step divides it by 3.7 (measured; P1 pressure is
// second order in h, backward Euler first order in dt, so 4 is expected
// once the coefficient is iterated within the step; a lagged k would add a
// first-order error of its own and an error in the law would not shrink).
// 160 cells and 6.25 s: 1.5e-4 p_u, 3.7 times less again. With the law
// left out (k fixed) the same run is off by 0.48 p_u.
TEST(ContinuumStressPermeability, ConsolidationFollowsTheNonlinearReference) {
  const double coarse = largest_error(kBeta, 100, 40), fine = largest_error(kBeta, 25, 80);
  EXPECT_LT(coarse, 0.01);
  EXPECT_GT(coarse / fine, 3) << coarse << " " << fine;
  EXPECT_LT(coarse / fine, 5) << coarse << " " << fine;
  EXPECT_GT(largest_error(0, 100, 40), 0.3);
}

// The undrained start, then a drained column: the tensors of the triangles
// are the law's at their own effective stress (uniform in the oedometer).
TEST(ContinuumStressPermeability, TensorsFollowTheLawAtTheTriangleStress) {
  ContinuumRun run(stress_dependent(kBeta));
  const test::NonlinearConsolidation c = reference();
  const double drained = c.a;  // p = 0
  run.advance_to(50 * test::nonlinear_consolidation_time(c), 5000);
  for (const Eigen::Vector3d& k : run.process().permeability()) {
    EXPECT_NEAR(k(0) / (kRef * std::exp(-kBeta * drained)), 1, 1e-6);
    EXPECT_EQ(k(0), k(1));
    EXPECT_EQ(k(2), 0);
  }
}

}  // namespace
}  // namespace fissure
