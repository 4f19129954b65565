// Stability of the continuum's schemes (issue 24, "Stability stress test";
// the full sweep is benchmarks/continuum_accuracy's stability.csv): fixed
// stress converges on Terzaghi's column for permeabilities from 1e-21 to
// 1e-10 m^2 and steps from a second to a thousand years, and with the
// pressure stabilization the pressure stays within 2 % of [0, p0]
// (Terzaghi's maximum principle): no first-step oscillation.
#include <gtest/gtest.h>

#include <algorithm>

#include "tests/support/continuum_runs.h"

namespace fissure {
namespace {

TEST(ContinuumStability, FixedStressConvergesOverPermeabilitiesAndStepsWithoutOscillation) {
  const double p0 = 892857.142857, year = 365.25 * 86400;
  for (double k : {1e-21, 1e-17, 1e-13, 1e-10})
    for (double dt : {1.0, 86400.0, 1000 * year}) {
      Scene scene = testing::continuum_scene("continuum_terzaghi.yaml");
      ContinuumControls& c = continuum_controls(scene);
      c.materials[0].permeability = Eigen::Vector3d(k, k, 0);
      c.time_step = dt;
      c.pressure_stabilization = 1;
      testing::ContinuumRun run(scene);
      ASSERT_NO_THROW(run.advance_to(2 * dt, dt)) << "k = " << k << ", dt = " << dt;
      const Eigen::VectorXd& p = run.process().fields().pressure;
      EXPECT_GE(p.minCoeff(), -0.02 * p0) << "k = " << k << ", dt = " << dt;
      EXPECT_LE(p.maxCoeff(), 1.02 * p0) << "k = " << k << ", dt = " << dt;
      EXPECT_LE(run.process().statistics()["most_passes_in_a_step"].get<long>(), 100)
          << "k = " << k << ", dt = " << dt;
    }
}

// The same column after one step of 1 s (c_v dt / h^2 = 0.017), where the
// pressure's boundary layer is far thinner than an element: with the
// stabilization of Rodrigo et al. (pressure_stabilization: 1) both elements
// stay within 2 % of [0, p0]; without it Taylor-Hood overshoots by about a
// third and equal-order P1/P1 (continuum.elements: p1p1) by more
// (benchmarks/continuum_accuracy's first_step.csv, docs/continuum.md 3).
TEST(ContinuumStability, TheStabilizationKeepsTheFirstStepMonotoneWhereTheElementsAloneOvershoot) {
  const double p0 = 892857.142857;
  auto largest = [p0](bool p1, double stabilization) {
    Scene scene = testing::continuum_scene("continuum_terzaghi.yaml");
    continuum_controls(scene).linear_displacement = p1;
    continuum_controls(scene).pressure_stabilization = stabilization;
    testing::ContinuumRun run(scene);
    run.advance_to(1, 1);
    const Eigen::VectorXd& p = run.process().fields().pressure;
    EXPECT_GE(p.minCoeff(), -0.02 * p0);
    return p.maxCoeff() / p0;
  };
  EXPECT_LE(largest(false, 1), 1.02);
  EXPECT_LE(largest(true, 1), 1.02);
  const double taylor_hood = largest(false, 0), equal_order = largest(true, 0);
  EXPECT_GT(taylor_hood, 1.2);
  EXPECT_GT(equal_order, taylor_hood);
}

}  // namespace
}  // namespace fissure
