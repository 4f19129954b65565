// A multi-block scene settling under gravity: 4 x 3 blocks (1 m, 2700 kg/m^3)
// dropped through 5 cm gaps onto a fixed floor, dynamic DDA (k01 = 1).
// Checks, every accepted step: the total energy (kinetic + potential + strain
// + penalty springs) never rises above its initial value, since Newmark
// (beta = 1/2, gamma = 1) and Coulomb friction only dissipate. At the end:
// the pile is at rest and no contact penetrates deeper than the penalty
// spring under the weight of the whole pile would allow (W / p_n).
#include <gtest/gtest.h>

#include "mechanics/dda/dda_process.h"
#include "tests/support/dda_scenes.h"

namespace fissure::testing {
namespace {

TEST(DdaSettling, PileComesToRestWithoutEnergyGain) {
  const Scene s = block_pile_scene(4, 3, 1.0, 0.05, 1e-3, 2.0);
  RockMass state = RockMass::from_scene(s);
  dda::DdaProcess dda(s);
  dda.initialize(state);

  const double e0 = dda.energy(state)["total"];
  double weight = 0;
  for (const Block& b : state.blocks)
    if (!b.fixed) weight += 2700 * b.section.area * 9.81;
  const double drop_energy = weight * 0.05 * 3;  // order of the energy released

  double t = 0, worst_gain = -1e300;
  int steps = 0;
  while (t < s.time.end_time) {
    const double dt = std::min(dda.proposed_dt(state), s.time.end_time - t);
    const StepReport r = dda.advance(state, t, dt);
    if (r.status != StepReport::Status::Ok) continue;
    t += dt;
    ++steps;
    worst_gain = std::max(worst_gain, dda.energy(state)["total"].get<double>() - e0);
  }
  // Energy: never above the start (round-off allowance 1e-9 of the released energy).
  EXPECT_LE(worst_gain, 1e-9 * drop_energy);
  // At rest: kinetic energy a negligible fraction of the energy released.
  EXPECT_LT(dda.energy(state)["kinetic"].get<double>(), 1e-8 * drop_energy);
  // Penetration at rest: bounded by the penalty spring under the pile's weight.
  const double penalty = dda.parameters().normal_penalty;
  double resting = 0;
  for (const dda::DdaContact& c : dda.contacts())
    if (c.state != ContactState::Open) resting = std::max(resting, -c.gap);
  EXPECT_LT(resting, weight / penalty);
  // During impacts: a block landing at v = sqrt(2 g h) on two contacts can
  // push at most m v^2 / 2 into them (the top block: h = 3 gaps).
  const double m = 2700 * 1.0, v2 = 2 * 9.81 * 0.15;
  const double impact_depth = std::sqrt(m * v2 / penalty);
  EXPECT_LT(dda.statistics()["max_penetration"].get<double>(), impact_depth);
  // No block passed through another, none left its column: vertically what
  // remains is the elastic deformation of the pile, rho g H h / E ~ 1e-5 m,
  // and the penetration at rest; sideways a block may slip during an impact
  // by about as much as the springs yield then (impact_depth, ~1e-4 m).
  for (std::size_t b = 1; b < state.blocks.size(); ++b) {
    const double y0 = 0.5 + (static_cast<double>((b - 1) / 4)) * 1.0;
    EXPECT_NEAR(state.blocks[b].section.centroid.y(), y0, 1e-4) << "block " << b;
    const double x0 = section_properties(s.blocks[b].polygon).centroid.x();
    EXPECT_NEAR(state.blocks[b].section.centroid.x(), x0, impact_depth) << "block " << b;
  }
  RecordProperty("steps", steps);
}

}  // namespace
}  // namespace fissure::testing
