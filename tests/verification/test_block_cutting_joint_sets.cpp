// Block cutting from joint sets (docs/rock-mass.md section 4; issue
// verification 1): two orthogonal persistent sets with spacings s1, s2 in an
// L x H box give exactly (L / s1)(H / s2) rectangular blocks whose areas sum
// to L H (1e-12 relative); the same for sets at an angle, where every block
// is a parallelogram of area s1 s2 / sin(angle) or a piece cut by the box.
#include <gtest/gtest.h>

#include <cmath>

#include "rockmass/block_cutter.h"
#include "rockmass/generate_rock_mass.h"
#include "tests/support/block_checks.h"

namespace fissure {
namespace {

constexpr double kPi = 3.14159265358979323846;

RockMassSpec box_spec(double L, double H) {
  RockMassSpec spec;
  spec.domain = {{0, 0}, {L, 0}, {L, H}, {0, H}};
  spec.merge_tolerance = 1e-5 * std::max(L, H);
  return spec;
}

JointSetSpec persistent_set(const std::string& name, double dip_deg, double spacing) {
  JointSetSpec s;
  s.name = name;
  s.dip = dip_deg * kPi / 180;
  s.spacing = spacing;
  s.aperture = 1e-4;
  return s;
}

std::vector<Polygon> polygons(const GeneratedRockMass& g) {
  std::vector<Polygon> p;
  for (const BlockSpec& b : g.blocks) p.push_back(b.polygon);
  return p;
}

struct Case {
  double L, H, s1, s2;
};

class OrthogonalSets : public ::testing::TestWithParam<Case> {};

TEST_P(OrthogonalSets, GiveExactlyTheGridOfRectangles) {
  const Case c = GetParam();
  RockMassSpec spec = box_spec(c.L, c.H);
  spec.joint_sets = {persistent_set("vertical", 90, c.s1), persistent_set("bedding", 0, c.s2)};
  const GeneratedRockMass g = generate_rock_mass(spec);

  const long expected = std::lround(c.L / c.s1) * std::lround(c.H / c.s2);
  ASSERT_EQ(static_cast<long>(g.blocks.size()), expected);
  const std::vector<Polygon> blocks = polygons(g);
  const double area = testing::total_area(blocks);
  EXPECT_NEAR(area / (c.L * c.H), 1.0, 1e-12) << "area " << area;
  for (const Polygon& p : blocks) {
    ASSERT_EQ(p.n_loops(), 1);
    ASSERT_EQ(p.n_vertices(), 4) << "a grid block is a rectangle";
    EXPECT_NEAR(signed_area(p.loop(0)) / (c.s1 * c.s2), 1.0, 1e-9);
  }
  EXPECT_TRUE(testing::block_system_problems(blocks, 1e-9 * std::max(c.L, c.H)).empty());

  // Graph: the interior grid lines; nodes at every crossing and where the
  // lines meet the sides; left/right faces are block edges.
  const long nx = std::lround(c.L / c.s1), ny = std::lround(c.H / c.s2);
  EXPECT_EQ(g.fractures.n_nodes(), (nx + 1) * (ny + 1) - 4);
  EXPECT_EQ(g.fractures.n_segments(), (nx - 1) * ny + (ny - 1) * nx);
  EXPECT_TRUE(testing::fracture_graph_problems(g.fractures, blocks, 1e-9).empty());
  EXPECT_EQ(g.fractures.boundary_nodes.at("left").size(), static_cast<size_t>(ny - 1));
  EXPECT_EQ(g.fractures.boundary_nodes.at("top").size(), static_cast<size_t>(nx - 1));
  for (const FractureSegment& s : g.fractures.segments) {
    EXPECT_NE(s.left.block, s.right.block);
    EXPECT_GE(s.left.edge, 0);
  }
}

INSTANTIATE_TEST_SUITE_P(Boxes, OrthogonalSets,
                         ::testing::Values(Case{10, 6, 1, 1}, Case{3, 2, 0.3, 0.25},
                                           Case{50, 30, 2.5, 1.5}, Case{1, 1, 0.1, 0.1},
                                           Case{7, 5, 0.7, 0.5}));

TEST(JointSetCutting, PhaseShiftsTheGridWithoutChangingTheCount) {
  // Phase 0.5: lines at (k + 1/2) s, so one more column and row of blocks,
  // the outer ones half as wide.
  RockMassSpec spec = box_spec(4, 3);
  spec.joint_sets = {persistent_set("v", 90, 1), persistent_set("h", 0, 1)};
  spec.joint_sets[0].phase = spec.joint_sets[1].phase = 0.5;
  const GeneratedRockMass g = generate_rock_mass(spec);
  EXPECT_EQ(g.blocks.size(), 5u * 4u);
  EXPECT_NEAR(testing::total_area(polygons(g)), 12.0, 1e-12 * 12);
}

TEST(JointSetCutting, InclinedSetsTileTheBox) {
  RockMassSpec spec = box_spec(20, 10);
  spec.joint_sets = {persistent_set("a", 30, 1.3), persistent_set("b", 110, 0.9)};
  const GeneratedRockMass g = generate_rock_mass(spec);
  const std::vector<Polygon> blocks = polygons(g);
  EXPECT_NEAR(testing::total_area(blocks) / 200.0, 1.0, 1e-12);
  EXPECT_TRUE(testing::block_system_problems(blocks, 1e-8).empty());
  // Whole parallelograms: area s1 s2 / sin(80 deg).
  const double cell = 1.3 * 0.9 / std::sin(80 * kPi / 180);
  int whole = 0;
  for (const Polygon& p : blocks)
    if (p.n_vertices() == 4 && std::abs(signed_area(p.loop(0)) / cell - 1) < 1e-9) ++whole;
  EXPECT_GT(whole, 100);
}

TEST(JointSetCutting, NonPersistentJointsLeaveDanglingSegmentsInsideBlocks) {
  // A persistent bedding set and a cross set with bridges: cross joints end
  // inside blocks and stay in the graph as segments with one block on both
  // sides.
  RockMassSpec spec = box_spec(10, 4);
  spec.joint_sets = {persistent_set("bedding", 0, 1)};
  JointSetSpec cross = persistent_set("cross", 80, 1.5);
  cross.trace_length = 0.6;
  cross.bridge_length = 0.7;
  cross.stagger = 0.5;
  spec.joint_sets.push_back(cross);
  const GeneratedRockMass g = generate_rock_mass(spec);
  const std::vector<Polygon> blocks = polygons(g);
  EXPECT_NEAR(testing::total_area(blocks) / 40.0, 1.0, 1e-12);
  EXPECT_TRUE(testing::block_system_problems(blocks, 1e-8).empty());
  EXPECT_TRUE(testing::fracture_graph_problems(g.fractures, blocks, 1e-9).empty());
  int inner = 0;
  for (const FractureSegment& s : g.fractures.segments)
    if (s.left.block == s.right.block && s.joint_set == 1) ++inner;
  EXPECT_GT(inner, 5);
  // The bedding is persistent: 4 layers at least.
  EXPECT_GE(g.blocks.size(), 4u);
}

}  // namespace
}  // namespace fissure
