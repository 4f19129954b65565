// Unit tests of flow/hm: the network of a block system, wall kinematics,
// apertures from contacts (never from penalty penetration), the pressure
// loads on block edges (theory.md 3.1, 3.5), and the aperture laws of the
// joints (theory.md 3.8, docs/joints.md section 6). Mutations of
// joint_apertures.cpp checked to fail here: the sum e0 + u_n + u_dil
// regrouped (the bit-for-bit test), a Coulomb joint's k_n or dilation taken
// from flow.hm, the continuously yielding closure linear in sigma' or its
// compliance 1/k_n,ref, the Barton-Bandis compliance without de/dE, the left
// wall's joint taken whatever the right one's, two joints with models accepted.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

#include "core/base/errors.h"
#include "flow/hm/fracture_walls.h"
#include "flow/hm/hm_apertures.h"
#include "flow/hm/pressure_loads.h"
#include "flow/network/block_network.h"
#include "rockmass/joints/joint_model.h"
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

// The aperture laws of the joints (joint_apertures.h): a base and a top
// block, the top one sheared by `shear` and pressed on the base by sigma'
// (two contacts at its corners), the fracture between them.
struct PressedFracture {
  std::vector<Block> blocks;
  FractureGraph graph;
  std::vector<SegmentWalls> walls;
  std::vector<ContactRecord> contacts;

  PressedFracture(double sigma, double shear, int base_joint = 0, int top_joint = 0) {
    using testing::rectangle;
    blocks = blocks_of({rectangle(4, 1, 0, Vec2(-1, -1)), rectangle(2, 1, 0, Vec2(0, 0))});
    blocks[0].name = "base", blocks[1].name = "top";
    blocks[0].edge_joint.assign(4, base_joint);
    blocks[1].edge_joint.assign(4, top_joint);
    graph = network_from_blocks(blocks, 1e-4, 1e-9);
    const FractureSegment& seg = graph.segments.at(0);
    const int base_top_edge = seg.left.block == 0 ? seg.left.edge : seg.right.edge;
    for (Vec2& v : blocks[1].polygon.vertices) v.x() += shear;
    contacts.resize(2);
    for (int k = 0; k < 2; ++k) {
      contacts[k].block_i = 1;
      contacts[k].block_j = 0;
      contacts[k].edge = base_top_edge;
      contacts[k].point = Vec2(2.0 * k, 0);
      contacts[k].normal_force = sigma;  // 2 sigma over the 2 m fracture
    }
    walls = segment_walls(graph, graph.nodes, block_maps(blocks, initial_geometry(blocks)));
  }

  /// The aperture at end a and its compliance, with the laws of `joints`.
  std::pair<double, double> aperture(const std::vector<JointProperties>& joints,
                                     const HmApertureLaw& hm) const {
    FractureApertureLaws laws(joints, hm);
    laws.assign(graph, blocks, joints, "test");
    std::vector<double> ea, eb;
    WallState ws;
    hm_apertures(graph, walls, contacts, laws, ea, eb, &ws);
    return {ea.at(0), ws.compliance_a.at(0)};
  }
};

constexpr double kDeg = std::numbers::pi / 180;
const HmApertureLaw kHm{1e9, 5 * kDeg, 2e-3, {1e-6, 0}};  // flow.hm's law
constexpr double kE0 = 1e-4;                              // network_from_blocks' e0

JointProperties joint_with(const std::string& name, const joints::JointModel& model) {
  JointProperties joint{name, 30 * kDeg, 0, 0};
  joint.model.set(joints::kJointModel, model);
  return joint;
}

