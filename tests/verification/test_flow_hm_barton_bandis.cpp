// verification.md (t), docs/flow.md 7: the flow's HM aperture of a fracture
// whose joint is Barton-Bandis, against the closed forms written out here
// (not the library's helpers):
//  * Bandis's closure dV = sigma' V_m / (k_ni V_m + sigma'), the mechanical
//    aperture E = E_0 - dV and the hydraulic aperture of Barton, Bandis and
//    Bakhtar (1985) e = E^2 / JRC_0^2.5 in micrometres, at most E, over a
//    sweep of the effective normal stress from 0 to 40 MPa: a closed form
//    evaluated at the stress the contacts give, so to rounding (1e-13
//    relative: a few operations on the stress 2F/L that the walls recover
//    from the contact forces);
//  * the dilation after a shear u_s at constant sigma', the integral of
//    tan(psi_mob) over the table of Barton et al. (1985), exact as well;
//  * a loaded fracture in a run of the DDA and the flow (the HM stack of
//    docs/flow.md 7 with a Barton-Bandis joint): sigma' = rho g H - p(x)
//    from statics, each end's aperture against the closed form at its own
//    stress to 1e-6 (the tolerance of verification.flow_hm_stack: the
//    static DDA relaxes to equilibrium within the open-close force
//    tolerance; measured 4e-8) and the flux against the cubic law with
//    Iwai's aperture of the two ends to 1e-5 (three times the apertures'
//    error, and the solve's rounding; measured 6e-8).
// Mutations checked (each failed here; the tests that caught it: s = sweep,
// d = dilation, q = the coupled run): the hydraulic aperture with JRC_n
// instead of JRC_0 (s, d, q), without the cap e <= E (s, d: the run stays
// below the cap), with E^2 / JRC^2 (s, d, q); Bandis's closure replaced by
// the linear -sigma'/k_ni (s, d, q); the mechanical aperture from the
// segment's e0 instead of E_0 (s, d, q); the dilation with the tangent of
// each segment's middle angle instead of the integral (d), and without the
// factor 0.5 of psi_mob (d); the fracture's joint not looked up, every
// segment on flow.hm's law (s, d, q).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "coupling/coordinator.h"
#include "flow/hm/fracture_walls.h"
#include "flow/hm/hm_apertures.h"
#include "flow/network/block_network.h"
#include "rockmass/fields/fracture_flow.h"
#include "rockmass/joints/joint_model.h"
#include "tests/support/dda_scenes.h"
#include "tests/support/flow_networks.h"
#include "tests/support/run_scene.h"

namespace fissure::testing {
namespace {

using flow::FractureApertureLaws;
using flow::HmApertureLaw;
using joints::BartonBandisProperties;

constexpr double kDeg = std::numbers::pi / 180;

// JRC_0 10, JCS_0 100 MPa on 100 mm samples, 1 m blocks in the field;
// E_0 0.5 mm, k_ni 10 GPa/m, V_m 0.3 mm given (not the regressions).
BartonBandisProperties properties() {
  BartonBandisProperties p;
  p.jrc = 10;
  p.jcs = 100e6;
  p.lab_length = 0.1;
  p.field_length = 1.0;
  p.residual_friction_angle = 28 * kDeg;
  p.initial_aperture = 0.5e-3;
  p.initial_normal_stiffness = 10e9;
  p.max_closure = 0.3e-3;
  return p;
}

JointProperties joint_of(const BartonBandisProperties& p) {
  JointProperties joint{"rough", p.residual_friction_angle, 0, 0};
  joint.model.set(joints::kJointModel, joints::JointModel{p});
  return joint;
}

/// The closed forms: Bandis's closure, then e = E^2 / JRC_0^2.5 (um), <= E.
double mechanical_aperture(const BartonBandisProperties& p, double sigma, double dilation) {
  const double kni = p.initial_normal_stiffness, vm = p.max_closure;
  return p.initial_aperture - sigma * vm / (kni * vm + sigma) + dilation;
}
double hydraulic_aperture(const BartonBandisProperties& p, double mechanical) {
  const double e_um = mechanical * 1e6;
  return std::min(e_um * e_um / std::pow(p.jrc, 2.5), e_um) * 1e-6;
}

/// A top block (2 m x 1 m) on a fixed base, sheared by `shear` along the
/// joint and pressed by two contacts of `force` at its bottom corners: the
/// effective normal stress 2 force / 2 m on the fracture between them.
struct LoadedFracture {
  std::vector<Block> blocks;
  FractureGraph graph;
  std::vector<flow::SegmentWalls> walls;
  std::vector<ContactRecord> contacts;

