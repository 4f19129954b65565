// verification.md (x), docs/dda.md section 10: viscous boundaries and
// free-field input in dynamic DDA. A layer of glued blocks, far wider than
// tall so that it shears as a 1D layer, stands on a viscous base that
// replaces the half-space below; the outcrop velocity enters through it.
//  * A shear pulse goes up, doubles at the free surface and leaves through
//    the base: what stays in the layer is the reflected energy.
//  * A harmonic input gives the surface/outcrop amplification of an elastic
//    layer on an elastic half-space (Kramer 1996, eq. 7.36):
//      |A| = 1 / sqrt(cos^2(k H) + alpha^2 sin^2(k H)),
//    alpha = rho_s v_s / (rho_r v_r), k = omega / v_s.
// The layer's blocks meet at two corner contacts per joint: the penalty
// springs add W / (2 p) of compliance to each block's h / G, so waves run at
// c_eff = c_s / sqrt(1 + G W / (2 p h)) (4.7 % below c_s in the pulse's
// layer, 0.25 % in the soft layer).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "tests/support/dynamic_scenes.h"
#include "tests/support/results_file_reader.h"
#include "tests/support/run_scene.h"

namespace fissure::testing {
namespace {

constexpr double kPi = std::numbers::pi;

double shear_modulus(double e, double nu) {
  return e / (2 * (1 + nu));
}

/// The wave speed of the glued layer: blocks and their joints' springs in series.
double layer_wave_speed(const LayerSpec& s) {
  const double g = shear_modulus(s.soil_modulus, s.poisson_ratio);
  const double h = s.height / s.layers;
  return shear_wave_speed(s.soil_modulus, s.poisson_ratio, s.density) /
         std::sqrt(1 + g * s.width / (2 * s.penalty * h));
}

TEST(DdaViscousBoundary, AShearPulseLeavesThroughTheBase) {
  // A sin^2 pulse of incident velocity v_in = 0.05 m/s over T = 0.1 s (a
  // wavelength of 12 layer thicknesses); outcrop velocity 2 v_in.
  const LayerSpec spec;
  const double v_in = 0.05, pulse = 0.1;
  MotionSamples outcrop;
  for (int k = 0; k <= 1000; ++k) {
    const double t = pulse * k / 1000;
    outcrop.t.push_back(t);
    outcrop.x.push_back(2 * v_in * std::pow(std::sin(kPi * t / pulse), 2));
  }
  outcrop.t.push_back(spec.end);
  outcrop.x.push_back(0);
  const RunResult r = run_scene(layer_on_viscous_base(spec, outcrop, scratch_dir("dda_pulse")),
                                "dda_viscous_pulse");
  ASSERT_EQ(r.summary.status, "completed") << r.summary.message;
  auto m = test::monitor_columns(r.outdir);
  const std::vector<double>& t = m["t"];
  const std::vector<double>& top = m["top.vx"];
  const auto peak = std::max_element(top.begin(), top.end());

  // The free surface doubles the incident wave (the layer's impedance is
  // the base's within the joints' 5 %, which transmits 1 % more).
  EXPECT_NEAR(*peak, 2 * v_in, 0.03 * 2 * v_in);
  // ... when the pulse's middle has crossed the layer at c_eff (the output
  // interval, 0.5 ms, is 0.6 % of the travel time).
  const double arrival = pulse / 2 + spec.height / layer_wave_speed(spec);
  EXPECT_NEAR(t[peak - top.begin()], arrival, 0.01 * arrival);

  // Reflected energy: what is left in the layer once the pulse has come
  // down and out again, against the incident pulse's energy flux
  // W rho c_s int v_in^2 dt = W rho c_s v_in^2 3 T / 8.
  const double c = shear_wave_speed(spec.bedrock_modulus, spec.poisson_ratio, spec.density);
  const double incident = spec.width * spec.density * c * v_in * v_in * 3 * pulse / 8;
  ASSERT_LT(pulse + 2 * spec.height / layer_wave_speed(spec), 0.9 * spec.end);
  const nlohmann::json& e = r.summary.energy;
  const double left =
      e["kinetic"].get<double>() + e["strain"].get<double>() + e["contact_springs"].get<double>();
  EXPECT_LT(left, 0.05 * incident) << "incident " << incident << " J/m";
  std::printf(
      "surface peak %.5f m/s (2 v_in %.3f), at %.5f s (c_eff: %.5f s), left %.3g of "
      "the incident energy\n",
      *peak, 2 * v_in, t[peak - top.begin()], arrival, left / incident);
  // The boundary took in the pulse and gave it back: its net work is what
  // stayed, and what the scheme's numerical damping (Newmark gamma = 1)
  // took on the way (1.1 % of the incident energy).
  EXPECT_NEAR(-e["boundary_dissipation"].get<double>(), left, 0.02 * incident);
}

struct Amplification {
  double kh;         ///< omega H / v_s
  double tolerance;  ///< relative
};

class DdaLayerAmplification : public ::testing::TestWithParam<Amplification> {};

TEST_P(DdaLayerAmplification, MatchesTheLayerOnAHalfSpace) {
  // A soft layer (E 1 GPa, v_s 385 m/s) on rock ten times stiffer: alpha =
  // 0.316, resonance (k H = pi / 2) at 0.96 Hz with |A| = 1 / alpha = 3.16.
  LayerSpec spec;
  spec.layers = 25;
  spec.soil_modulus = 1e9;
  spec.time_step = 1e-3;
  const double vs = shear_wave_speed(spec.soil_modulus, spec.poisson_ratio, spec.density);
  const double omega = GetParam().kh * vs / spec.height, period = 2 * kPi / omega;
  const int periods = 10;  // radiation damps the start within 3-4 periods
  spec.end = periods * period;
  spec.output_interval = period / 100;
  // v_out = V sin(omega t), switched on smoothly over two periods.
  const double v = 0.01;
  MotionSamples outcrop;
  for (int k = 0; k <= periods * 200; ++k) {
    const double t = period * k / 200, s = std::min(1.0, t / (2 * period));
    outcrop.t.push_back(t);
    outcrop.x.push_back(v * s * s * (3 - 2 * s) * std::sin(omega * t));
  }
  const RunResult r = run_scene(layer_on_viscous_base(spec, outcrop, scratch_dir("dda_layer")),
                                "dda_layer_amplification");
  ASSERT_EQ(r.summary.status, "completed") << r.summary.message;
  auto m = test::monitor_columns(r.outdir);
  double high = -1e300, low = 1e300;
  for (std::size_t i = 0; i < m["t"].size(); ++i)
    if (m["t"][i] > (periods - 3) * period) {
      high = std::max(high, m["top.vx"][i]);
      low = std::min(low, m["top.vx"][i]);
    }
  const double measured = (high - low) / 2 / v;
  const double alpha = std::sqrt(spec.soil_modulus / spec.bedrock_modulus);  // same density
  const double kh = GetParam().kh;
  const double exact =
      1 / std::sqrt(std::pow(std::cos(kh), 2) + alpha * alpha * std::pow(std::sin(kh), 2));
  EXPECT_NEAR(measured, exact, GetParam().tolerance * exact) << "k H = " << kh;
  std::printf("k H = %.4f: |A| = %.5f, closed form %.5f (%+.2f %%)\n", kh, measured, exact,
              100 * (measured / exact - 1));
}

// Off resonance the amplification is flat in frequency and the layer's
// 0.25 % slower waves (its joints) move it little; at resonance the peak is
// sharp: the slower waves detune it, and the scheme's numerical damping
// (Newmark gamma = 1: a damping ratio of about omega dt / 4 = 0.15 %) and the
// sampling of the peak (0.05 %) lower it.
INSTANTIATE_TEST_SUITE_P(Frequencies, DdaLayerAmplification,
                         ::testing::Values(Amplification{kPi / 4, 0.01},
                                           Amplification{kPi / 2, 0.05},
                                           Amplification{3 * kPi / 4, 0.03}));

}  // namespace
}  // namespace fissure::testing
