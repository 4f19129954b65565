// verification.md (d): elastic block in uniaxial compression (Chang et al.'s
// marble specimen, W = 2.54 cm, H = 3.65 cm, E = 51.4 GPa, nu = 0.17,
// sigma = 10 MPa as two point loads at the top corners). The supports (one
// corner fixed in x and y, the other in y) are statically determinate, so the
// reactions, and with them the constant strain, do not depend on the fixed
// points' penalty. One static step (k01 = 0) with dt = 1 s leaves an inertia
// term 2M/dt^2 about 1e-17 of the elastic stiffness: the small-strain answer
// is reproduced to round-off, and the tolerances of the issue (strain 1e-6
// relative) and of verification.md (stress 1e-8) hold with margin.
#include <gtest/gtest.h>

#include "mechanics/dda/dda_settings.h"
#include "tests/support/dda_scenes.h"
#include "tests/support/run_scene.h"

namespace fissure::testing {
namespace {

constexpr double kW = 0.0254, kH = 0.0365, kE = 5.14e10, kNu = 0.17, kSigma = 10e6;

Scene specimen(PlaneMode plane) {
  Scene s = base_scene(kE, 30, 0.0);
  s.materials[0].poisson_ratio = kNu;
  mechanics_controls(s).plane = plane;
  s.blocks.push_back(block("specimen", rectangle(kW, kH)));
  s.fixed_points.push_back({Vec2(0, 0), 0, true, true});
  s.fixed_points.push_back({Vec2(kW, 0), 0, false, true});
  for (const double x : {0.0, kW}) {
    PointLoad load;
    load.point = Vec2(x, kH);
    load.block = 0;
    load.force = Vec2(0, -kSigma * kW / 2);
    s.point_loads.push_back(load);
  }
  mechanics_controls(s).dda.velocity_carry_over = 0;
  mechanics_controls(s).dda.max_time_step = 1.0;
  mechanics_controls(s).dda.max_displacement_ratio = 0.5;
  s.time.end_time = 1.0;
  return s;
}

TEST(DdaUniaxialCompression, PlaneStress) {
  const RunResult r = run_scene(specimen(PlaneMode::Stress), "dda_uniaxial_stress");
  ASSERT_EQ(r.summary.status, "completed") << r.summary.message;
  const Block& b = r.state.blocks[0];
  const double ey = -kSigma / kE, ex = kNu * kSigma / kE;  // -1.94553e-4, 3.30739e-5
  EXPECT_NEAR(b.strain(1), ey, 1e-6 * std::abs(ey));
  EXPECT_NEAR(b.strain(0), ex, 1e-6 * std::abs(ex));
  EXPECT_NEAR(b.strain(2), 0, 1e-6 * std::abs(ex));
  EXPECT_NEAR(b.stress(1), -kSigma, 1e-8 * kSigma);
  EXPECT_NEAR(b.stress(0), 0, 1e-8 * kSigma);
  EXPECT_NEAR(b.stress(2), 0, 1e-8 * kSigma);
}

TEST(DdaUniaxialCompression, PlaneStrain) {
  const RunResult r = run_scene(specimen(PlaneMode::Strain), "dda_uniaxial_strain");
  ASSERT_EQ(r.summary.status, "completed") << r.summary.message;
  const Block& b = r.state.blocks[0];
  const double ey = -kSigma * (1 - kNu * kNu) / kE;  // -1.88930e-4
  const double ex = kNu * (1 + kNu) * kSigma / kE;   // 3.86965e-5
  EXPECT_NEAR(b.strain(1), ey, 1e-6 * std::abs(ey));
  EXPECT_NEAR(b.strain(0), ex, 1e-6 * std::abs(ex));
  EXPECT_NEAR(b.stress(1), -kSigma, 1e-8 * kSigma);
  EXPECT_NEAR(b.stress(0), 0, 1e-8 * kSigma);
}

}  // namespace
}  // namespace fissure::testing