  LoadedFracture(double force, double shear) {
    for (const Polygon& polygon :
         {rectangle(4, 1, 0, Vec2(-1, -1)), rectangle(2, 1, 0, Vec2(0, 0))}) {
      Block b;
      b.polygon = polygon;
      b.initial_vertices = polygon.vertices;
      b.edge_joint.assign(polygon.vertices.size(), 0);
      blocks.push_back(b);
    }
    graph = flow::network_from_blocks(blocks, 1e-4, 1e-9);
    const FractureSegment& seg = graph.segments.at(0);
    const int base_top_edge = seg.left.block == 0 ? seg.left.edge : seg.right.edge;
    for (Vec2& v : blocks[1].polygon.vertices) v.x() += shear;
    for (int k = 0; k < 2; ++k) {
      ContactRecord c;
      c.block_i = 1;
      c.block_j = 0;
      c.edge = base_top_edge;
      c.point = Vec2(2.0 * k, 0);
      c.normal_force = force;
      contacts.push_back(c);
    }
    walls = flow::segment_walls(graph, graph.nodes,
                                flow::block_maps(blocks, flow::initial_geometry(blocks)));
  }
};

/// The apertures at both ends with the joint's law (flow.hm's: k_n 1 GPa/m,
/// e_res 1 um).
std::pair<double, double> apertures(const LoadedFracture& f, const JointProperties& joint) {
  const HmApertureLaw hm{1e9, 0, 0, {1e-6, 0}};
  const std::vector<JointProperties> joints = {joint};
  FractureApertureLaws laws(joints, hm);
  laws.assign(f.graph, f.blocks, joints, "test");
  std::vector<double> ea, eb;
  flow::hm_apertures(f.graph, f.walls, f.contacts, laws, ea, eb);
  return {ea.at(0), eb.at(0)};
}

TEST(FlowHmBartonBandis, ApertureFollowsBandisClosureAndTheHydraulicAperture) {
  const BartonBandisProperties p = properties();
  const JointProperties joint = joint_of(p);
  int capped = 0, rough = 0;
  double worst = 0;
  for (const double sigma : {0.0, 1e4, 1e5, 5e5, 1e6, 2e6, 4e6, 5e6, 8e6, 1.5e7, 2.5e7, 4e7}) {
    const LoadedFracture f(sigma, 0);  // 2 x sigma over 2 m
    const auto [ea, eb] = apertures(f, joint);
    const double mechanical = mechanical_aperture(p, sigma, 0);
    const double e = hydraulic_aperture(p, mechanical);
    (mechanical * 1e6 < std::pow(p.jrc, 2.5) ? rough : capped) += 1;
    EXPECT_NEAR(ea, e, 1e-13 * e) << "sigma' = " << sigma;
    EXPECT_NEAR(eb, e, 1e-13 * e) << "sigma' = " << sigma;
    worst = std::max({worst, std::abs(ea - e) / e, std::abs(eb - e) / e});
  }
  std::printf("sigma' sweep: largest relative error %.2e\n", worst);
  // Both branches met: E below JRC_0^2.5 um = 316 um (above 4.74 MPa), and
  // the cap e = E (below it).
  EXPECT_EQ(capped, 7);
  EXPECT_EQ(rough, 5);
  // The closed form's figures at 40 MPa: dV = 279.07 um, E = 220.93 um, e = 154.35 um.
  EXPECT_NEAR(hydraulic_aperture(p, mechanical_aperture(p, 4e7, 0)), 154.351e-6, 0.001e-6);
}

// The dilation after a shear u_s at constant sigma': with
// psi_mob = 0.5 (JRC_mob / JRC_n) i linear in u_s between the points of the
// table, the integral of tan(psi_mob) over a segment is
// [ln cos psi]_end^start / (d psi / d u_s).
TEST(FlowHmBartonBandis, DilationFollowsTheMobilizedDilationAngle) {
  const BartonBandisProperties p = properties();
  const JointProperties joint = joint_of(p);
  const double jrc_n = p.jrc * std::pow(p.field_length / p.lab_length, -0.02 * p.jrc);
  const double jcs_n = p.jcs * std::pow(p.field_length / p.lab_length, -0.03 * p.jrc);
  const double dp = p.field_length / 500 * std::pow(jrc_n / p.field_length, 0.33);
  const std::vector<double> x = {0.3, 0.6, 1, 2, 4, 10, 100};
  const std::vector<double> ratio = {0, 0.75, 1, 0.85, 0.70, 0.50, 0};
  auto dilation = [&](double shear, double sigma) {
    const double i = jrc_n * std::log10(jcs_n / sigma) * kDeg;
    double d = 0;
    for (std::size_t k = 0; k + 1 < x.size() && shear > x[k] * dp; ++k) {
      const double end = std::min(shear, x[k + 1] * dp);
      const double a = 0.5 * ratio[k] * i;
      const double slope = 0.5 * (ratio[k + 1] - ratio[k]) * i / ((x[k + 1] - x[k]) * dp);
      const double b = a + slope * (end - x[k] * dp);
      d += (std::log(std::cos(a)) - std::log(std::cos(b))) / slope;
    }
    return d;
  };
  int rough = 0;
  double worst = 0;
  // 2 MPa: E = 380 um + dilation, capped; 8 MPa: E = 282 um + dilation,
  // below the cap while the dilation is below 34 um (up to 0.45 delta_p:
  // 4.5 um; 75 um at delta_p, 4.7 mm at 150 delta_p).
  for (const double sigma : {2e6, 8e6})
    for (const double ratio_of_peak : {0.2, 0.45, 1.0, 2.5, 12.0, 150.0}) {
      const double shear = ratio_of_peak * dp;
      const LoadedFracture f(sigma, shear);
      const auto [ea, eb] = apertures(f, joint);
      const double d = dilation(shear, sigma);
      const double mechanical = mechanical_aperture(p, sigma, d);
      const double e = hydraulic_aperture(p, mechanical);
      rough += mechanical * 1e6 < std::pow(p.jrc, 2.5);
      // The shear the walls report is the block's move to rounding (1e-16
      // of the 4 m block's coordinates: 1e-12 of the smallest shear, which
      // moves the aperture by tan(psi) < 1 times that).
      EXPECT_NEAR(ea, e, 1e-10 * e)
          << "sigma' = " << sigma << ", u_s / delta_p = " << ratio_of_peak;
      EXPECT_NEAR(eb, e, 1e-10 * e)
          << "sigma' = " << sigma << ", u_s / delta_p = " << ratio_of_peak;
      worst = std::max({worst, std::abs(ea - e) / e, std::abs(eb - e) / e});
      if (ratio_of_peak < 0.3) {
        EXPECT_EQ(d, 0);
      } else {
        EXPECT_GT(d, 0.005 * p.initial_aperture);  // the dilation shows in the aperture
      }
    }
  EXPECT_EQ(rough, 2);
  std::printf("shear: largest relative error %.2e\n", worst);
}

// The HM stack (docs/flow.md 7) with a Barton-Bandis joint between the
// blocks: the ends held at p + dp/2 (left) and p - dp/2 (right), so that the
// statics of the top block give the linear effective stress
// sigma'(x) = rho g H - p(x), and each end's aperture is the closed form's
// at its own stress (the law is not linear in sigma': the mean of the two
// ends is not the aperture at the mean stress, by e''/2 (dp/2)^2 = 4e-10 m
// at 20 kPa). The flux is the cubic law with Iwai's aperture of the two ends
// (theory.md 3.2), e_h^3 = 2 e_l^2 e_r^2 / (e_l + e_r).
TEST(FlowHmBartonBandis, FluxThroughALoadedFractureFollowsTheCubicLaw) {
  // E_0 200 um, k_ni 0.5 GPa/m, V_m 0.1 mm: k_ni V_m = 50 kPa, so the
  // overburden rho g H = 27 kPa closes the joint by a third of V_m.
  BartonBandisProperties p = properties();
  p.initial_aperture = 200e-6;
  p.initial_normal_stiffness = 5e8;
  p.max_closure = 100e-6;
  p.field_length = 0;  // the segment's length (2 m)
  StackParameters stack;
  stack.kn = 1e9;  // flow.hm's: not this joint's
  stack.p_ref = 1e4;
  stack.dp = 100;
  stack.history = {{0, 2}, {0.05, 2}, {0.1, 0.5}, {0.15, 0.5}};
  const double mu = 1e-3, length = 2;
  for (const auto& [end, factor] : {std::pair{0.05, 2.0}, std::pair{0.15, 0.5}}) {
    stack.end_time = end;
    Scene scene = hm_stack_scene(stack);
    scene.joints.at(0) = joint_of(p);
    RunOptions options;
    options.outdir = scratch_dir("flow_hm_barton_bandis");
    options.quiet = true;
    Coordinator coordinator(scene, options);
    const RunSummary summary = coordinator.run();
    ASSERT_EQ(summary.status, "completed") << summary.message;
    const RockMass& s = coordinator.state();
    const FractureGraph& graph = s.fields.get(kFractureGraph);
    const FractureFlowState& flow = s.fields.get(kFractureFlow);
    ASSERT_EQ(graph.n_segments(), 1);
    const FractureSegment& seg = graph.segments[0];
    const bool a_is_left = graph.nodes[seg.node_a].x() < graph.nodes[seg.node_b].x();
    const double left_to_right = a_is_left ? flow.flux[0] : -flow.flux[0];
    const double e_left = a_is_left ? flow.aperture_a[0] : flow.aperture_b[0];
    const double e_right = a_is_left ? flow.aperture_b[0] : flow.aperture_a[0];
    const double weight = stack.density * stack.g * stack.height;
    const double p_left = factor * (stack.p_ref + stack.dp / 2);
    const double p_right = factor * (stack.p_ref - stack.dp / 2);
    const double el = hydraulic_aperture(p, mechanical_aperture(p, weight - p_left, 0));
    const double er = hydraulic_aperture(p, mechanical_aperture(p, weight - p_right, 0));
    const double eh3 = 2 * el * el * er * er / (el + er);
    const double q = eh3 * (p_left - p_right) / (12 * mu * length);
    std::printf(
        "p = %.0f Pa: apertures %.7e, %.7e m (closed form %.7e, %.7e; relative errors %.1e, "
        "%.1e), flux %.7e m^2/s (cubic law %.7e; %.1e)\n",
        factor * stack.p_ref, e_left, e_right, el, er, std::abs(e_left - el) / el,
        std::abs(e_right - er) / er, left_to_right, q, std::abs(left_to_right - q) / q);
    EXPECT_NEAR(e_left, el, 1e-6 * el);
    EXPECT_NEAR(e_right, er, 1e-6 * er);
    EXPECT_NEAR(left_to_right, q, 1e-5 * q);
  }
}

}  // namespace
}  // namespace fissure::testing
