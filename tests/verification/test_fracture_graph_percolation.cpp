// Connectivity and percolation of the fracture graph (issue 3 verification 5;
// docs/rock-mass.md section 6): on networks small enough to count by hand,
// the components, the boundaries each one touches, percolation between named
// boundaries, isolated and dead-end components and dead-end segments are
// exactly the expected ones. First on abstract graphs (analyze_connectivity
// alone), then on a 10 m x 10 m box cut by nine explicit fractures (the whole
// chain: cutting, fracture graph, connectivity, the summary of `fissure
// mesh`). Counts are integers: no tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "core/base/errors.h"
#include "core/geometry/network_connectivity.h"
#include "coupling/process_registry.h"
#include "rockmass/generate_rock_mass.h"
#include "rockmass/rock_mass_output.h"
#include "tests/support/block_checks.h"

namespace fissure {
namespace {

using Ends = std::vector<std::pair<int, int>>;
using Boundaries = std::map<std::string, std::vector<int>>;

TEST(ConnectivityOfGraphs, PathBetweenTwoBoundariesPercolatesAndHasNoDeadEnds) {
  // 0 - 1 - 2 - 3, node 0 on "in", node 3 on "out".
  const Ends ends = {{0, 1}, {1, 2}, {2, 3}};
  const NetworkConnectivity c = analyze_connectivity(4, ends, {{"in", {0}}, {"out", {3}}});
  EXPECT_EQ(c.n_components, 1);
  EXPECT_TRUE(c.percolates("in", "out"));
  EXPECT_TRUE(c.percolates("out", "in"));
  EXPECT_EQ(c.n_isolated(), 0);
  EXPECT_EQ(c.n_dead_end_components(), 0);
  EXPECT_EQ(c.n_dead_end_segments(), 0);
}

TEST(ConnectivityOfGraphs, BranchesArePrunedBackToTheBackbone) {
  // Backbone 0 - 1 - 2 - 3 (0 on "in", 3 on "out"); a two-segment branch
  // 1 - 4 - 5, a fork 2 - 6 with 6 - 7 and 6 - 8, and a loop 9 - 10 - 11 - 9
  // hanging from 3 by 3 - 9. The branch and the fork are dead ends; the loop
  // is not (it can circulate), nor is the segment that holds it.
  const Ends ends = {{0, 1}, {1, 2}, {2, 3}, {1, 4},  {4, 5},   {2, 6},
                     {6, 7}, {6, 8}, {3, 9}, {9, 10}, {10, 11}, {11, 9}};
  const NetworkConnectivity c = analyze_connectivity(12, ends, {{"in", {0}}, {"out", {3}}});
  EXPECT_EQ(c.n_components, 1);
  EXPECT_TRUE(c.percolates("in", "out"));
  const std::vector<char> expected = {0, 0, 0, 1, 1, 1, 1, 1, 0, 0, 0, 0};
  EXPECT_EQ(c.dead_end, expected);
}

TEST(ConnectivityOfGraphs, PruningStopsAtBoundaryNodes) {
  // A single segment from the boundary into the rock: its free end is
  // pruned, so the segment is a dead end; its component touches one
  // boundary (a dead-end component). A segment between two nodes of the
  // same boundary stays (it short-circuits that boundary).
  const Ends ends = {{0, 1}, {2, 3}};
  const NetworkConnectivity c =
      analyze_connectivity(5, ends, {{"left", {0, 2, 3}}, {"right", {4}}});
  EXPECT_EQ(c.n_components, 2);
  EXPECT_EQ(c.dead_end, (std::vector<char>{1, 0}));
  EXPECT_EQ(c.n_dead_end_components(), 2);
  EXPECT_EQ(c.n_isolated(), 0);
  EXPECT_FALSE(c.percolates("left", "right"));
  EXPECT_EQ(c.node_component[4], -1) << "a node without segments belongs to no component";
}

TEST(ConnectivityOfGraphs, ComponentsNumberedByLowestSegmentAndCounted) {
  // Three components: {0-1, 1-2} touching a and b, {3-4} touching nothing,
  // {5-5} (a closed self-loop) touching c.
  const Ends ends = {{3, 4}, {0, 1}, {5, 5}, {1, 2}};
  const NetworkConnectivity c = analyze_connectivity(6, ends, {{"a", {0}}, {"b", {2}}, {"c", {5}}});
  EXPECT_EQ(c.n_components, 3);
  EXPECT_EQ(c.segment_component, (std::vector<int>{0, 1, 2, 1}));
  EXPECT_EQ(c.component_segments, (std::vector<int>{1, 2, 1}));
  EXPECT_TRUE(c.isolated(0));
  EXPECT_EQ(c.component_boundaries[1], (std::vector<std::string>{"a", "b"}));
  EXPECT_TRUE(c.dead_end_component(2));
  EXPECT_TRUE(c.percolates("a", "b"));
  EXPECT_FALSE(c.percolates("a", "c"));
  EXPECT_EQ(c.dead_end, (std::vector<char>{1, 0, 0, 0}))
      << "the isolated segment is a dead end; a self-loop never is";
}

TEST(ConnectivityOfGraphs, NodesOutsideTheGraphAreErrors) {
  EXPECT_THROW(analyze_connectivity(2, Ends{{0, 2}}, {}), GeometryError);
  EXPECT_THROW(analyze_connectivity(2, Ends{{0, 1}}, {{"left", {5}}}), GeometryError);
}

// --- a cut network --------------------------------------------------------
//
// The box [0, 10] x [0, 10] and nine fractures (x, y in m):
//  * percolating cluster P: F1 (-1, 3) -> (6, 3) from the left side, F2
//    (5, 2) -> (5, 7), F3 (4, 6) -> (11, 6) to the right side. Its backbone
//    (0, 3) - (5, 3) - (5, 6) - (10, 6) cuts the box in two; the four
//    overhanging ends are dead ends inside blocks. 7 segments, 8 nodes.
//  * dead-end cluster D: F4 (2, 11) -> (2, 8) from the top, crossed by F5
//    (1, 9) -> (3.5, 9). Touches "top" only. 4 segments (all dead ends),
//    5 nodes.
//  * isolated triangle T: F6 (6.5, 7.5) -> (9.5, 7.5), F7 (7, 7) ->
//    (8.5, 9.5), F8 (9, 7) -> (7.5, 9.5). The triangle (7.3, 7.5),
//    (8.7, 7.5), (8, 26/3) is a block of its own, inside the upper block;
//    its six overhangs are dead ends. 9 segments, 9 nodes.
//  * isolated fracture S: F9 (1, 5) -> (2.5, 5), one dead-end segment.
// In all: 4 components, 21 segments (15 dead ends), 24 nodes, 3 blocks.

constexpr const char* kNetworkScene = R"(physics: [mechanics]
materials:
  - {name: rock, density: 2600 kg/m^3, young_modulus: 20 GPa, poisson_ratio: 0.25}
joints:
  - {name: joint, friction_angle: 30}
rock_mass:
  domain: [[0, 0], [10, 0], [10, 10], [0, 10]]
  fractures:
    - {from: [-1, 3], to: [6, 3]}
    - {from: [5, 2], to: [5, 7]}
    - {from: [4, 6], to: [11, 6]}
    - {from: [2, 11], to: [2, 8]}
    - {from: [1, 9], to: [3.5, 9]}
    - {from: [6.5, 7.5], to: [9.5, 7.5]}
    - {from: [7, 7], to: [8.5, 9.5]}
    - {from: [9, 7], to: [7.5, 9.5]}
    - {from: [1, 5], to: [2.5, 5]}
mechanics: {}
time:
  end: 0.01
)";

/// Connectivity of a scene's fracture graph.
NetworkConnectivity connectivity(const FractureGraph& g) {
  Ends ends;
  for (const FractureSegment& s : g.segments) ends.emplace_back(s.node_a, s.node_b);
  return analyze_connectivity(g.n_nodes(), ends, g.boundary_nodes);
}

/// The component of the graph node at p (exactly: every node here is a
/// fracture end or a crossing of fractures with decimal coordinates, or a
/// point on a box side), or -1.
int component_at(const FractureGraph& g, const NetworkConnectivity& c, const Vec2& p) {
  for (int n = 0; n < g.n_nodes(); ++n)
    if ((g.nodes[n] - p).norm() < 1e-9) return c.node_component[n];
  return -1;
}

class CutNetwork : public ::testing::Test {
 protected:
  void SetUp() override { scene = read_scene_text(kNetworkScene, "network.yaml"); }
  Scene scene;
};

TEST_F(CutNetwork, BlocksAndGraphHaveTheCountedSizes) {
  const FractureGraph& g = scene.initial_fields.get(kFractureGraph);
  EXPECT_EQ(scene.blocks.size(), 3u);
  EXPECT_EQ(g.n_segments(), 21);
  EXPECT_EQ(g.n_nodes(), 24);
  std::vector<Polygon> blocks;
  for (const BlockSpec& b : scene.blocks) blocks.push_back(b.polygon);
  EXPECT_NEAR(testing::total_area(blocks), 100.0, 1e-12 * 100);
  const std::vector<std::string> problems = testing::fracture_graph_problems(g, blocks, 1e-9);
  EXPECT_TRUE(problems.empty()) << problems.front();
  // The upper block holds the triangle as a hole.
  const auto holed = std::count_if(blocks.begin(), blocks.end(),
                                   [](const Polygon& p) { return p.n_loops() == 2; });
  EXPECT_EQ(holed, 1);
  // Nodes on the named sides: where P meets left and right, where D meets top.
  EXPECT_EQ(g.boundary_nodes.at("left").size(), 1u);
  EXPECT_EQ(g.boundary_nodes.at("right").size(), 1u);
  EXPECT_EQ(g.boundary_nodes.at("top").size(), 1u);
  EXPECT_TRUE(g.boundary_nodes.at("bottom").empty());
}

TEST_F(CutNetwork, ComponentsPercolationAndDeadEndsAreTheExpectedOnes) {
  const FractureGraph& g = scene.initial_fields.get(kFractureGraph);
  const NetworkConnectivity c = connectivity(g);
  ASSERT_EQ(c.n_components, 4);

  const int p = component_at(g, c, Vec2(5, 3)), d = component_at(g, c, Vec2(2, 9));
  const int t = component_at(g, c, Vec2(7.3, 7.5)), s = component_at(g, c, Vec2(1, 5));
  ASSERT_GE(std::min({p, d, t, s}), 0);
  EXPECT_EQ((std::set<int>{p, d, t, s}).size(), 4u) << "four distinct clusters";
  EXPECT_EQ(component_at(g, c, Vec2(10, 6)), p);
  EXPECT_EQ(component_at(g, c, Vec2(8, 26.0 / 3)), t);
  EXPECT_EQ(c.component_segments[p], 7);
  EXPECT_EQ(c.component_segments[d], 4);
  EXPECT_EQ(c.component_segments[t], 9);
  EXPECT_EQ(c.component_segments[s], 1);

  EXPECT_EQ(c.component_boundaries[p], (std::vector<std::string>{"left", "right"}));
  EXPECT_EQ(c.component_boundaries[d], (std::vector<std::string>{"top"}));
  EXPECT_TRUE(c.isolated(t));
  EXPECT_TRUE(c.isolated(s));
  EXPECT_TRUE(c.dead_end_component(d));
  EXPECT_EQ(c.n_isolated(), 2);
  EXPECT_EQ(c.n_dead_end_components(), 1);

  EXPECT_TRUE(c.percolates("left", "right"));
  EXPECT_FALSE(c.percolates("left", "top"));
  EXPECT_FALSE(c.percolates("right", "top"));
  EXPECT_FALSE(c.percolates("bottom", "top"));

  // Dead ends: the four overhangs of P, all of D, the six overhangs of T,
  // S. Here they are exactly the segments with one block on both sides (the
  // backbone of P and the triangle's sides separate blocks).
  EXPECT_EQ(c.n_dead_end_segments(), 15);
  for (int i = 0; i < g.n_segments(); ++i) {
    const FractureSegment& f = g.segments[i];
    EXPECT_EQ(c.dead_end[i] != 0, f.left.block == f.right.block) << "segment " << i;
  }
}

TEST_F(CutNetwork, MeshSummaryReportsTheSameConnectivity) {
  const nlohmann::json j = rock_mass_summary(scene);
  EXPECT_EQ(j["blocks"], 3);
  EXPECT_EQ(j["segments"], 21);
  EXPECT_EQ(j["components"], 4);
  EXPECT_EQ(j["isolated_components"], 2);
  EXPECT_EQ(j["dead_end_components"], 1);
  EXPECT_EQ(j["dead_end_segments"], 15);
  EXPECT_EQ(j["percolation"]["left-right"], true);
  EXPECT_EQ(j["percolation"]["left-top"], false);
  EXPECT_EQ(j["percolation"]["bottom-top"], false);
}

TEST(CutNetworkVariants, CuttingTheBackboneStopsPercolation) {
  // The same box with F3 shortened to end at x = 9.5: the cluster touches the
  // left side only, everything beyond the crossing (5, 3) is a dead end, and
  // the box is one block with a dangling network inside.
  std::string text = kNetworkScene;
  const std::string from = "{from: [4, 6], to: [11, 6]}";
  text.replace(text.find(from), from.size(), "{from: [4, 6], to: [9.5, 6]}");
  const Scene scene = read_scene_text(text, "network.yaml");
  const NetworkConnectivity c = connectivity(scene.initial_fields.get(kFractureGraph));
  EXPECT_FALSE(c.percolates("left", "right"));
  EXPECT_EQ(c.n_dead_end_components(), 2);
  EXPECT_EQ(c.n_isolated(), 2);
  // Only the triangle's three sides are not dead ends (a loop).
  EXPECT_EQ(c.n_dead_end_segments(), scene.initial_fields.get(kFractureGraph).n_segments() - 3);
  EXPECT_EQ(scene.blocks.size(), 2u) << "the rock around the triangle, and the triangle";
}

}  // namespace
}  // namespace fissure
