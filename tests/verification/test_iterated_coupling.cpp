// The iterated staggered scheme (coupling.scheme: iterated; theory.md 6.1,
// docs/architecture.md "Coupling") on real processes: the flow gives the
// others the pressures on the block walls and the segments' fluxes and
// apertures (CubicLawProcess::exchanged_values), so a coupling step is
// repeated until the pressures the mechanics is loaded with are those the
// flow computes from the apertures the mechanics leaves.
//
// configs/flow_hm_injection.yaml (80 blocks, a well injecting into the
// joints, the flow updated every 5 ms of DDA steps) to 15 ms: three flow
// updates. Measured: 4 passes per update with Aitken relaxation, the
// relative change of the exchanged values falling 0.035, 4e-4, 6e-6, 2e-8
// (superlinear). Checked: every coupling step reaches the tolerance; the
// monitors at 1e-6 are those at 1e-10 to 2.1e-6 relative (bound 2e-5), and
// they differ from the Lie sweep's (which loads the mechanics with the last
// update's pressures) by 17 % (bound: 1000 times the former): the iteration
// has an effect and is converged.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "coupling/process_registry.h"
#include "tests/support/run_scene.h"

namespace fissure::testing {
namespace {

RunResult run_injection(CouplingSettings::Scheme scheme, double tolerance,
                        const std::string& name) {
  Scene scene = read_scene(std::string(FISSURE_SOURCE_DIR "/configs/flow_hm_injection.yaml"));
  scene.coupling.scheme = scheme;
  scene.coupling.iteration.tolerance = tolerance;
  scene.time.end_time = 0.015;
  scene.output.hdf5 = false;
  return run_scene(scene, name);
}

/// Largest relative difference of the monitors' displacements and pressures.
double monitor_difference(const nlohmann::json& a, const nlohmann::json& b) {
  double worst = 0;
  for (const auto& [name, values] : a.items())
    for (const char* key : {"ux", "uy", "p"}) {
      if (!values[key].is_number()) continue;
      const double x = values[key].get<double>(), y = b[name][key].get<double>();
      worst = std::max(worst, std::abs(x - y) / std::max(std::abs(y), 1e-300));
    }
  return worst;
}

TEST(IteratedCoupling, TheHmInjectionConvergesInEveryCouplingStep) {
  using Scheme = CouplingSettings::Scheme;
  const RunResult iterated = run_injection(Scheme::Iterated, 1e-6, "iterated_hm");
  const RunResult tight = run_injection(Scheme::Iterated, 1e-10, "iterated_hm_tight");
  const RunResult lie = run_injection(Scheme::Lie, 1e-6, "lie_hm");
  for (const RunResult* r : {&iterated, &tight, &lie})
    ASSERT_EQ(r->summary.status, "completed") << r->summary.message;

  const nlohmann::json& it = iterated.summary.processes["coordinator"]["coupling"]["iteration"];
  EXPECT_EQ(it["not_converged_steps"], 0) << it;
  // The flow's three updates iterate (more than one pass each), and converge
  // fast: at most 6 passes (4 measured).
  EXPECT_GE(it["passes"].get<long>(), iterated.summary.steps + 3) << it;
  EXPECT_LE(it["max_passes_in_a_step"].get<long>(), 6) << it;
  const nlohmann::json& it_tight = tight.summary.processes["coordinator"]["coupling"]["iteration"];
  EXPECT_EQ(it_tight["not_converged_steps"], 0) << it_tight;
  EXPECT_GT(it_tight["passes"].get<long>(), it["passes"].get<long>()) << it_tight;

  const double to_tight = monitor_difference(iterated.summary.monitors, tight.summary.monitors);
  const double to_lie = monitor_difference(lie.summary.monitors, tight.summary.monitors);
  EXPECT_LT(to_tight, 2e-5) << "iterated (1e-6) against iterated (1e-10)";
  EXPECT_GT(to_lie, 1000 * to_tight) << "Lie against iterated (1e-10): " << to_lie;
}

}  // namespace
}  // namespace fissure::testing
