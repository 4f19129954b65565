// Unit tests of flow/hm: the network of a block system, wall kinematics,
// apertures from contacts (never from penalty penetration), and the pressure
// loads on block edges (theory.md 3.1, 3.5).
#include <gtest/gtest.h>

#include <cmath>

#include "flow/hm/fracture_walls.h"
#include "flow/hm/hm_apertures.h"
#include "flow/hm/pressure_loads.h"
#include "flow/network/block_network.h"
#include "tests/support/dda_scenes.h"

namespace fissure::flow {
namespace {

std::vector<Block> blocks_of(const std::vector<Polygon>& polygons) {
  std::vector<Block> blocks;
  for (const Polygon& p : polygons) {
    Block b;
    b.polygon = p;
    b.initial_vertices = p.vertices;
    b.edge_joint.assign(p.vertices.size(), 0);
    blocks.push_back(b);
  }
  return blocks;
}

TEST(flow_hm, TwoByTwoBlocksMakeACross) {
  using testing::rectangle;
  const auto blocks = blocks_of({rectangle(1, 1, 0, Vec2(0, 0)), rectangle(1, 1, 0, Vec2(1, 0)),
                                 rectangle(1, 1, 0, Vec2(0, 1)), rectangle(1, 1, 0, Vec2(1, 1))});
  const FractureGraph g = network_from_blocks(blocks, 1e-4, 1e-9);
  EXPECT_EQ(g.n_nodes(), 5);
  EXPECT_EQ(g.n_segments(), 4);
  EXPECT_EQ(g.boundary_nodes.at("exterior").size(), 4u);  // the four fracture mouths
  EXPECT_EQ(g.boundary_nodes.at("left").size(), 1u);
  for (const FractureSegment& s : g.segments) {
    EXPECT_GE(s.left.block, 0);
    EXPECT_GE(s.right.block, 0);
    EXPECT_NE(s.left.block, s.right.block);
    // The left face's edge runs from node_a to node_b (block on its left).
    const Polygon& p = blocks[s.left.block].polygon;
    const Vec2 d = p.vertices[p.next(s.left.edge)] - p.vertices[s.left.edge];
    EXPECT_GT(d.dot(g.nodes[s.node_b] - g.nodes[s.node_a]), 0);
  }
}

TEST(flow_hm, BrickOnTwoBlocksIsSplitAtTheJunction) {
  using testing::rectangle;
  // A 2 m brick on two 1 m blocks: the bed joint is split at x = 1 (T-junction).
  const auto blocks = blocks_of({rectangle(1, 1, 0, Vec2(0, 0)), rectangle(1, 1, 0, Vec2(1, 0)),
                                 rectangle(2, 1, 0, Vec2(0, 1))});
  const FractureGraph g = network_from_blocks(blocks, 1e-4, 1e-9);
  EXPECT_EQ(g.n_nodes(), 4);     // (0,1), (1,1), (2,1), (1,0)
  EXPECT_EQ(g.n_segments(), 3);  // two bed segments and the vertical joint
}

TEST(flow_hm, AffineMapsFollowRigidMotionAndStrain) {
  using testing::rectangle;
  auto blocks = blocks_of({rectangle(2, 1, 0, Vec2(0, 0))});
  Eigen::Matrix2d a;
  a << std::cos(0.1) * 1.001, -std::sin(0.1), std::sin(0.1), std::cos(0.1) * 0.999;
  for (Vec2& v : blocks[0].polygon.vertices) v = a * v + Vec2(0.3, -0.2);
  const auto maps = block_maps(blocks, initial_geometry(blocks));
  const Vec2 x(0.7, 0.4);
  EXPECT_NEAR((maps[0](x) - (a * x + Vec2(0.3, -0.2))).norm(), 0, 1e-14);
}

TEST(flow_hm, AperturesFromContactForcesAndOpening) {
  using testing::rectangle;
  // Base below, top block above: one segment along the base's top edge.
  auto blocks = blocks_of({rectangle(4, 1, 0, Vec2(-1, -1)), rectangle(2, 1, 0, Vec2(0, 0))});
  blocks[0].fixed = true;
  const FractureGraph g = network_from_blocks(blocks, 1e-4, 1e-9);
  ASSERT_EQ(g.n_segments(), 1);
  const FractureSegment& seg = g.segments[0];
  HmApertureLaw law{1e9, 0, 0, {1e-5, 0}};
  // Closed: two contacts of 5 kN at the top block's bottom corners, on the
  // base's top edge; the top block penetrates 1e-8 m (penalty): ignored.
  for (Vec2& v : blocks[1].polygon.vertices) v.y() -= 1e-8;
  std::vector<ContactRecord> contacts(2);
  const int base_top_edge = seg.left.block == 0 ? seg.left.edge : seg.right.edge;
  for (int k = 0; k < 2; ++k) {
    contacts[k].block_i = 1;
    contacts[k].block_j = 0;
    contacts[k].edge = base_top_edge;
    contacts[k].point = Vec2(2.0 * k, -1e-8);
    contacts[k].normal_force = 5e3;
  }
  auto walls = segment_walls(g, g.nodes, block_maps(blocks, initial_geometry(blocks)));
  std::vector<double> ea, eb;
  WallState ws;
  hm_apertures(g, walls, contacts, law, ea, eb, &ws);
  // sigma' = 10 kN / 2 m = 5 kPa; closure 5e3 / 1e9 = 5e-6 m.
  EXPECT_NEAR(ws.stress_a[0], 5e3, 1e-6);
  EXPECT_NEAR(ea[0], 1e-4 - 5e-6, 1e-15);
  EXPECT_NEAR(eb[0], 1e-4 - 5e-6, 1e-15);
  // Open: the top block lifted by 20 um, no contacts.
  for (Vec2& v : blocks[1].polygon.vertices) v.y() += 1e-8 + 20e-6;
  walls = segment_walls(g, g.nodes, block_maps(blocks, initial_geometry(blocks)));
  hm_apertures(g, walls, {}, law, ea, eb);
  EXPECT_NEAR(ea[0], 1.2e-4, 1e-15);
  EXPECT_NEAR(eb[0], 1.2e-4, 1e-15);
}

TEST(flow_hm, UniformPressureLoadsBalance) {
  using testing::rectangle;
  // A block surrounded by four others: a uniform pressure on all its walls
  // gives zero resultant on it.
  const auto blocks = blocks_of({rectangle(1, 1, 0, Vec2(0, 0)), rectangle(1, 3, 0, Vec2(-1, -1)),
                                 rectangle(1, 3, 0, Vec2(1, -1)), rectangle(1, 1, 0, Vec2(0, -1)),
                                 rectangle(1, 1, 0, Vec2(0, 1))});
  const FractureGraph g = network_from_blocks(blocks, 1e-4, 1e-9);
  const auto walls = segment_walls(g, g.nodes, block_maps(blocks, initial_geometry(blocks)));
  const std::vector<double> p(g.n_nodes(), 1e5);
  const auto loads = wall_pressure_loads(g, walls, p, blocks);
  Vec2 force = Vec2::Zero();
  double perimeter = 0;
  for (const EdgePressureLoad& l : loads) {
    if (l.block != 0) continue;
    const double len = (l.b - l.a).norm();
    force += -0.5 * (l.p_a + l.p_b) * len * l.normal;
    perimeter += len;
    // Outward: the normal points away from the block's centroid (0.5, 0.5).
    EXPECT_GT(l.normal.dot(0.5 * (l.a + l.b) - Vec2(0.5, 0.5)), 0);
  }
  EXPECT_NEAR(perimeter, 4, 1e-12);
  EXPECT_NEAR(force.norm(), 0, 1e-9);
}

}  // namespace
}  // namespace fissure::flow
