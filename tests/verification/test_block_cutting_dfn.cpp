// Block cutting of random DFNs (issue verification 2): for networks of 100,
// 1,000 and 10,000 fractures in a box with a circular tunnel, the blocks
// cover exactly the domain minus the excavation (area to 1e-10 relative), no
// two blocks overlap, every block is a valid simple polygon (check_polygon at
// the scene's geometry tolerance, outer loop counter-clockwise, holes
// clockwise), no block is thinner than half the merge tolerance, and the
// fracture graph is consistent with the blocks.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "core/geometry/domain_sides.h"
#include "mechanics/blocks/generate_rock_mass.h"
#include "tests/support/block_checks.h"

namespace fissure {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// A square domain sized so that `n` fractures of two families (mean length
/// 2 m; P20 = 2 per m^2 in total) are expected to reach it, with a tunnel.
RockMassSpec dfn_spec(int n, std::uint64_t seed) {
  const double p20 = 2.0, mean_length = 2.0;
  // Expected number drawn: P20 (L^2 + 2 L E[l] + E[l^2]); solve for L.
  const double el2 = 2 * mean_length * mean_length;  // exponential: E[l^2] = 2 m^2
  const double L = -mean_length + std::sqrt(mean_length * mean_length - el2 + n / p20);
  RockMassSpec spec;
  spec.domain = {{0, 0}, {L, 0}, {L, L}, {0, L}};
  spec.excavations.push_back(
      ExcavationSpec{"tunnel", regular_polygon(Vec2(0.5 * L, 0.4 * L), 0.1 * L, 48)});
  spec.seed = seed;
  spec.merge_tolerance = 1e-5 * L;
  spec.max_blocks = 1000000;

  DfnFamilySpec a;
  a.name = "a";
  a.density_kind = DfnFamilySpec::Density::P20;
  a.density = 0.5 * p20;
  a.orientation.type = DistributionSpec::Type::VonMises;
  a.orientation.mean = 30 * kPi / 180;
  a.orientation.kappa = 10;
  a.length.type = DistributionSpec::Type::Exponential;
  a.length.mean = mean_length;
  a.aperture.value = 1e-4;
  DfnFamilySpec b = a;
  b.name = "b";
  b.orientation.type = DistributionSpec::Type::Uniform;
  spec.dfn = {a, b};
  return spec;
}

class RandomDfn : public ::testing::TestWithParam<int> {};

TEST_P(RandomDfn, BlocksTileTheRockExactly) {
  const int n = GetParam();
  const RockMassSpec spec = dfn_spec(n, 7 + n);
  const double L = spec.domain[1].x();

  const auto t0 = std::chrono::steady_clock::now();
  const GeneratedRockMass g = generate_rock_mass(spec);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

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

  const std::vector<std::string> problems =
      testing::block_system_problems(blocks, 1e-9 * L);
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
  const GeneratedRockMass a = generate_rock_mass(dfn_spec(300, 5));
  const GeneratedRockMass b = generate_rock_mass(dfn_spec(300, 5));
  ASSERT_EQ(a.blocks.size(), b.blocks.size());
  for (size_t i = 0; i < a.blocks.size(); ++i)
    EXPECT_EQ(a.blocks[i].polygon.vertices, b.blocks[i].polygon.vertices);
  EXPECT_EQ(a.fractures.nodes, b.fractures.nodes);
  const GeneratedRockMass c = generate_rock_mass(dfn_spec(300, 6));
  EXPECT_NE(a.fractures.nodes, c.fractures.nodes);
}

}  // namespace
}  // namespace fissure