// A joint without a model keeps flow.hm's law, the arithmetic of the
// apertures before the joint models, to the bit (over a grid of stresses and
// shears, so that a change in the order of the sums shows in some last bit).
TEST(flow_hm, AJointWithoutAModelKeepsFlowHmsLawToTheBit) {
  const std::vector<JointProperties> joints = {{"plain", 30 * kDeg, 0, 0}};
  int checked = 0;
  for (int i = 0; i < 12; ++i)
    for (int k = 0; k < 12; ++k) {
      const PressedFracture f(3.7e3 * i, 2.3e-4 * k);
      FractureApertureLaws laws(joints, kHm);
      laws.assign(f.graph, f.blocks, joints, "test");
      std::vector<double> ea, eb, old_a, old_b;
      WallState ws;
      hm_apertures(f.graph, f.walls, f.contacts, laws, ea, eb, &ws);
      ASSERT_FALSE(laws.any_model());
      ASSERT_NEAR(ws.stress_a.at(0), 3.7e3 * i, 1e-9);
      ASSERT_NEAR(std::abs(ws.shear_a.at(0)), 2.3e-4 * k, 1e-15);
      for (const auto& [e, sigma, shear, compliance] :
           {std::tuple{ea[0], ws.stress_a[0], ws.shear_a[0], ws.compliance_a[0]},
            std::tuple{eb[0], ws.stress_b[0], ws.shear_b[0], ws.compliance_b[0]}}) {
        const double slip = std::min(std::abs(shear), kHm.dilation_limit);
        const double expected = clip_aperture(
            kE0 + -sigma / kHm.normal_stiffness + std::tan(kHm.dilation_angle) * slip, kHm.limits);
        EXPECT_EQ(e, expected) << "sigma' " << sigma << ", u_s " << shear;
        EXPECT_EQ(compliance, 1 / kHm.normal_stiffness);
        ++checked;
      }
      hm_apertures(f.graph, f.walls, f.contacts, kHm, old_a, old_b);
      EXPECT_EQ(ea, old_a);
      EXPECT_EQ(eb, old_b);
    }
  EXPECT_EQ(checked, 288);
}

// A Coulomb joint with its own k_n closes by it and dilates by its own
// psi and u_cs; without a stiffness of its own (the process's springs) it
// takes flow.hm's k_n, and without dilation flow.hm's.
TEST(flow_hm, ACoulombJointClosesAndDilatesByItsOwnLaw) {
  const double sigma = 4e4, shear = 3e-3;
  const PressedFracture f(sigma, shear);
  joints::CoulombProperties c;
  c.normal_stiffness = 4e9;
  c.shear_stiffness = 4e9;
  c.friction_angle = 30 * kDeg;
  c.dilation_angle = 10 * kDeg;
  c.zero_dilation_displacement = 1e-3;
  auto [e, compliance] = f.aperture({joint_with("own", c)}, kHm);
  EXPECT_NEAR(e, kE0 - sigma / 4e9 + std::tan(10 * kDeg) * 1e-3, 1e-18);
  EXPECT_DOUBLE_EQ(compliance, 1 / 4e9);
  c.normal_stiffness = c.shear_stiffness = 0;
  c.dilation_angle = 0;
  std::tie(e, compliance) = f.aperture({joint_with("springs", c)}, kHm);
  EXPECT_NEAR(e, kE0 - sigma / kHm.normal_stiffness + std::tan(kHm.dilation_angle) * 2e-3, 1e-18);
  EXPECT_DOUBLE_EQ(compliance, 1 / kHm.normal_stiffness);
}

// A continuously yielding joint closes on its normal curve: with e_n = 1/2,
// s = sigma'/sigma_ref and K = k_n,ref/sigma_ref, c = s / (K s_f^(1/2)) below
// the floor s_f = 0.01 and c = s_f^(1/2)/K + 2 (s^(1/2) - s_f^(1/2)) / K
// above it; its compliance is 1/k_n(sigma'), its dilation flow.hm's.
TEST(flow_hm, AContinuouslyYieldingJointClosesOnItsNormalCurve) {
  joints::ContinuouslyYieldingProperties y;
  y.normal_stiffness = 2e10;
  y.normal_stiffness_exponent = 0.5;
  y.shear_stiffness = 1e10;
  y.reference_normal_stress = 1e6;
  y.friction_angle = 30 * kDeg;
  y.initial_friction_angle = 40 * kDeg;
  y.roughness_length = 1e-3;
  const double K = 2e10 / 1e6, root_floor = 0.1;
  for (const double sigma : {5e3, 4e4, 1e5}) {
    const PressedFracture f(sigma, 1e-3);
    const auto [e, compliance] = f.aperture({joint_with("cy", y)}, kHm);
    const double s = sigma / 1e6;
    const double closure =
        s <= 0.01 ? s / (K * root_floor) : root_floor / K + 2 * (std::sqrt(s) - root_floor) / K;
    EXPECT_NEAR(e, kE0 - closure + std::tan(kHm.dilation_angle) * 1e-3, 1e-16) << sigma;
    EXPECT_NEAR(compliance, 1 / (2e10 * std::sqrt(std::max(s, 0.01))), 1e-24) << sigma;
    EXPECT_NEAR(joints::ContinuouslyYielding(y).normal_stress(closure), sigma, 1e-9 * sigma);
  }
}

