// The poro-elastic continuum against Terzaghi's and Mandel's solutions
// (verification.md (j) and (k)), and its staggered schemes against the
// monolithic solve (theory.md 5.3). Taylor-Hood triangles on the scenes of
// configs/, backward Euler.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/base/errors.h"
#include "tests/support/continuum_runs.h"
#include "tests/support/poroelastic_solutions.h"

namespace fissure {
namespace {

using continuum::PointValues;
using Scheme = ContinuumControls::Scheme;
using testing::continuum_scene;
using testing::ContinuumRun;

Scene with_scheme(Scene scene, Scheme scheme) {
  continuum_controls(scene).scheme = scheme;
  return scene;
}

// 1 x 40 cells of 0.25 m, steps of 100 s (T_v = 1.07e-3 per step). The
// catalogue's tolerance is 1 % of p0 for T_v >= 0.05; the pressure error of
// P1 pressure on 0.25 m is a few 1e-4 p0 there, backward Euler's lag about
// 1e-3 p0 at T_v = 0.05.
TEST(ContinuumConsolidation, TerzaghiPressureAndSettlementFollowTheSeries) {
  const test::Terzaghi exact;
  ContinuumRun run(with_scheme(continuum_scene("continuum_terzaghi.yaml"), Scheme::Monolithic));
  const double p0 = exact.initial_pressure();
  EXPECT_NEAR(run.at({0.5, 0}).pressure, p0, 1e-9 * p0) << "the undrained start";
  for (double tv : {0.05, 0.2, 0.5, 1.0}) {
    const double t = tv * exact.height * exact.height / exact.consolidation_coefficient();
    run.advance_to(t, 100);
    // z is measured down from the drained top (y = 10 m).
    for (double y : {0.0, 5.0, 7.5})
      EXPECT_NEAR(run.at({0.5, y}).pressure / p0, exact.pressure(10 - y, t) / p0, 0.01)
          << "T_v = " << tv << ", y = " << y;
    const double w = -run.at({0.5, 10}).displacement.y();
    EXPECT_NEAR(w / exact.settlement(t), 1, 0.01) << "settlement at T_v = " << tv;
  }
}

// 16 x 16 cells over the quarter 1 m x 1 m, steps of 0.01 s
// (c t / a^2 = 7.1e-4 per step). Catalogue: 2 % of p0 for c t / a^2 >= 0.01,
// and the Mandel-Cryer peak above 1.05 p0.
TEST(ContinuumConsolidation, MandelPressureRisesAboveItsStartAndFollowsTheSeries) {
  const test::Mandel exact;
  ContinuumRun run(with_scheme(continuum_scene("continuum_mandel.yaml"), Scheme::Monolithic));
  const double p0 = exact.initial_pressure(), c = exact.consolidation_coefficient();
  double peak = 0;
  for (double ct : {0.01, 0.02, 0.03, 0.05, 0.07, 0.1, 0.2, 0.5, 1.0}) {
    const double t = ct / c;
    run.advance_to(t, 0.01);
    const PointValues centre = run.at({0, 0}), half = run.at({0.5, 0});
    peak = std::max(peak, centre.pressure / p0);
    EXPECT_NEAR(centre.pressure / p0, exact.pressure(0, t) / p0, 0.02) << "ct/a^2 = " << ct;
    EXPECT_NEAR(half.pressure / p0, exact.pressure(0.5, t) / p0, 0.02) << "ct/a^2 = " << ct;
    EXPECT_NEAR(half.displacement.x(), exact.displacement_x(0.5, t),
                0.02 * std::abs(exact.displacement_x(0.5, t)))
        << "ct/a^2 = " << ct;
    EXPECT_NEAR(run.at({0.5, 1}).displacement.y(), exact.displacement_y(1, t),
                0.02 * std::abs(exact.displacement_y(1, t)))
        << "ct/a^2 = " << ct;
  }
  EXPECT_GT(peak, 1.05);
}

/// The largest differences of u and p between two runs of `steps` steps,
/// relative to the largest |u| and p0.
std::pair<double, double> difference(const Scene& a, const Scene& b, int steps, double dt) {
  ContinuumRun ra(a), rb(b);
  ra.advance_to(steps * dt, dt);
  rb.advance_to(steps * dt, dt);
  const continuum::PoroState &fa = ra.process().fields(), &fb = rb.process().fields();
  return {(fa.displacement - fb.displacement).lpNorm<Eigen::Infinity>() /
              fb.displacement.lpNorm<Eigen::Infinity>(),
          (fa.pressure - fb.pressure).lpNorm<Eigen::Infinity>() /
              fb.pressure.lpNorm<Eigen::Infinity>()};
}

// Fixed stress iterated to 1e-12 is the monolithic solution to 1e-6
// (verification.md (j), (k)), also at Mandel's strong coupling (tau = 2.88).
TEST(ContinuumConsolidation, FixedStressIteratedMatchesTheMonolithicSolve) {
  for (const char* config : {"continuum_mandel.yaml", "continuum_terzaghi.yaml"}) {
    Scene fixed = with_scheme(continuum_scene(config), Scheme::FixedStress);
    continuum_controls(fixed).tolerance = 1e-12;
    const double dt = continuum_controls(fixed).time_step;
    const auto [du, dp] =
        difference(fixed, with_scheme(continuum_scene(config), Scheme::Monolithic), 20, dt);
    EXPECT_LT(du, 1e-6) << config;
    EXPECT_LT(dp, 1e-6) << config;
  }
}

// The drained split converges below tau = 1 (Kim et al. 2011) and agrees
// with the monolithic solve there; the undrained split converges for any
// coupling.
TEST(ContinuumConsolidation, DrainedSplitBelowItsBoundAndUndrainedSplitMatchMonolithic) {
  Scene weak = continuum_scene("continuum_mandel.yaml");
  continuum_controls(weak).materials[0].biot_modulus = 0.2e9;  // tau = 0.288
  Scene drained = with_scheme(weak, Scheme::Drained);
  continuum_controls(drained).tolerance = 1e-12;
  auto [du, dp] = difference(drained, with_scheme(weak, Scheme::Monolithic), 10, 0.01);
  EXPECT_LT(du, 1e-6);
  EXPECT_LT(dp, 1e-6);
  Scene strong = continuum_scene("continuum_mandel.yaml");
  Scene undrained = with_scheme(strong, Scheme::Undrained);
  continuum_controls(undrained).tolerance = 1e-12;
  std::tie(du, dp) = difference(undrained, with_scheme(strong, Scheme::Monolithic), 10, 0.01);
  EXPECT_LT(du, 1e-6);
  EXPECT_LT(dp, 1e-6);
}

// Beyond its bound (Mandel's tau = 2.88) the drained split diverges: the run
// stops with a diagnosis that names the coupling strength, never a silent
// wrong answer.
TEST(ContinuumConsolidation, DrainedSplitBeyondItsBoundIsReported) {
  ContinuumRun run(with_scheme(continuum_scene("continuum_mandel.yaml"), Scheme::Drained));
  try {
    run.advance_to(0.1, 0.01);
    FAIL() << "the drained split at tau = 2.88 ran";
  } catch (const DivergenceError& e) {
    EXPECT_NE(std::string(e.what()).find("coupling strength alpha^2 M / K_dr is 2.88"),
              std::string::npos)
        << e.what();
  }
}

// Observed orders on Mandel at c t / a^2 = 0.1 (benchmarks/continuum_accuracy
// has the full study): the largest nodal pressure error against the series
// falls by 4 from 4 to 8 cells across (P1 pressure: second order; measured
// 3.6 to 4.1 between 4 and 32 cells), and the change from a fine step by 2
// when the step halves (backward Euler: first order).
TEST(ContinuumConsolidation, ObservedOrdersAreTwoInMeshSizeAndOneInTheStep) {
  const test::Mandel exact;
  const double t = 0.1 / exact.consolidation_coefficient(), p0 = exact.initial_pressure();
  auto mandel = [](int n) {
    Scene s = with_scheme(continuum_scene("continuum_mandel.yaml"), Scheme::Monolithic);
    continuum_controls(s).divisions = {n, n};
    return s;
  };
  double error[2];
  for (int k : {0, 1}) {
    ContinuumRun run(mandel(4 << k));
    run.advance_to(t, 2e-3);
    double e = 0;
    for (double x = 0; x <= 1.0001; x += 0.125)
      e = std::max(e, std::abs(run.at({x, 0}).pressure - exact.pressure(x, t)) / p0);
    error[k] = e;
  }
  EXPECT_GT(std::log2(error[0] / error[1]), 1.7) << error[0] << " " << error[1];
  ContinuumRun fine(mandel(8));
  fine.advance_to(t, 2.5e-3);
  double change[2];
  for (int k : {0, 1}) {
    ContinuumRun run(mandel(8));
    run.advance_to(t, 0.04 / (1 << k));
    change[k] = (run.process().fields().pressure - fine.process().fields().pressure).norm();
  }
  const double order = std::log2(change[0] / change[1]);
  EXPECT_GT(order, 0.85);
  EXPECT_LT(order, 1.3);
}

// BDF2 (continuum.time_scheme: bdf2) is second order in the step on the
// same study: the change from a fine BDF2 run falls by 4 when the step
// halves, where backward Euler's falls by 2 (measured 1.94 here).
TEST(ContinuumConsolidation, Bdf2IsSecondOrderInTheStep) {
  const double t = 0.1 / test::Mandel().consolidation_coefficient();
  auto mandel = [] {
    Scene s = with_scheme(continuum_scene("continuum_mandel.yaml"), Scheme::Monolithic);
    continuum_controls(s).divisions = {8, 8};
    continuum_controls(s).time_scheme = ContinuumControls::TimeScheme::Bdf2;
    return s;
  };
  ContinuumRun fine(mandel());
  fine.advance_to(t, 2.5e-3);
  double change[2];
  for (int k : {0, 1}) {
    ContinuumRun run(mandel());
    run.advance_to(t, 0.04 / (1 << k));
    change[k] = (run.process().fields().pressure - fine.process().fields().pressure).norm();
  }
  EXPECT_GT(std::log2(change[0] / change[1]), 1.7) << change[0] << " " << change[1];
}

}  // namespace
}  // namespace fissure
