// verification.md (f), transient: pressure diffusion along one rigid
// fracture (theory.md 3.4). e = 10 um, K_f = 2.2 GPa, mu = 1e-3 Pa s, so
// D = K_f e^2 / (12 mu) = 18.333 m^2/s; p(0, t) = p0 from t = 0 into p = 0,
// far end (no flow) at 10 m. Reference p/p0 = erfc(x / 2 sqrt(D t)),
// 0.098648 at x = 1 m, t = 0.01 s.
//  * accuracy: 0.01 absolute in p/p0 at dx = 0.05 m (verification.md; the
//    spatial error of the lumped scheme dominates);
//  * order in time: errors against a converged solution on the same mesh for
//    dt halved three times: backward Euler ~1, BDF2 ~2 (tolerance 0.15 on the
//    order; the initial step discontinuity costs a little at the largest dt);
//  * explicit stability: the reported limit min S_i/T_ii equals dx^2 / 2D to
//    round-off; forward Euler at that step stays bounded by p0 (maximum
//    principle), at 1.05 times it diverges (verification.md: the bound is
//    sharp for a uniform chain).
#include <gtest/gtest.h>

#include <cmath>

#include "core/base/errors.h"
#include "flow/network/apertures.h"
#include "flow/network/transient_integrator.h"
#include "flow/network/transient_system.h"
#include "tests/support/flow_networks.h"

namespace fissure::flow {
namespace {

using Scheme = FlowControls::Transient::Scheme;
constexpr double kE = 10e-6, kKf = 2.2e9, kMu = 1e-3, kP0 = 1e6, kLength = 10;
const double kD = kKf * kE * kE / (12 * kMu);

struct Chain {
  FractureGraph graph;
  TransientSystem system;
};

Chain make_chain(double dx) {
  Chain c;
  const int n = static_cast<int>(std::lround(kLength / dx));
  c.graph = testing::chain_network(n, Vec2(0, 0), Vec2(kLength, 0), kE);
  std::vector<double> cond(n), length(n), e(n, kE);
  for (int s = 0; s < n; ++s) {
    length[s] = c.graph.length(s);
    cond[s] = segment_conductance(kE, kE, length[s], kMu);
  }
  const std::vector<double> volume = node_volumes(c.graph, length, e, e);
  const int n_nodes = c.graph.n_nodes();
  auto conditions = [n_nodes](double) {
    NodeConditions bc(n_nodes);
    bc.fixed_pressure[0] = kP0;
    return bc;
  };
  build_transient_system(c.graph, cond, volume, FluidProperties{1000, kMu, kKf}, Vec2::Zero(),
                         conditions, 0, c.system);
  return c;
}

/// p / p0 at the unknowns (nodes 1..n) at t_end.
Eigen::VectorXd run(const Chain& c, Scheme scheme, double dt, double t_end, double rtol = 1e-6) {
  FlowControls::Transient controls;
  controls.scheme = scheme;
  controls.time_step = dt;
  controls.relative_tolerance = rtol;
  controls.absolute_tolerance = rtol * kP0;
  TransientIntegrator integrator(controls, {});
  Eigen::VectorXd x = Eigen::VectorXd::Zero(c.system.n());
  integrator.advance(c.system, x, 0, t_end);
  return x / kP0;
}

double analytical(double x, double t) {
  return std::erfc(x / (2 * std::sqrt(kD * t)));
}

TEST(flow_transient_chain, MatchesErfcAtDx005) {
  EXPECT_NEAR(analytical(1, 0.01), 0.098648, 1e-6);
  const Chain c = make_chain(0.05);
  for (Scheme scheme : {Scheme::Cvode, Scheme::Bdf2, Scheme::BackwardEuler}) {
    const Eigen::VectorXd p = run(c, scheme, scheme == Scheme::BackwardEuler ? 1e-5 : 1e-4, 0.01);
    double worst = 0;
    for (int i = 0; i < c.system.n(); ++i) {
      const double x = c.graph.nodes[c.system.network.node_of_unknown[i]].x();
      worst = std::max(worst, std::abs(p[i] - analytical(x, 0.01)));
    }
    const int at_1m = 1.0 / 0.05 - 1;  // node 20 is unknown 19
    std::printf("scheme %d: p/p0(1 m, 0.01 s) = %.6f (erfc 0.098648), max |error| %.4f\n",
                static_cast<int>(scheme), p[at_1m], worst);
    EXPECT_NEAR(p[at_1m], 0.098648, 0.01);
    EXPECT_LT(worst, 0.01);
  }
}

double observed_order(Scheme scheme) {
  const Chain c = make_chain(0.1);
  const double t_end = 0.01;
  const Eigen::VectorXd reference = run(c, Scheme::Cvode, 0, t_end, 1e-11);
  double previous = 0, order = 0;
  for (int k = 0; k < 4; ++k) {
    const double dt = 1e-3 / std::pow(2.0, k);
    const double error = (run(c, scheme, dt, t_end) - reference).lpNorm<Eigen::Infinity>();
    if (k > 0) {
      order = std::log2(previous / error);
      std::printf("scheme %d: dt %.3e -> %.3e: error %.3e -> %.3e, order %.3f\n",
                  static_cast<int>(scheme), 2 * dt, dt, previous, error, order);
    }
    previous = error;
  }
  return order;
}

TEST(flow_transient_chain, BackwardEulerIsFirstOrder) {
  EXPECT_NEAR(observed_order(Scheme::BackwardEuler), 1.0, 0.15);
}

TEST(flow_transient_chain, Bdf2IsSecondOrder) {
  EXPECT_NEAR(observed_order(Scheme::Bdf2), 2.0, 0.15);
}

TEST(flow_transient_chain, ExplicitLimitIsSharp) {
  const double dx = 0.1;
  const Chain c = make_chain(dx);
  const double limit = dx * dx / (2 * kD);
  EXPECT_NEAR(limit, 2.727e-4, 1e-7);
  EXPECT_NEAR(c.system.explicit_limit(), limit, 1e-10 * limit);
  const double t_end = 500 * limit;
  const Eigen::VectorXd stable = run(c, Scheme::Explicit, limit, t_end);
  EXPECT_LE(stable.maxCoeff(), 1 + 1e-12);
  EXPECT_GE(stable.minCoeff(), -1e-12);
  bool diverged = false;
  try {
    const Eigen::VectorXd unstable = run(c, Scheme::Explicit, 1.05 * limit, t_end);
    diverged = unstable.cwiseAbs().maxCoeff() > 10;
  } catch (const DivergenceError&) {
    diverged = true;
  }
  EXPECT_TRUE(diverged);
}

TEST(flow_transient_chain, ImplicitStepsFarBeyondTheExplicitLimit) {
  // 1000 x the explicit limit per step: bounded and still close to erfc.
  const Chain c = make_chain(0.1);
  const double dt = 1000 * c.system.explicit_limit();
  const Eigen::VectorXd p = run(c, Scheme::BackwardEuler, dt, 20 * dt);
  EXPECT_LE(p.maxCoeff(), 1 + 1e-12);
  EXPECT_GE(p.minCoeff(), -1e-12);
}

}  // namespace
}  // namespace fissure::flow
