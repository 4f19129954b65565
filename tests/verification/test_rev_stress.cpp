// The REV study under stress (docs/upscaling.md section 5; docs/verification.md
// "REV under stress"): squares cut from a rock mass of persistent joint sets,
// loaded by a stress state and brought to rest by the DEM, against closed forms.
//  * One set under the normal stress sigma_n: the square's permeability is
//    e^3 / 12 sum (L / A) t t^T over its traces (L inside the square: e^3 /
//    (12 s) on average over positions) with e the joint law's aperture at
//    sigma_n: e0 - sigma_n / k_n (linear) or Bandis's
//    E = E0 - sigma_n V_m / (k_ni V_m + sigma_n), e = E^2 / JRC^2.5 (um).
//  * Two orthogonal sets, the first at theta to sigma_1: below the ratio
//    sigma_1 / sigma_3 = (1 + tan(phi) cot(theta)) / (1 - tan(phi) tan(theta))
//    nothing slips and each set closes by its own sigma_n; above it the
//    first set slips, and the rollers bring the blocks to rest again.
// Below the critical ratio the prestressed blocks are in equilibrium as they
// start, so the contact stresses are the applied ones to round-off and the
// flow network of persistent sets is solved exactly: the tolerance 1e-9 is
// round-off's. Where a side of the square cuts a block into a corner with a
// short edge (2.4 mm at 30 and 120 deg), the contacts' shares of the
// interface (half the distance to their neighbours, UDEC's rule) do not give
// the exact traction there: the prestress is out of balance by 1e-3 of a
// contact force, the blocks move to rest and k changes by 2e-5; the
// two-set tests allow 1e-4. A slip near the critical ratio is decided by a
// margin of 1 % of the ratio, far above the solve ratio's share (1e-7).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <numbers>
#include <string>

#include "core/geometry/segment_clip.h"
#include "coupling/process_registry.h"
#include "coupling/upscaling/scene_rock_mass_source.h"
#include "coupling/upscaling/stress_study.h"
#include "flow/rev/permeability.h"
#include "flow/rev/tensor_fit.h"
#include "mechanics/dem/dem_settings.h"

