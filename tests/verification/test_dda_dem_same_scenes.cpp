// The DDA and the explicit DEM on the same scenes of configs/ (issue 37,
// section 3; docs/verification.md, "DDA and DEM on the same scenes"):
//  * the brick wall as rigid blocks on linear joints in both methods
//    (tests/support/dda_dem_scenes.h: the DDA's corner springs p = 2.5e9 N/m
//    are the DEM's k_n = 10 GPa/m, its base 5 GPa/m). The DEM's top brick
//    settles by the joints' closed form; the DDA's by that plus its blocks'
//    elastic shortening at E = 1 TPa (3.6e-3 of it), whose closed form
//    assumes no lateral stress in the bricks. Tolerance 1e-4 of the
//    settlement: the lateral stresses the wall's friction and Poisson effect
//    leave (5 % of the vertical ones in brick_wall.yaml) change the blocks'
//    share by nu (1 + nu) x 5 % = 1.6 % of it, 6e-5 of the settlement. With
//    the blocks' share taken off, the two methods' end states agree within
//    it; the top brick's stress -rho g h / 2 in both within 1e-4 (the DEM's
//    contact points lie midway in the joint's closure: 2 dV / h = 5e-6).
//  * the jointed slope of jointed_slope.yaml and dem_jointed_slope.yaml
//    (k_n = E/s, k_s = G/s): both stand, no contact slides, every free block
//    moves elastically (below 1 mm; the DDA's largest 0.30 mm, the DEM's
//    0.54 mm), and the crest moves down and out of the slope in the same
//    direction (within 15 degrees; measured 6.4). Their magnitudes differ by
//    the two models' stiffness (the DEM's 0.53 mm against the DDA's 0.28 mm:
//    rigid blocks carry their whole weight on their joints, inclined joints
//    add their shear compliance), not asserted beyond the direction.
//  * the same slope on a weak bedding (12 degrees, below its 20 degree dip):
//    the same nine blocks slide in both (7 to 14 mm in 0.3 s), and no other
//    moves more than 0.7 mm: the set of blocks that move more than 2 mm is
//    the same.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <string>

#include "tests/support/dda_dem_scenes.h"
#include "tests/support/run_scene.h"

namespace fissure::testing {
namespace {

/// The top brick's settlement (m) and stress syy (Pa) from the "top" monitor.
struct TopBrick {
  double settlement, syy;
};

TopBrick top_brick(const RunResult& r) {
  const nlohmann::json& top = r.summary.monitors.at("top");
  return {-top.at("uy").get<double>(), top.at("syy").get<double>()};
}

TEST(DdaDemSameScenes, TheBrickWallSettlesOnItsJointsAlikeInBothMethods) {
  const RunResult dem = run_scene(
      rigid_wall_dem("  solve_ratio: 1e-9\n  max_cycles: 200000\n", 0.02), "dda_dem_wall_dem");
  const RunResult dda = run_scene(stiff_wall_dda(0.01, 0, 0.1), "dda_dem_wall_dda");
  ASSERT_EQ(dem.summary.status, "completed");
  ASSERT_EQ(dda.summary.status, "completed");
  const double joints = wall_joints_settlement();
  const double blocks = wall_blocks_shortening(wall::kStiffYoungModulus);
  const TopBrick a = top_brick(dem), b = top_brick(dda);
  EXPECT_NEAR(a.settlement, joints, 1e-6 * joints);
  EXPECT_NEAR(b.settlement, joints + blocks, 1e-4 * joints);
  EXPECT_NEAR(b.settlement - blocks, a.settlement, 1e-4 * joints);
  const double syy = -wall::kDensity * wall::kG * wall::kCourseHeight / 2;
  EXPECT_NEAR(a.syy, syy, 1e-4 * std::abs(syy));
  EXPECT_NEAR(b.syy, syy, 1e-4 * std::abs(syy));
}

/// Each free block's largest vertex displacement (m), by block index.
std::vector<double> free_block_moves(const RockMass& state) {
  std::vector<double> moves(state.blocks.size(), -1.0);
  for (std::size_t k = 0; k < state.blocks.size(); ++k) {
    const Block& b = state.blocks[k];
    if (b.fixed) continue;
    moves[k] = 0;
    for (std::size_t v = 0; v < b.polygon.vertices.size(); ++v)
      moves[k] = std::max(moves[k], (b.polygon.vertices[v] - b.initial_vertices[v]).norm());
  }
  return moves;
}

std::set<int> blocks_moved_beyond(const RockMass& state, double distance) {
  std::set<int> moved;
  const std::vector<double> moves = free_block_moves(state);
  for (std::size_t k = 0; k < moves.size(); ++k)
    if (moves[k] > distance) moved.insert(static_cast<int>(k));
  return moved;
}

long sliding_contacts(const RunResult& r, const std::string& process) {
  return r.summary.processes.at(process).at("contacts").at("sliding").get<long>();
}

TEST(DdaDemSameScenes, TheJointedSlopeStandsInBothMethods) {
  const RunResult dda = run_scene(edited_config("jointed_slope", {}), "dda_dem_slope_dda");
  const RunResult dem = run_scene(edited_config("dem_jointed_slope", {}), "dda_dem_slope_dem");
  ASSERT_EQ(dda.summary.status, "completed");
  ASSERT_EQ(dem.summary.status, "completed");
  EXPECT_EQ(sliding_contacts(dda, "mechanics"), 0);
  EXPECT_EQ(sliding_contacts(dem, "dem"), 0);
  EXPECT_TRUE(blocks_moved_beyond(dda.state, 1e-3).empty());
  EXPECT_TRUE(blocks_moved_beyond(dem.state, 1e-3).empty());
  // The crest's move: down and out of the slope (-x), in one direction.
  double direction[2];
  for (int k = 0; k < 2; ++k) {
    const nlohmann::json& crest = (k == 0 ? dda : dem).summary.monitors.at("crest");
    const double ux = crest.at("ux").get<double>(), uy = crest.at("uy").get<double>();
    EXPECT_LT(ux, 0);
    EXPECT_LT(uy, 0);
    direction[k] = std::atan2(uy, ux) * 180 / std::numbers::pi;
  }
  EXPECT_NEAR(direction[0], direction[1], 15.0);
}

TEST(DdaDemSameScenes, OnAWeakBeddingTheSameBlocksSlideInBothMethods) {
  const RunResult dda = run_scene(
      edited_config("jointed_slope", {{"{name: bedding, friction_angle: 35, cohesion: 0}",
                                       "{name: bedding, friction_angle: 12, cohesion: 0}"}}),
      "dda_dem_sliding_dda");
  // In real time (not solved to a ratio, which a sliding block never reaches).
  const RunResult dem = run_scene(
      edited_config("dem_jointed_slope",
                    {{"{name: bedding, friction_angle: 35,", "{name: bedding, friction_angle: 12,"},
                     {"  solve_ratio: 1e-5\n", ""}}),
      "dda_dem_sliding_dem");
  ASSERT_EQ(dda.summary.status, "completed");
  ASSERT_EQ(dem.summary.status, "completed");
  const std::set<int> sliding = blocks_moved_beyond(dda.state, 2e-3);
  EXPECT_FALSE(sliding.empty());
  EXPECT_EQ(sliding, blocks_moved_beyond(dem.state, 2e-3));
}

}  // namespace
}  // namespace fissure::testing
