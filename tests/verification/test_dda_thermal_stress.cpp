// verification.md (m): thermal stress of a confined block in DDA (theory.md
// 4.3). Masada dolomite, E = 43 GPa, nu = 0.184, alpha_T = 1e-5 1/K, a
// temperature rise of dT = 20 K, a 1 m x 1 m block without gravity. The
// free thermal strain alpha_T dT is set on the state's field
// block_thermal_strain (rockmass/fields/block_thermal_strain.h) as the
// thermal process would write it (it owns alpha_T), ramped in four steps of
// 5 K and held for two more; static DDA (k01 = 0) at
// dt = 1 s, where the inertia term 2M/dt^2 is ~1e-8 of the block's
// stiffness, so the held steps settle the block to round-off.
//
// Frictionless confinement by penalty rollers: fixed points held in x only
// (or in y only) at the block's corners, which leave the other direction
// free. A roller of stiffness p yields by F/p, so the block's strain along a
// held direction is off by about M * 1 m / p of the thermal strain, M the
// block's constrained modulus (E / (1 - nu) = 1.23 E in plane stress,
// E / ((1 + nu)(1 - 2 nu)) = 1.34 E in plane strain, both directions held):
//  * penalty walls, the catalogue's p >= 1e3 E * 1 m with tolerance 1e-3: at
//    p = 1e3 E the stresses are off by 1.2e-3 to 1.3e-3 (M / p, measured), so
//    the walls here are p = 1e4 E * 1 m (errors ~1.3e-4);
//  * p = 1e7 E * 1 m (4.3e17 N/m, below the scenes' largest stiffness,
//    1e18 N/m): the roller error is ~1e-7, the rollers are ideal constraints
//    to the catalogue's 1e-6 (round-off in the 6 x 6 solve with springs 1e7
//    times the block's stiffness is ~1e-16 * 1e7 = 1e-9).
// The free in-plane row has no constraint at all (1e-6). The out-of-plane
// stress of plane strain, which the DDA does not store, follows from the
// in-plane stresses as sigma_z = nu (sigma_x + sigma_y) - E alpha_T dT.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/io/checkpoint.h"
#include "core/io/hdf5_file.h"
#include "mechanics/dda/dda_process.h"
#include "mechanics/dda/dda_settings.h"
#include "rockmass/fields/block_thermal_strain.h"
#include "tests/support/dda_scenes.h"
#include "tests/support/run_scene.h"