// A Barton-Bandis joint stores de/dp = -de/dsigma' at fixed total stress:
// de/dE / k_n(sigma') with Bandis's tangent, de/dE = 2 e / E below the cap
// e = E (8 MPa here) and 1 at it (2 MPa); against a central difference of
// the apertures in sigma' (its O(h^2) error is below 1e-6 at h = 1 kPa).
TEST(flow_hm, ABartonBandisJointStoresItsTangentCompliance) {
  joints::BartonBandisProperties b;
  b.jrc = 10;
  b.jcs = 100e6;
  b.lab_length = 0.1;
  b.field_length = 1;
  b.residual_friction_angle = 28 * kDeg;
  b.initial_aperture = 0.5e-3;
  b.initial_normal_stiffness = 10e9;
  b.max_closure = 0.3e-3;
  const std::vector<JointProperties> joints = {joint_with("rough", b)};
  const double h = 1e3;
  for (const double sigma : {2e6, 8e6}) {
    const double compliance = PressedFracture(sigma, 0).aperture(joints, kHm).second;
    const double difference = (PressedFracture(sigma - h, 0).aperture(joints, kHm).first -
                               PressedFracture(sigma + h, 0).aperture(joints, kHm).first) /
                              (2 * h);
    EXPECT_NEAR(compliance, difference, 1e-6 * difference) << sigma;
  }
}

// A fracture takes the joint of its walls' block edges; where they differ,
// the one with a model; two different joints with models are refused.
TEST(flow_hm, AFractureTakesTheJointWithAModelOfItsWalls) {
  joints::CoulombProperties c;
  c.normal_stiffness = c.shear_stiffness = 4e9;
  const std::vector<JointProperties> joints = {
      {"plain", 30 * kDeg, 0, 0}, joint_with("own", c), joint_with("other", c)};
  const double sigma = 4e4;
  const double own = kE0 - sigma / 4e9, plain = kE0 - sigma / kHm.normal_stiffness;
  EXPECT_NEAR(PressedFracture(sigma, 0, 0, 1).aperture(joints, kHm).first, own, 1e-18);
  EXPECT_NEAR(PressedFracture(sigma, 0, 1, 0).aperture(joints, kHm).first, own, 1e-18);
  EXPECT_NEAR(PressedFracture(sigma, 0, 0, 0).aperture(joints, kHm).first, plain, 1e-18);
  EXPECT_NEAR(PressedFracture(sigma, 0, 1, 1).aperture(joints, kHm).first, own, 1e-18);
  try {
    PressedFracture(sigma, 0, 1, 2).aperture(joints, kHm);
    ADD_FAILURE() << "two joints with models on one fracture were accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("between block 'base' with joint 'own' and block 'top' "
                                         "with joint 'other'"),
              std::string::npos)
        << e.what();
  }
  // Without assign() (no network yet) every segment has flow.hm's law.
  const PressedFracture f(sigma, 0, 1, 1);
  std::vector<double> ea, eb;
  hm_apertures(f.graph, f.walls, f.contacts, FractureApertureLaws(joints, kHm), ea, eb);
  EXPECT_NEAR(ea.at(0), plain, 1e-18);
}

}  // namespace
}  // namespace fissure::flow
