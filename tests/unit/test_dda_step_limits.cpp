// The DDA's step limits from the scene (mechanics/dda/dda_parameters.cpp,
// docs/dda.md section 1): the largest step displacement g2 w (w = half the
// model's larger side) and the contact range 2.5 g2 w, with g2 w capped at a
// fifth of the median block size. Without the cap one block stretching the
// model's box (the fuzzer's brick wall with a vertex moved 990 m up, seed
// 2024 case 4097) gave a contact range of 6 m among 0.5 m bricks: 600,000
// vertex-edge pairs and more than a minute per step.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "mechanics/dda/contact_detection.h"
#include "mechanics/dda/dda_parameters.h"
#include "mechanics/dda/step_update.h"
#include "tests/support/dda_scenes.h"

namespace fissure::dda {
namespace {

constexpr double kG2 = 0.005;  // the default max_displacement_ratio

/// 10 courses of 20 bricks 1 x 0.5 m on a 22 x 1 m base: a 22 m model.
Scene wall() {
  return testing::brick_wall_scene(10, 20, 1.0, 0.5, 30, 1e-3, 1e9, 1);
}

/// The wall with its first top-course brick's top-left corner 1 km up.
Scene wall_with_sliver() {
  Scene s = wall();
  Polygon& p = s.blocks[s.blocks.size() - 21].polygon;
  p.vertices[3].y() = 1000;
  return s;
}

TEST(DdaStepLimits, ModelOfAFewBlocksKeepsShisG2W) {
  const Scene s = wall();
  const DdaParameters p = DdaParameters::from_scene(s);
  // w = 11 m: g2 w = 0.055 m, below a fifth of the bricks' 0.707 m.
  EXPECT_DOUBLE_EQ(p.max_step_displacement, kG2 * 11);
  EXPECT_DOUBLE_EQ(p.contact_range, 2.5 * kG2 * 11);
}

TEST(DdaStepLimits, MedianBlockSizeIgnoresOneOddBlock) {
  // 200 bricks of sqrt(0.5) m (the few half bricks are smaller, the base and
  // the sliver larger): the median is a whole brick.
  EXPECT_DOUBLE_EQ(median_block_size(wall()), std::sqrt(0.5));
  EXPECT_DOUBLE_EQ(median_block_size(wall_with_sliver()), std::sqrt(0.5));
  EXPECT_EQ(median_block_size(Scene{}), 0);
}

TEST(DdaStepLimits, OneBlockStretchingTheModelDoesNotStretchTheStep) {
  const Scene s = wall_with_sliver();
  const DdaParameters p = DdaParameters::from_scene(s);
  // w would be about 500 m and g2 w 2.5 m; capped at a fifth of a brick.
  const double cap = kMaxStepPerBlockSize * std::sqrt(0.5);
  EXPECT_DOUBLE_EQ(p.max_step_displacement, cap);
  EXPECT_DOUBLE_EQ(p.contact_range, 2.5 * cap);
  EXPECT_LT(p.contact_range, 0.5 * std::sqrt(0.5) + 1e-12);
}

TEST(DdaStepLimits, ContactsOfTheStretchedModelStayLocal) {
  // With the capped range a vertex pairs with the edges of its neighbours
  // only: the wall with the sliver has about as many contact candidates as
  // the wall without it (a few more along the sliver's foot), not the
  // hundreds per vertex of a 6 m range.
  const auto count = [](const Scene& s) {
    const RockMass state = RockMass::from_scene(s);
    const DdaParameters p = DdaParameters::from_scene(s);
    return detect_contacts(state, p.contact_range, {}, true).size();
  };
  const std::size_t plain = count(wall()), stretched = count(wall_with_sliver());
  ASSERT_GT(plain, 0u);
  EXPECT_LT(stretched, plain + plain / 10) << "plain wall " << plain;
  // Every vertex of the wall has at most a handful of candidates.
  std::size_t vertices = 0;
  for (const BlockSpec& b : wall_with_sliver().blocks) vertices += b.polygon.vertices.size();
  EXPECT_LT(stretched, 4 * vertices);
}

// The strain guard (docs/dda.md section 1): a step whose strain would leave
// a block less than half its area is cut. The share kept is det(I + strain):
// (1 + ex)(1 + ey) - (gxy / 2)^2; the rotation keeps the area, and fixed
// blocks have no increment.
TEST(DdaStepLimits, TheAreaAStepsStrainLeavesABlock) {
  const Scene scene = wall();
  RockMass state = RockMass::from_scene(scene);
  std::vector<Vector6> d(state.blocks.size(), Vector6::Zero());
  const int free = static_cast<int>(state.blocks.size()) - 1;
  ASSERT_FALSE(state.blocks[free].fixed);
  ASSERT_TRUE(state.blocks[0].fixed);
  EXPECT_EQ(smallest_area_ratio(state, d), std::make_pair(-1, 1.0));

  d[free] << 0.1, -0.2, 0.3, 0, 0, 0;  // rigid motion: the area stays
  EXPECT_EQ(smallest_area_ratio(state, d).second, 1.0);
  d[free] << 0, 0, 0.3, -0.6, 0.1, 0.4;  // crushed: (0.4)(1.1) - 0.2^2 = 0.4
  const auto [block, ratio] = smallest_area_ratio(state, d);
  EXPECT_EQ(block, free);
  EXPECT_NEAR(ratio, 0.4, 1e-15);
  d[0] << 0, 0, 0, -2, -2, 0;  // a fixed block's entry is not looked at
  EXPECT_EQ(smallest_area_ratio(state, d).first, free);
  d[free] << 0, 0, 0, -1.5, 0.1, 0;  // inside out: a negative share
  EXPECT_LT(smallest_area_ratio(state, d).second, 0);
}

}  // namespace
}  // namespace fissure::dda