namespace fissure::testing {
namespace {

constexpr double kE = 43e9, kNu = 0.184, kAlpha = 1e-5, kDeltaT = 20;
constexpr double kFree = kAlpha * kDeltaT;  // alpha_T dT = 2e-4
constexpr int kRampSteps = 4, kHeldSteps = 2;

enum class Held { XY, X, None };

struct Confinement {
  PlaneMode plane;
  Held held;
};

Scene confined_block(const Confinement& c, double penalty_factor) {
  Scene s = base_scene(kE, 30, 0.0);
  s.materials[0].poisson_ratio = kNu;
  mechanics_controls(s).plane = c.plane;
  s.blocks.push_back(block("block", rectangle(1, 1)));
  // Rollers at the four corners: x held on the left and right sides, y on
  // the bottom and top (each fixed point holds one direction only).
  for (const Vec2& corner : {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)}) {
    if (c.held == Held::None) break;
    s.fixed_points.push_back({corner, 0, true, c.held == Held::XY});
  }
  auto& dda = mechanics_controls(s).dda;
  dda.penalty = penalty_factor * kE * 1.0;
  dda.velocity_carry_over = 0;
  dda.max_time_step = 1.0;
  s.time.end_time = kRampSteps + kHeldSteps;
  return s;
}

struct Heated {
  Block block;
  nlohmann::json energy;
  double worst_energy_gain = 0;  ///< largest rise of the total energy in a step (J)
};

/// The field block_thermal_strain of a block heated by dT: alpha_T dT.
void set_heating(RockMass& state, double dT) {
  state.fields.get_or_add(kBlockThermalStrain) = {kAlpha * dT};
}

/// Heats the block by dT (the field block_thermal_strain = alpha_T dT),
/// step by step, and checks that every step is accepted.
Heated heat(const Scene& s) {
  RockMass state = RockMass::from_scene(s);
  dda::DdaProcess dda(s);
  dda.initialize(state);
  double total = dda.energy(state)["total"];
  Heated h;
  for (int step = 0; step < kRampSteps + kHeldSteps; ++step) {
    const double dT = kDeltaT * std::min(1.0, (step + 1.0) / kRampSteps);
    set_heating(state, dT);
    const StepReport r = dda.advance(state, step, 1.0);
    EXPECT_EQ(r.status, StepReport::Status::Ok) << "step " << step << ": " << r.reason;
    const double now = dda.energy(state)["total"];
    h.worst_energy_gain = std::max(h.worst_energy_gain, now - total);
    total = now;
  }
  h.block = state.blocks[0];
  h.energy = dda.energy(state);
  return h;
}

/// Stress scale of the problem: E alpha_T dT = 8.6 MPa.
constexpr double kStressScale = kE * kFree;

void expect_stress(const Block& b, double sx, double sy, double tolerance) {
  // The measured errors, in units of E alpha_T dT (docs/dda.md, "Thermal strain").
  std::printf("stress errors / (E alpha dT): %.2e %.2e %.2e\n", (b.stress(0) - sx) / kStressScale,
              (b.stress(1) - sy) / kStressScale, b.stress(2) / kStressScale);
  EXPECT_NEAR(b.stress(0), sx, tolerance * kStressScale);
  EXPECT_NEAR(b.stress(1), sy, tolerance * kStressScale);
  EXPECT_NEAR(b.stress(2), 0, tolerance * kStressScale);
}

/// Out-of-plane stress of plane strain (epsilon_z = 0 with the free thermal strain).
double plane_strain_sigma_z(const Block& b) {
  return kNu * (b.stress(0) + b.stress(1)) - kE * kFree;
}

/// The energy ledger: heating does work on the block (thermal_work, J per
/// unit thickness) that the strain energy and the rollers' springs store, or
/// the static steps dissipate; the total never rises.
/// The ledger's strain energy uses the block's end-of-step area, its step
/// the start-of-step area: a step may show a gain of the relative area change
/// times the energy, bounded by (|eps_x| + |eps_y|) W.
void expect_energy_accounted(const Heated& h) {
  const double w = h.energy["thermal_work"];
  std::printf(
      "energy (J/m): thermal work %.6g, strain %.6g, springs %.3g, total %.3g, largest "
      "gain in a step %.3g\n",
      w, h.energy["strain"].get<double>(), h.energy["fixed_point_springs"].get<double>(),
      h.energy["total"].get<double>(), h.worst_energy_gain);
  EXPECT_GT(w, 0);
  const double allowance = (std::abs(h.block.strain(0)) + std::abs(h.block.strain(1)) + 1e-12) * w;
  EXPECT_LE(h.worst_energy_gain, allowance);
  EXPECT_LE(h.energy["total"].get<double>(), allowance);
}

/// The catalogue's tolerance for rollers of p = factor x E x 1 m: 1e-3 for
/// penalty walls (p >= 1e3 E), 1e-6 once the roller error M / p is ~1e-7.
double tolerance_of(double penalty_factor) {
  return penalty_factor < 1e7 ? 1e-3 : 1e-6;
}

class ConfinedThermalStress : public ::testing::TestWithParam<double> {};

// Plane strain, fixed in x and y: sigma_x = sigma_y = sigma_z = -E alpha dT / (1 - 2 nu).
TEST_P(ConfinedThermalStress, PlaneStrainFixedInXAndY) {
  const double tolerance = tolerance_of(GetParam());
  const Heated h = heat(confined_block({PlaneMode::Strain, Held::XY}, GetParam()));
  const double s = -kE * kFree / (1 - 2 * kNu);  // -13.608 MPa
  EXPECT_NEAR(s, -13.608e6, 1e3);
  expect_stress(h.block, s, s, tolerance);
  EXPECT_NEAR(plane_strain_sigma_z(h.block), s, tolerance * kStressScale);
  expect_energy_accounted(h);
  // Confined: all the work is stored in the strain energy (and the springs).
  EXPECT_NEAR(h.energy["strain"].get<double>(), h.energy["thermal_work"].get<double>(),
              2 * tolerance * h.energy["thermal_work"].get<double>());
}

// Plane strain, fixed x, free y: sigma_x = sigma_z = -E alpha dT / (1 - nu),
// epsilon_y = (1 + nu) / (1 - nu) alpha dT.
TEST_P(ConfinedThermalStress, PlaneStrainFixedXFreeY) {
  const double tolerance = tolerance_of(GetParam());
  const Heated h = heat(confined_block({PlaneMode::Strain, Held::X}, GetParam()));
  const double s = -kE * kFree / (1 - kNu);  // -10.539 MPa
  EXPECT_NEAR(s, -10.539e6, 1e3);
  expect_stress(h.block, s, 0, tolerance);
  EXPECT_NEAR(plane_strain_sigma_z(h.block), s, tolerance * kStressScale);
  const double ey = (1 + kNu) / (1 - kNu) * kFree;  // 2.902e-4
  EXPECT_NEAR(h.block.strain(1), ey, tolerance * ey);
  EXPECT_NEAR(h.block.strain(0), 0, tolerance * ey);
  expect_energy_accounted(h);
}

// Plane stress, fixed in x and y: sigma_x = sigma_y = -E alpha dT / (1 - nu).
TEST_P(ConfinedThermalStress, PlaneStressFixedInXAndY) {
  const double tolerance = tolerance_of(GetParam());
  const Heated h = heat(confined_block({PlaneMode::Stress, Held::XY}, GetParam()));
  const double s = -kE * kFree / (1 - kNu);  // -10.539 MPa
  expect_stress(h.block, s, s, tolerance);
  expect_energy_accounted(h);
}

// Plane stress, fixed x, free y: sigma_x = -E alpha dT, epsilon_y = (1 + nu) alpha dT.
TEST_P(ConfinedThermalStress, PlaneStressFixedXFreeY) {
  const double tolerance = tolerance_of(GetParam());
  const Heated h = heat(confined_block({PlaneMode::Stress, Held::X}, GetParam()));
  const double s = -kE * kFree;  // -8.600 MPa
  EXPECT_NEAR(s, -8.6e6, 1e3);
  expect_stress(h.block, s, 0, tolerance);
  const double ey = (1 + kNu) * kFree;
  EXPECT_NEAR(h.block.strain(1), ey, tolerance * ey);
  expect_energy_accounted(h);
}

INSTANTIATE_TEST_SUITE_P(Rollers, ConfinedThermalStress, ::testing::Values(1e4, 1e7),
                         [](const auto& info) {
                           return info.param < 1e6 ? "PenaltyWalls1e4E" : "IdealRollers1e7E";
                         });

// Plane strain, free in-plane (no constraint): epsilon_x = epsilon_y =
// (1 + nu) alpha dT = 2.368e-4, no in-plane stress, sigma_z = -E alpha dT.
TEST(DdaThermalStrain, PlaneStrainFreeInPlane) {
  const Heated h = heat(confined_block({PlaneMode::Strain, Held::None}, 50));
  const double e = (1 + kNu) * kFree;
  EXPECT_NEAR(e, 2.368e-4, 1e-7);
  EXPECT_NEAR(h.block.strain(0), e, 1e-6 * e);
  EXPECT_NEAR(h.block.strain(1), e, 1e-6 * e);
  EXPECT_NEAR(h.block.strain(2), 0, 1e-6 * e);
  expect_stress(h.block, 0, 0, 1e-6);
  EXPECT_NEAR(plane_strain_sigma_z(h.block), -8.6e6, 1e-6 * kStressScale);
  // The geometry compounds each step's strain, the block's strain is their
  // sum (small strain): the area differs from (1 + e)^2 at second order.
  EXPECT_NEAR(h.block.section.area, (1 + e) * (1 + e), e * e);
  // Free expansion stores nothing: what the steps' temperature jumps put in
  // is dissipated by the static steps.
  EXPECT_LT(h.energy["strain"].get<double>(), 1e-6 * h.energy["thermal_work"].get<double>());
  expect_energy_accounted(h);
}

// The mechanics catches up with a thermal strain field that changed while it
// did not step (a sub-cycled thermal process): one jump of 20 K applied in
// one step gives the same end state as the ramp; and a temperature that
// returns to zero leaves the confined block stress-free.
TEST(DdaThermalStrain, AppliesOnlyTheChangeSinceItsLastStep) {
  const Scene s = confined_block({PlaneMode::Stress, Held::XY}, 1e7);
  RockMass state = RockMass::from_scene(s);
  dda::DdaProcess dda(s);
  dda.initialize(state);
  const double s_ref = -kE * kFree / (1 - kNu);
  const auto step_at = [&](double dT, int step) {
    set_heating(state, dT);
    ASSERT_EQ(dda.advance(state, step, 1.0).status, StepReport::Status::Ok);
  };
  for (int step = 0; step < 3; ++step) step_at(kDeltaT, step);
  expect_stress(state.blocks[0], s_ref, s_ref, 1e-6);
  for (int step = 3; step < 6; ++step) step_at(0, step);
  expect_stress(state.blocks[0], 0, 0, 1e-6);
}

// The applied thermal strain and the thermal work are the DDA's inner
// state: a run restored from a checkpoint taken between two temperature
// changes continues to the same bits as the uninterrupted one.
TEST(DdaThermalStrain, ACheckpointKeepsTheAppliedThermalStrain) {
  const Scene s = confined_block({PlaneMode::Stress, Held::XY}, 1e4);
  RockMass state = RockMass::from_scene(s);
  dda::DdaProcess dda(s);
  dda.initialize(state);
  const auto step = [](dda::DdaProcess& p, RockMass& m, double dT, int n) {
    set_heating(m, dT);
    ASSERT_EQ(p.advance(m, n, 1.0).status, StepReport::Status::Ok);
  };
  step(dda, state, 10, 0);
  step(dda, state, 10, 1);
  const std::string file = scratch_dir("dda_thermal_checkpoint") + "/checkpoint.h5";
  {
    Hdf5File h5(file, Hdf5File::Mode::Create);
    CheckpointWriter out(h5, h5.root());
    dda.save(out, state);
    h5.flush();
  }
  RockMass restored_state = state;
  dda::DdaProcess restored(s);
  restored.initialize(restored_state);
  {
    Hdf5File h5(file, Hdf5File::Mode::Read);
    CheckpointReader in(h5, h5.root());
    restored.restore(in, restored_state);
  }
  for (int n = 2; n < 4; ++n) {
    step(dda, state, 20, n);
    step(restored, restored_state, 20, n);
  }
  EXPECT_EQ(restored_state.blocks[0].stress, state.blocks[0].stress);
  EXPECT_EQ(restored_state.blocks[0].strain, state.blocks[0].strain);
  EXPECT_EQ(restored.energy(restored_state)["thermal_work"], dda.energy(state)["thermal_work"]);
  // Without the restored state the fresh process would apply the whole 20 K again.
  const double s_ref = -kE * kFree / (1 - kNu);
  EXPECT_NEAR(state.blocks[0].stress(0), s_ref, 1e-3 * kStressScale);
}

// Without the field nothing changes: no thermal strain, and the energy has
// no thermal term.
TEST(DdaThermalStrain, NoFieldNoThermalStrain) {
  const Scene s = confined_block({PlaneMode::Stress, Held::XY}, 1e3);
  RockMass state = RockMass::from_scene(s);
  dda::DdaProcess dda(s);
  dda.initialize(state);
  ASSERT_EQ(dda.advance(state, 0, 1.0).status, StepReport::Status::Ok);
  EXPECT_EQ(state.blocks[0].stress, Eigen::Vector3d::Zero());
  EXPECT_FALSE(dda.energy(state).contains("thermal_work"));
}

TEST(DdaThermalStrain, FieldOfTheWrongSizeIsAProgrammingError) {
  const Scene s = confined_block({PlaneMode::Stress, Held::XY}, 1e3);
  RockMass state = RockMass::from_scene(s);
  dda::DdaProcess dda(s);
  dda.initialize(state);
  state.fields.get_or_add(kBlockThermalStrain) = {1e-5, 2e-5};
  EXPECT_THROW(dda.advance(state, 0, 1.0), std::logic_error);
}

}  // namespace
}  // namespace fissure::testing
