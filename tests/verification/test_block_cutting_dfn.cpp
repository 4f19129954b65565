// Block cutting of random DFNs (issue verification 2): for networks of 100,
// 1,000 and 10,000 fractures in a box with a circular tunnel, the blocks
// cover exactly the domain minus the excavation (area to 1e-10 relative), no
// two blocks overlap, every block is a valid simple polygon (check_polygon at
// the scene's geometry tolerance, outer loop counter-clockwise, holes
// clockwise), no block is thinner than half the merge tolerance, and the
// fracture graph is consistent with the blocks.
#include <gtest/gtest.h>

#include <cmath>

#include "core/base/stopwatch.h"
#include "rockmass/generate_rock_mass.h"
#include "tests/support/block_checks.h"
#include "tests/support/rock_mass_specs.h"

namespace fissure {
namespace {

class RandomDfn : public ::testing::TestWithParam<int> {};

TEST_P(RandomDfn, BlocksTileTheRockExactly) {
  const int n = GetParam();
  const RockMassSpec spec = testing::random_dfn_spec(n, 7 + n);
  const double L = spec.domain[1].x();

  const Stopwatch clock;
  const GeneratedRockMass g = generate_rock_mass(spec);
  const double seconds = clock.seconds();

  std::vector<Polygon> blocks;
  for (const BlockSpec& b : g.blocks) blocks.push_back(b.polygon);
  const double rock = L * L - std::abs(signed_area(spec.excavations[0].vertices));
  const double area = testing::total_area(blocks);
  const double relative_error = std::abs(area - rock) / rock;
  std::printf(
      "DFN n = %d: %ld fractures drawn, %ld reach the rock, %zu blocks, %d graph segments, "
      "%d slivers and %d vertices merged, %d invalid merged; area error %.2e; %.3f s\n",
      n, g.statistics.generated_fractures, g.statistics.cut_fractures, g.blocks.size(),
      g.fractures.n_segments(), g.statistics.slivers_merged, g.statistics.vertices_merged,
      g.statistics.invalid_merged, relative_error, seconds);
  EXPECT_LT(relative_error, 1e-10);
  EXPECT_NEAR(static_cast<double>(g.statistics.generated_fractures), n, 5 * std::sqrt(n));

  const std::vector<std::string> problems = testing::block_system_problems(blocks, 1e-9 * L);
  EXPECT_TRUE(problems.empty()) << problems.front();
  for (const Polygon& p : blocks) {
    double perimeter = 0, a = 0;
    for (int k = 0; k < p.n_loops(); ++k) {
      a += signed_area(p.loop(k));
      for (int v = p.loop_offsets[k]; v < p.loop_offsets[k + 1]; ++v)
        perimeter += (p.vertices[p.next(v)] - p.vertices[v]).norm();
    }
    EXPECT_GE(2 * a / perimeter, 0.5 * spec.merge_tolerance);
  }
  const std::vector<std::string> graph_problems =
      testing::fracture_graph_problems(g.fractures, blocks, 1e-9 * L);
  EXPECT_TRUE(graph_problems.empty()) << graph_problems.front();
  EXPECT_TRUE(g.fractures.boundary_nodes.count("tunnel"));
  EXPECT_GT(g.blocks.size(), static_cast<size_t>(n / 20));
}

INSTANTIATE_TEST_SUITE_P(Sizes, RandomDfn, ::testing::Values(100, 1000, 10000));

TEST(RandomDfn, SameSeedSameRockMass) {
  const GeneratedRockMass a = generate_rock_mass(testing::random_dfn_spec(300, 5));
  const GeneratedRockMass b = generate_rock_mass(testing::random_dfn_spec(300, 5));
  ASSERT_EQ(a.blocks.size(), b.blocks.size());
  for (size_t i = 0; i < a.blocks.size(); ++i)
    EXPECT_EQ(a.blocks[i].polygon.vertices, b.blocks[i].polygon.vertices);
  EXPECT_EQ(a.fractures.nodes, b.fractures.nodes);
  const GeneratedRockMass c = generate_rock_mass(testing::random_dfn_spec(300, 6));
  EXPECT_NE(a.fractures.nodes, c.fractures.nodes);
}

}  // namespace
}  // namespace fissure