namespace fissure {
namespace {

constexpr double kDeg = std::numbers::pi / 180;
constexpr double kSize = 4, kAperture = 100e-6, kNormalStiffness = 80e9;

/// A 20 m rock mass of persistent sets at `dips` (deg), spacing 0.5 m,
/// aperture kAperture, on joint `joint` (a joints[] item).
std::shared_ptr<const Scene> rock_mass(const std::vector<double>& dips, const std::string& joint,
                                       const std::string& dem = "{solve_ratio: 1e-7}") {
  std::string yaml =
      "name: rock\nphysics: [dem]\nmaterials:\n"
      "  - {name: granite, density: 2650, young_modulus: 50 GPa, poisson_ratio: 0.25}\n"
      "joints:\n  - " +
      joint +
      "\nrock_mass:\n  domain: [[-10, -10], [10, -10], [10, 10], [-10, 10]]\n"
      "  material: granite\n  joint_sets:\n";
  for (std::size_t i = 0; i < dips.size(); ++i)
    yaml += "    - {name: s" + std::to_string(i) + ", dip: " + std::to_string(dips[i]) +
            ", spacing: 0.5 m, joint: j, aperture: 100 um, phase: 0.3}\n";
  yaml += "dem: " + dem + "\ntime: {end: 1}\n";
  return std::make_shared<const Scene>(read_scene_text(yaml, "rock.yaml"));
}

std::string coulomb(double friction_deg, double dilation_deg = 0) {
  return "{name: j, model: coulomb, friction_angle: " + std::to_string(friction_deg) +
         ", dilation_angle: " + std::to_string(dilation_deg) +
         ", normal_stiffness: 80 GPa/m, shear_stiffness: 30 GPa/m}";
}

/// Principal stresses (compression +, sigma_1 along `angle` deg) as the
/// total stress tensor (tension +).
StressState principal_state(double sigma_1, double sigma_3, double angle_deg = 0) {
  const double c = std::cos(angle_deg * kDeg), s = std::sin(angle_deg * kDeg);
  StressState st;
  st.stress << -(sigma_1 * c * c + sigma_3 * s * s), -(sigma_1 * s * s + sigma_3 * c * c),
      -(sigma_1 - sigma_3) * c * s;
  return st;
}

/// The study's one domain (a 4 m square) under each state.
std::vector<StressStateResult> solve(std::shared_ptr<const Scene> scene,
                                     const std::vector<StressState>& states,
                                     double compliance_increment = 0) {
  flow::RevStudyConfig study;
  study.sizes = {kSize};
  study.realizations = 1;
  study.rotations = 1;
  study.threads = 1;
  StressStudyConfig config;
  config.states = states;
  config.compliance_increment = compliance_increment;
  const SceneRockMassSource source(std::move(scene), Vec2::Zero());
  return run_stress_study(study, config, source, {});
}

/// The exact permeability of the square's network: sum over its traces of
/// e^3 / 12 (L / A) t t^T, L the trace's length inside the square and e its
/// set's aperture (`aperture_of_set`). For persistent sets this is e^3 /
/// (12 s) on average; a finite square holds a little more or less trace
/// length than A / s (9e-4 for the 40 deg sets below), so the exact value
/// is the reference.
Eigen::Matrix2d network_permeability(const std::shared_ptr<const Scene>& scene, double angle_deg,
                                     const std::vector<double>& aperture_of_set) {
  const SceneRockMassSource source(scene, Vec2::Zero());
  Box square;
  square.extend(Vec2(-kSize / 2, -kSize / 2));
  square.extend(Vec2(kSize / 2, kSize / 2));
  Eigen::Matrix2d k = Eigen::Matrix2d::Zero();
  for (FractureTrace t : source.square_traces(0, kSize, angle_deg * kDeg)) {
    if (!clip_to_box(t.a, t.b, square)) continue;
    const Eigen::Vector2d d = (t.b - t.a) / (kSize * kSize);
    const Eigen::Vector2d u = (t.b - t.a).normalized();
    k += std::pow(aperture_of_set[t.set], 3) / 12 * d.norm() * u * u.transpose();
  }
  // Back into the study's frame.
  return flow::rotate_into(k, -angle_deg * kDeg);
}

/// sigma_n on a plane at `dip` (deg) under sigma_1 along x and sigma_3.
double normal_stress(double sigma_1, double sigma_3, double dip) {
  const double s = std::sin(dip * kDeg), c = std::cos(dip * kDeg);
  return sigma_1 * s * s + sigma_3 * c * c;
}

void expect_tensor_near(const Eigen::Matrix2d& k, const Eigen::Matrix2d& expected, double rel) {
  const double scale = expected.norm();
  EXPECT_LT((k - expected).norm(), rel * scale) << "k =\n" << k << "\nexpected\n" << expected;
}

TEST(RevStress, OneSetClosesAsItsLinearJoint) {
  // Horizontal set, sigma_1 vertical (normal to it) at several magnitudes.
  const auto scene = rock_mass({0}, coulomb(30));
  std::vector<StressState> states;
  const std::vector<double> sigma = {0, 1e6, 2.5e6, 5e6};
  for (double s : sigma) states.push_back(principal_state(s, 0.4 * s, 90));
  const auto results = solve(scene, states);
  for (std::size_t i = 0; i < sigma.size(); ++i) {
    const double e = kAperture - sigma[i] / kNormalStiffness;
    SCOPED_TRACE(sigma[i]);
    expect_tensor_near(results[i].rev.domains[0].k, network_permeability(scene, 90, {e}), 1e-9);
    EXPECT_EQ(results[i].rev.domains[0].mechanics.slip_fraction, 0);
    EXPECT_TRUE(results[i].rev.domains[0].mechanics.equilibrium);
  }
}

TEST(RevStress, OneSetClosesOnBandisHyperbola) {
  constexpr double kE0 = 300e-6, kni = 30e9, vm = 150e-6, jrc = 6;
  const auto scene =
      rock_mass({0},
                "{name: j, model: barton_bandis, friction_angle: 30, jrc: 6, jcs: 100 MPa, "
                "lab_length: 0.5 m, field_length: 0.5 m, initial_aperture: 300 um, "
                "initial_normal_stiffness: 30 GPa/m, max_closure: 150 um}");
  std::vector<StressState> states;
  const std::vector<double> sigma = {0.5e6, 2e6, 8e6, 20e6};
  for (double s : sigma) states.push_back(principal_state(s, s, 0));
  const auto results = solve(scene, states);
  for (std::size_t i = 0; i < sigma.size(); ++i) {
    const double mechanical = kE0 - sigma[i] * vm / (kni * vm + sigma[i]);
    const double um = mechanical / 1e-6;
    const double e = std::min(um * um / std::pow(jrc, 2.5) * 1e-6, mechanical);
    SCOPED_TRACE(sigma[i]);
    expect_tensor_near(results[i].rev.domains[0].k, network_permeability(scene, 0, {e}), 1e-9);
  }
}

TEST(RevStress, TheSquareFollowsThePrincipalAxes) {
  // A set at 30 deg, sigma_1 normal to it (120 deg): k along 30 deg only,
  // reported in the study's frame.
  const auto scene = rock_mass({30}, coulomb(30));
  const auto results = solve(scene, {principal_state(4e6, 1e6, 120)});
  const double e = kAperture - 4e6 / kNormalStiffness;
  expect_tensor_near(results[0].rev.domains[0].k, network_permeability(scene, 120, {e}), 1e-9);
  EXPECT_NEAR(results[0].principal.angle, 120 * kDeg, 1e-12);
}

/// sigma_1 / sigma_3 at which a plane at theta (deg) to sigma_1 slips.
double critical_ratio(double theta_deg, double phi_deg) {
  const double t = std::tan(phi_deg * kDeg);
  return (1 + t / std::tan(theta_deg * kDeg)) / (1 - t * std::tan(theta_deg * kDeg));
}

TEST(RevStress, OrthogonalSetsSlipAtMohrCoulombsRatio) {
  constexpr double kSigma3 = 2e6;
  for (const auto& [theta, phi] : {std::pair{30.0, 30.0}, {40.0, 20.0}, {25.0, 35.0}}) {
    SCOPED_TRACE(::testing::Message() << "theta " << theta << ", phi " << phi);
    const double ratio = critical_ratio(theta, phi);
    const auto scene = rock_mass({theta, theta + 90}, coulomb(phi));
    const auto results = solve(scene, {principal_state(0.99 * ratio * kSigma3, kSigma3),
                                       principal_state(1.01 * ratio * kSigma3, kSigma3)});
    // Below: at rest as loaded, each set closed by its own sigma_n.
    const double s1 = 0.99 * ratio * kSigma3;
    const std::vector<double> e = {
        kAperture - normal_stress(s1, kSigma3, theta) / kNormalStiffness,
        kAperture - normal_stress(s1, kSigma3, theta + 90) / kNormalStiffness};
    const flow::DomainResult& below = results[0].rev.domains[0];
    expect_tensor_near(below.k, network_permeability(scene, 0, e), 1e-4);
    EXPECT_EQ(below.mechanics.slip_fraction, 0);
    EXPECT_TRUE(below.mechanics.equilibrium);
    // Above: the first set slips (the second, at 90 - theta, holds: its
    // ratio is larger), and the rollers bring the blocks to rest again.
    const flow::DomainResult& above = results[1].rev.domains[0];
    EXPECT_GT(above.mechanics.slip_fraction, 0);
    EXPECT_TRUE(above.mechanics.equilibrium);
  }
}

TEST(RevStress, PastTheCriticalRatioDilationOpensTheSlippedSet) {
  // The same slip with a dilation angle of 10 deg opens the network further
  // than without: each slipped segment gains tan(psi) |u_s| (at most).
  constexpr double kSigma3 = 2e6;
  const double s1 = 1.05 * critical_ratio(30, 30) * kSigma3;
  const auto flat = solve(rock_mass({30, 120}, coulomb(30)), {principal_state(s1, kSigma3)});
  const auto dilating =
      solve(rock_mass({30, 120}, coulomb(30, 10)), {principal_state(s1, kSigma3)});
  double kmax_flat, kmin_flat, kmax_dilating, kmin_dilating, angle;
  flow::principal(flat[0].rev.domains[0].k, kmax_flat, kmin_flat, angle);
  flow::principal(dilating[0].rev.domains[0].k, kmax_dilating, kmin_dilating, angle);
  EXPECT_GT(dilating[0].rev.domains[0].mechanics.slip_fraction, 0.1);
  EXPECT_GT(kmax_dilating, kmax_flat);
  EXPECT_TRUE(dilating[0].rev.domains[0].mechanics.equilibrium);
}

// The compliance of one set of spacing s (docs/upscaling.md section 5), of
// the floating square: its joints and the blocks in series. Rigid blocks:
// 1/(k_n s) across the set, nothing along it, no coupling; in shear
// 1/(k_s s), uncoupled from the normal terms. Zoned blocks (plane strain,
// the lateral side free): (1 - nu^2)/E + 1/(k_n s) across, (1 - nu^2)/E
// along, -C_tn/C_tt = nu/(1 - nu), and in shear 2 (1 + nu)/E + 1/(k_s s).
// The increment (0.1 MPa) is 2 % of the stress, elastic (nothing slips);
// the solve ratio 1e-7 of the forces is 5e-6 of the increment's, so rigid
// blocks are held to 1e-4 in the normal terms (measured round-off). In
// shear the slabs' end tractions turn each slab a little against its
// neighbours' contacts: measured 1.0e-4 and 2.6e-4 of 1/(k_s s), held to
// 1e-3 (1e-8 as solve ratio does not come to rest: the round-off of the
// prestressed contact forces). Zoned blocks of 0.25 m (two zones across a
// 0.5 m slab) to 1 % (measured 0.74 % across the set, 0.02 % in shear: the
// contacts sit at the zones' nodes).
TEST(RevStress, TheComplianceOfASetIsItsJointsAndBlocksInSeries) {
  constexpr double kE = 50e9, kNu = 0.25, kIncrement = 1e5, kShearStiffness = 30e9;
  const double joints = 1 / (kNormalStiffness * 0.5);
  const double joints_shear = 1 / (kShearStiffness * 0.5);
  for (const double angle : {0.0, 90.0}) {  // sigma_1 along the set, then across it
    SCOPED_TRACE(angle);
    const int across = angle == 90 ? 0 : 1, along = 1 - across;  // square axes
    const auto rigid =
        solve(rock_mass({0}, coulomb(30)), {principal_state(5e6, 2e6, angle)}, kIncrement);
    const Eigen::Matrix3d c = rigid[0].rev.domains[0].mechanics.compliance;
    EXPECT_NEAR(c(across, across), joints, 1e-4 * joints);
    EXPECT_LT(std::abs(c(along, along)), 1e-4 * joints);
    EXPECT_LT(std::abs(c(0, 1)) + std::abs(c(1, 0)), 1e-4 * joints);
    EXPECT_NEAR(c(2, 2), joints_shear, 1e-3 * joints_shear);
    EXPECT_LT(c.row(2).head<2>().cwiseAbs().sum() + c.col(2).head<2>().cwiseAbs().sum(),
              1e-4 * joints_shear);

    const auto zoned = solve(rock_mass({0}, coulomb(30), "{solve_ratio: 1e-7, zone_size: 0.25 m}"),
                             {principal_state(5e6, 2e6, angle)}, kIncrement);
    const Eigen::Matrix3d z = zoned[0].rev.domains[0].mechanics.compliance;
    const double rock = (1 - kNu * kNu) / kE, rock_shear = 2 * (1 + kNu) / kE;
    EXPECT_NEAR(z(across, across), rock + joints, 1e-2 * (rock + joints));
    EXPECT_NEAR(z(along, along), rock, 1e-2 * rock);
    EXPECT_NEAR(-z(across, along) / z(along, along), kNu / (1 - kNu), 1e-2);
    EXPECT_NEAR(z(2, 2), rock_shear + joints_shear, 1e-2 * (rock_shear + joints_shear));
  }
}

TEST(RevStress, SquaresThatFindNoRestHaveNoPermeability) {
  // The DFN of configs/rev_stress_rock.yaml at sigma_1 / sigma_3 = 4, past
  // the critical ratio 3 of its best oriented joints: the fractures slide
  // along through-going paths (a mechanism under stress control), the
  // blocks do not come to rest in 300 cycles, and the square is reported
  // as not at rest and not connected, with no tensor (not the permeability
  // of a rock mass in motion).
  const auto scene = std::make_shared<const Scene>(
      read_scene(std::filesystem::path(FISSURE_SOURCE_DIR) / "configs" / "rev_stress_rock.yaml"));
  Scene limited = *scene;
  section_settings(limited, dem::kDemSettings).max_cycles = 300;
  flow::RevStudyConfig study;
  study.sizes = {6};
  study.realizations = 1;
  study.rotations = 1;
  StressStudyConfig config;
  config.states = {principal_state(20e6, 5e6), principal_state(6.5e6, 5e6)};
  const SceneRockMassSource source(std::make_shared<const Scene>(limited), Vec2::Zero());
  const auto results = run_stress_study(study, config, source, {});
  const flow::DomainResult& sliding = results[0].rev.domains[0];
  EXPECT_FALSE(sliding.mechanics.equilibrium);
  EXPECT_FALSE(sliding.connected);
  EXPECT_EQ(sliding.k.norm(), 0);
  EXPECT_GT(sliding.mechanics.slip_fraction, 0.02);
  EXPECT_EQ(results[0].rev.sizes[0].samples, 0);
  EXPECT_FALSE(results[0].rev.rev_size.has_value());
  // Below the critical ratio the same square comes to rest, connected.
  const flow::DomainResult& resting = results[1].rev.domains[0];
  EXPECT_TRUE(resting.mechanics.equilibrium);
  EXPECT_TRUE(resting.connected);
  EXPECT_GT(resting.k.norm(), 0);
}

TEST(RevStress, WithoutStressTheStudyIsTheGeometricOne) {
  // A stochastic DFN (two families): at zero stress the cut blocks' network
  // carries the traces' own apertures, as the geometric study's.
  const std::string yaml =
      "name: rock\nphysics: [dem]\nmaterials:\n"
      "  - {name: granite, density: 2650, young_modulus: 50 GPa, poisson_ratio: 0.25}\n"
      "joints:\n  - " +
      coulomb(30) +
      "\nrock_mass:\n  domain: [[-10, -10], [10, -10], [10, 10], [-10, 10]]\n"
      "  material: granite\n  seed: 11\n  dfn:\n"
      "    - {name: a, density: {p21: 2 1/m}, orientation: {distribution: von_mises, mean: 20, "
      "kappa: 10}, length: {distribution: truncated_power_law, exponent: 1.5, min: 1 m, max: 8 "
      "m}, aperture: 80 um, joint: j}\n"
      "    - {name: b, density: {p21: 2 1/m}, orientation: {distribution: von_mises, mean: 110, "
      "kappa: 10}, length: {distribution: truncated_power_law, exponent: 1.5, min: 1 m, max: 8 "
      "m}, aperture: 60 um, joint: j}\n"
      "dem: {solve_ratio: 1e-7}\ntime: {end: 1}\n";
  const auto scene = std::make_shared<const Scene>(read_scene_text(yaml, "rock.yaml"));
  const SceneRockMassSource source(scene, Vec2::Zero());
  flow::RevStudyConfig study;
  study.sizes = {5};
  study.realizations = 2;
  study.rotations = 1;
  study.threads = 1;
  StressStudyConfig config;
  config.states = {StressState{}};
  const auto stressed = run_stress_study(study, config, source, {});
  const flow::RevStudyResult geometric = flow::run_rev_study(study, source);
  ASSERT_EQ(stressed[0].rev.domains.size(), geometric.domains.size());
  for (std::size_t d = 0; d < geometric.domains.size(); ++d) {
    SCOPED_TRACE(d);
    EXPECT_GT(geometric.domains[d].k.norm(), 0);
    expect_tensor_near(stressed[0].rev.domains[d].k, geometric.domains[d].k, 1e-6);
  }
}

}  // namespace
}  // namespace fissure
