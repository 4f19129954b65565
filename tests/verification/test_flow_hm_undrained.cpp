// Undrained loading of a sealed fracture (docs/flow.md 7, the fixed-stress
// split of the transient HM coupling). The HM stack of docs/flow.md (a top
// block of width L = 2 m, height H = 1 m, density 2700 kg/m^3 on a fixed
// base, g = 10 m/s^2; the horizontal fracture between them with e0 = 100 um,
// k_n = 1e9 Pa/m) holds water at p0 = 10 kPa and is sealed (no condition:
// no flow in or out). The initial stage settles the block under its weight
// and p0: the joint carries sigma_n' = rho g H - p0 = 17 kPa, so
// e = e0 - sigma_n'/k_n = 83 um. A load of 10 kPa x L is then put on the
// top block. Closed form: the water cannot leave, so the joint can close
// only as far as the water compresses. Fluid volume V = L e (per unit
// thickness), storage S = V / K_f; the joint's compliance at fixed total
// stress C = L / k_n. Mass balance S dp = -dV with dV = -C (dsigma - dp):
//   dp = dsigma C / (C + S),   de = -(dsigma - dp) / k_n,
// with S / C = e k_n / K_f = 3.8e-5: the water takes the load (Skempton's
// B = 0.99996) and the aperture stays. Without the fixed-stress storage C
// the lagged loop pressure -> opening -> pressure has the gain C / S = 2.7e4.
// Tolerances: the pressure 1e-6 x dsigma and the aperture 1e-6 x e: the
// static DDA relaxes to equilibrium within a few steps of the load's
// plateau (as in test_flow_hm_stack.cpp, where the contact forces then give
// the aperture to 5e-8), and the storage uses the mean volume of each update
// (V changes by 5e-6 relative here). Measured: pressure 2.6e-8 x dsigma off
// before the load, 4.0e-7 x dsigma after; apertures 4e-8 and 5e-8 relative.
#include <gtest/gtest.h>

#include "coupling/coordinator.h"
#include "flow/cubic_law/flow_controls.h"
#include "rockmass/fields/fracture_flow.h"
#include "tests/support/flow_networks.h"
#include "tests/support/run_scene.h"

namespace fissure::testing {
namespace {

struct Result {
  double pressure, aperture;
};

constexpr double kP0 = 1e4, kLoad = 1e4, kLength = 2, kKn = 1e9, kBulk = 2.2e9;

Result sealed_stack(double end_time) {
  StackParameters p;
  p.kn = kKn;
  p.end_time = end_time;
  Scene scene = hm_stack_scene(p);
  FlowControls& flow = flow_controls(scene);
  flow.conditions.clear();  // sealed
  flow.initial_pressure = kP0;
  flow.transient.emplace().scheme = TransientControls::Scheme::BackwardEuler;
  flow.fluid.bulk_modulus = kBulk;
  scene.coupling.initial_equilibrium.emplace();
  scene.coupling.initial_equilibrium->max_speed = 1e-9;
  PointLoad load;
  load.point = Vec2(1, 1);  // the middle of the top block's upper edge
  load.block = 1;
  load.force = Vec2(0, -kLoad * kLength);
  load.history = {{0, 0}, {0.01, 0}, {0.02, 1}, {10, 1}};
  scene.point_loads.push_back(load);
  const RunResult r = run_scene(scene, "hm_undrained");
  EXPECT_EQ(r.summary.status, "completed") << r.summary.message;
  const FractureFlowState& state = r.state.fields.get(kFractureFlow);
  return {0.5 * (state.pressure[0] + state.pressure[1]),
          0.5 * (state.aperture_a[0] + state.aperture_b[0])};
}

TEST(flow_hm_undrained, ASealedFractureTakesTheLoadAndKeepsItsAperture) {
  const StackParameters p;
  const double sigma0 = p.density * p.g * p.height - kP0;  // effective stress at rest
  const double e_settled = p.e0 - sigma0 / kKn;
  // Before the load: the settled state, pressure p0.
  const Result before = sealed_stack(0.01);
  EXPECT_NEAR(before.pressure, kP0, 1e-6 * kLoad);
  EXPECT_NEAR(before.aperture, e_settled, 1e-6 * e_settled);
  // After the load's ramp and a plateau.
  const Result after = sealed_stack(0.1);
  const double compliance = kLength / kKn;
  const double storage = kLength * e_settled / kBulk;
  const double dp = kLoad * compliance / (compliance + storage);
  EXPECT_NEAR(after.pressure, kP0 + dp, 1e-6 * kLoad);
  EXPECT_NEAR(after.aperture, e_settled - (kLoad - dp) / kKn, 1e-6 * e_settled);
}

}  // namespace
}  // namespace fissure::testing
