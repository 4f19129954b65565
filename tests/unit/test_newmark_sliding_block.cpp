// The Newmark sliding block reference (tests/support/newmark_sliding_block.h) against closed
// forms (Newmark 1965; Kramer 1996, ch. 10) and against a plain fine-step integration, and the
// synthetic base motions it and the DDA's earthquake tests are driven with. The reference
// integrates the piecewise-linear record exactly, so the closed forms hold to rounding.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "tests/support/newmark_sliding_block.h"

namespace fissure::testing {
namespace {

constexpr double kG = 9.81;
constexpr double kDeg = std::numbers::pi / 180;
const Eigen::Vector2d kGravity(0, -kG);

/// Largest |a_i - b_i|.
double largest_difference(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double largest = 0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
    largest = std::max(largest, std::abs(a[i] - b[i]));
  return largest;
}

double largest_magnitude(const std::vector<double>& a) {
  double largest = 0;
  for (const double x : a) largest = std::max(largest, std::abs(x));
  return largest;
}

/// A deliberately plain second integrator of the same block, sharing nothing with the
/// reference but BaseAcceleration::at: fixed substeps h, the forces at the (rest of the)
/// substep's midpoint, the rate by the midpoint rule, the slip by the trapezoidal rule, a stop
/// where the rate's chord crosses 0, and the rest of that substep from there (a reversal).
/// Second order: h = 5e-6 s leaves a few 1e-11 m of the slips below (measured by halving h
/// down to 1.25e-6 s: the differences fall 4-fold per halving, towards the reference).
std::vector<double> fine_step_slip(const BaseAcceleration& base, const SlidingPlane& plane,
                                   double mu, double t_end, double dt_output, int substeps) {
  const double h = dt_output / substeps;
  const auto outputs = static_cast<int>(std::lround(t_end / dt_output));
  double slip = 0, rate = 0;
  std::vector<double> history{0};
  for (int k = 0; k < outputs; ++k) {
    for (int j = 0; j < substeps; ++j) {
      const double t = (static_cast<double>(k) * substeps + j) * h;
      double left = h;
      while (left > 0) {
        const Eigen::Vector2d felt = kGravity - base.at(t + h - left / 2);
        const double driving = felt.dot(plane.tangent), normal = -felt.dot(plane.normal);
        double direction = rate > 0 ? 1 : rate < 0 ? -1 : 0;
        if (direction == 0) {
          if (std::abs(driving) <= mu * normal) break;  // stuck
          direction = driving > 0 ? 1 : -1;
        }
        const double new_rate = rate + (driving - direction * mu * normal) * left;
        if (direction * new_rate > 0) {
          slip += (rate + new_rate) / 2 * left;
          rate = new_rate;
          break;
        }
        const double part = rate / (rate - new_rate);
        slip += rate * part * left / 2;
        rate = 0;
        left *= 1 - part;
        if (part == 0) break;  // started and stopped at once: stuck
      }
    }
    history.push_back(slip);
  }
  return history;
}

TEST(NewmarkSlidingBlock, BaseAccelerationIsPiecewiseLinearWithJumpsAndZeroOutside) {
  const BaseAcceleration base{{0.5, 1.5, 2.0, 2.0}, {2, 4, 4, -1}, {0, -2, -2, 3}};
  EXPECT_EQ(base.at(0.4), Eigen::Vector2d(0, 0));
  EXPECT_EQ(base.at(0.5), Eigen::Vector2d(2, 0));
  EXPECT_EQ(base.at(1.0), Eigen::Vector2d(3, -1));
  EXPECT_EQ(base.at(1.75), Eigen::Vector2d(4, -2));
  EXPECT_EQ(base.at(2.0), Eigen::Vector2d(-1, 3));  // a jump: the value after it
  EXPECT_EQ(base.at(2.0000001), Eigen::Vector2d(0, 0));
}

// A rectangular pulse A for t0 on a horizontal plane (Newmark 1965; Kramer 1996, ch. 10).
// In the base's frame the block feels -A, resisted by mu g: it slides back at A - mu g,
// to s1 = (A - mu g) t0^2 / 2 with rate V1 = (A - mu g) t0; then it decelerates at mu g
// for V1 / (mu g), another V1^2 / (2 mu g). In total
//   (A - mu g) t0^2 / (2 mu g) (mu g + A - mu g) = V^2 / (2 mu g) (1 - mu g / A),  V = A t0,
// stopping at t = A t0 / (mu g).
TEST(NewmarkSlidingBlock, RectangularPulseOnAHorizontalPlaneSlidesNewmarksDistance) {
  const double mu = 0.2, amplitude = 4, duration = 0.5, yield = mu * kG;
  const BaseAcceleration pulse{{0, duration, duration}, {amplitude, amplitude, 0}, {0, 0, 0}};
  const SlidingBlockHistory h = newmark_sliding_block(pulse, SlidingPlane{}, mu, kGravity, 2, 0.01);
  ASSERT_FALSE(h.lifted_off);
  ASSERT_EQ(h.t.size(), 201u);

  const double v = amplitude * duration;
  const double total = v * v / (2 * yield) * (1 - yield / amplitude);
  const double stop = amplitude * duration / yield;
  // The closed form at every output (the base moves towards +x: the block slips towards -x).
  std::vector<double> exact(h.t.size()), exact_rate(h.t.size());
  for (std::size_t i = 0; i < h.t.size(); ++i) {
    const double t = h.t[i], tau = t - duration;
    const double rate1 = (amplitude - yield) * duration;
    if (t <= duration) {
      exact[i] = -(amplitude - yield) * t * t / 2;
      exact_rate[i] = -(amplitude - yield) * t;
    } else if (t <= stop) {
      exact[i] =
          -((amplitude - yield) * duration * duration / 2 + rate1 * tau - yield * tau * tau / 2);
      exact_rate[i] = -(rate1 - yield * tau);
    } else {
      exact[i] = -total;
      exact_rate[i] = 0;
    }
  }
  // Exact but for rounding: a few hundred operations on numbers near 1 (1e-12 of the slip).
  const double slip_error = largest_difference(h.slip, exact) / total;
  const double rate_error = largest_difference(h.slip_rate, exact_rate) / v;
  std::printf("pulse: s = %.15f m (closed form %.15f), slip error %.1e, rate error %.1e\n",
              -h.slip.back(), total, slip_error, rate_error);
  EXPECT_LT(slip_error, 1e-12);
  EXPECT_LT(rate_error, 1e-12);
  // Stopped, not creeping: the rate is exactly 0 after the stop.
  for (std::size_t i = 0; i < h.t.size(); ++i) {
    if (h.t[i] > stop) {
      EXPECT_EQ(h.slip_rate[i], 0) << "t = " << h.t[i];
    }
  }
}

// A triangular pulse A (1 - t/t1) on a horizontal plane, from A at t = 0 (the same algebra): the
// block starts at once and slides back at A (1 - t/t1) - mu g, its rate
// -((A - mu g) t - A t^2 / (2 t1)) returning to 0 at t* = 2 (A - mu g) t1 / A. For A <= 2 mu g
// that is within the pulse: s = (A - mu g) t*^2 / 2 - A t*^3 / (6 t1). Otherwise it leaves the
// pulse at rate (A/2 - mu g) t1 after (A - mu g) t1^2 / 2 - A t1^2 / 6 and decelerates at mu g,
// another ((A/2 - mu g) t1)^2 / (2 mu g).
TEST(NewmarkSlidingBlock, TriangularPulseOnAHorizontalPlaneSlidesNewmarksDistance) {
  const double mu = 0.2, yield = mu * kG, t1 = 0.3;
  for (const double amplitude : {1.5 * yield, 3 * yield}) {
    const BaseAcceleration pulse{{0, t1}, {amplitude, 0}, {0, 0}};
    // Output at 0 and 1 s only: the start and the stop fall within one stretch of the record.
    const SlidingBlockHistory h = newmark_sliding_block(pulse, SlidingPlane{}, mu, kGravity, 1, 1);
    double exact = 0;
    if (amplitude <= 2 * yield) {
      const double stop = 2 * (amplitude - yield) * t1 / amplitude;
      exact = (amplitude - yield) * stop * stop / 2 - amplitude * stop * stop * stop / (6 * t1);
    } else {
      const double rate = (amplitude / 2 - yield) * t1;
      exact =
          (amplitude - yield) * t1 * t1 / 2 - amplitude * t1 * t1 / 6 + rate * rate / (2 * yield);
    }
    // Rounding only, as for the rectangular pulse.
    const double error = std::abs(-h.slip.back() - exact) / exact;
    std::printf("triangular pulse %.1f mu g: s = %.15f m (closed form %.15f), error %.1e\n",
                amplitude / yield, -h.slip.back(), exact, error);
    EXPECT_LT(error, 1e-12);
    EXPECT_EQ(h.slip_rate.back(), 0);
  }
}

// No base motion, tan(phi) < tan(alpha): s'' = g (sin a - cos a tan phi) from rest. With a
// steady upward base acceleration a_v the block feels g + a_v instead.
TEST(NewmarkSlidingBlock, InclineWithoutBaseMotionSlidesWithTheClosedForm) {
  const double slope = 30 * kDeg, mu = std::tan(20 * kDeg);
  const SlidingPlane plane = incline_rising_towards_x(slope);
  for (const double upwards : {0.0, 3.0}) {
    const BaseAcceleration base{{0, 2}, {0, 0}, {upwards, upwards}};
    const SlidingBlockHistory h = newmark_sliding_block(base, plane, mu, kGravity, 2, 0.05);
    const double a = (kG + upwards) * (std::sin(slope) - std::cos(slope) * mu);
    std::vector<double> exact;
    for (const double t : h.t) exact.push_back(a * t * t / 2);
    // A cubic through each output stretch: rounding only (1e-12 of the slip).
    const double error = largest_difference(h.slip, exact) / exact.back();
    std::printf("incline, base up %.0f m/s^2: s(2 s) = %.12f m, error %.1e\n", upwards,
                h.slip.back(), error);
    EXPECT_LT(error, 1e-12);
    EXPECT_NEAR(h.slip_rate.back(), 2 * a, 1e-12 * a);
  }
}

// The yield accelerations of a plane rising towards +x at alpha, horizontal base motion:
// downslope for a_h > g tan(phi - alpha), upslope for a_h < -g tan(phi + alpha) (Kramer 1996,
// ch. 10). Just below them nothing moves at all; just above (the check that the first could
// fail) the block slips.
TEST(NewmarkSlidingBlock, NoSlipBelowTheYieldAcceleration) {
  struct Case {
    double slope_deg, phi_deg;
  };
  for (const Case c : {Case{0, 16.7}, Case{20, 35}}) {
    const double slope = c.slope_deg * kDeg, phi = c.phi_deg * kDeg;
    const double yield = kG * std::tan(phi - slope);
    const SlidingPlane plane = incline_rising_towards_x(slope);
    for (const double ratio : {0.99, 1.01}) {
      const BaseAcceleration base = sinusoidal_base(ratio * yield, 2, 5, 0.0025);
      const SlidingBlockHistory h =
          newmark_sliding_block(base, plane, std::tan(phi), kGravity, 6, 0.01);
      if (ratio < 1) {
        EXPECT_EQ(largest_magnitude(h.slip), 0) << c.slope_deg;
        EXPECT_EQ(largest_magnitude(h.slip_rate), 0) << c.slope_deg;
      } else {
        // (On the horizontal plane it slips back as far in the other half-cycle.)
        EXPECT_GT(largest_magnitude(h.slip), 1e-6) << c.slope_deg;
        std::printf("alpha %.0f deg, 1.01 x yield: max |s| = %.3e m\n", c.slope_deg,
                    largest_magnitude(h.slip));
      }
    }
  }
}

TEST(NewmarkSlidingBlock, SyntheticAccelerogramIsDeterministicStartsAtZeroAndPeaksAtPga) {
  const double duration = 20, dt = 0.005, pga = 3.0;
  const BaseAcceleration a = synthetic_accelerogram(duration, dt, pga, 42);
  const BaseAcceleration same = synthetic_accelerogram(duration, dt, pga, 42);
  const BaseAcceleration other = synthetic_accelerogram(duration, dt, pga, 43);
  EXPECT_EQ(a.t, same.t);
  EXPECT_EQ(a.ax, same.ax);  // to the bit
  EXPECT_NE(a.ax, other.ax);

  ASSERT_EQ(a.t.size(), 4001u);
  for (std::size_t k = 0; k < a.t.size(); ++k) ASSERT_EQ(a.t[k], k * dt);
  EXPECT_EQ(a.ax.front(), 0);
  EXPECT_EQ(a.ax.back(), 0);
  EXPECT_EQ(largest_magnitude(a.ax), pga);
  EXPECT_EQ(largest_magnitude(a.ay), 0);

  // Recorded-like, not white: white noise at 200 samples/s crosses 0 about 100 times a second,
  // a 2.5 Hz sine 5 times; the filtered record about 9 (8.3 to 9.1 for seeds 1 to 10, with
  // peak velocities of 0.26 to 0.50 m/s: 0.09 to 0.17 s times the pga, as on firm ground).
  int crossings = 0;
  for (std::size_t k = 1; k < a.ax.size(); ++k) crossings += (a.ax[k - 1] < 0) != (a.ax[k] < 0);
  const double rate = crossings / duration;
  std::printf("synthetic: %.2f zero crossings per second\n", rate);
  EXPECT_GT(rate, 5);
  EXPECT_LT(rate, 13);

  // Along a direction: the peak |a| is pga (the components rounded once each).
  const BaseAcceleration oblique = synthetic_accelerogram(duration, dt, pga, 42, {3, 4});
  double peak = 0;
  for (std::size_t k = 0; k < oblique.t.size(); ++k)
    peak = std::max(peak, std::hypot(oblique.ax[k], oblique.ay[k]));
  EXPECT_NEAR(peak, pga, 4e-16 * pga);
}

// A sinusoid between the two yield accelerations (g tan 15 deg = 2.6, g tan 55 deg = 14.0
// m/s^2): the block slips downslope in each cycle and never back.
TEST(NewmarkSlidingBlock, SinusoidOnAnInclineSlipsDownslopeOnly) {
  const double slope = 20 * kDeg, phi = 35 * kDeg, amplitude = 5;
  ASSERT_GT(amplitude, kG * std::tan(phi - slope));
  ASSERT_LT(amplitude, kG * std::tan(phi + slope));
  const BaseAcceleration base = sinusoidal_base(amplitude, 2, 3, 0.0025);
  const SlidingPlane plane = incline_rising_towards_x(slope);
  const SlidingBlockHistory h =
      newmark_sliding_block(base, plane, std::tan(phi), kGravity, 4, 0.001);
  for (std::size_t i = 1; i < h.t.size(); ++i) {
    ASSERT_GE(h.slip[i], h.slip[i - 1]) << "t = " << h.t[i];
    ASSERT_GE(h.slip_rate[i], 0) << "t = " << h.t[i];
  }
  EXPECT_GT(h.slip.back(), 0.05);
  // The value, against the fine-step integration: 7e-10 of the slip, the fine steps' own error;
  // 1e-6 is the accuracy asked of the reference (the DDA is compared at 1-3 %).
  const std::vector<double> fine = fine_step_slip(base, plane, std::tan(phi), 4, 0.001, 200);
  const double error = largest_difference(h.slip, fine) / h.slip.back();
  std::printf("sinusoid on incline: s = %.9f m, against fine steps %.1e\n", h.slip.back(), error);
  EXPECT_LT(error, 1e-6);
}

// Two-way sliding on a horizontal plane (amplitude 2 mu g): both directions occur, and the
// record turned round turns the slip round to the bit (the two branches are mirror images).
TEST(NewmarkSlidingBlock, HorizontalPlaneSlidesBothWaysSymmetrically) {
  const double mu = 0.2;
  const BaseAcceleration base = sinusoidal_base(2 * mu * kG, 1, 3, 0.005);
  BaseAcceleration reversed = base;
  for (double& a : reversed.ax) a = -a;
  const SlidingBlockHistory h = newmark_sliding_block(base, SlidingPlane{}, mu, kGravity, 4, 0.001);
  const SlidingBlockHistory r =
      newmark_sliding_block(reversed, SlidingPlane{}, mu, kGravity, 4, 0.001);
  EXPECT_LT(*std::min_element(h.slip_rate.begin(), h.slip_rate.end()), -0.1);
  EXPECT_GT(*std::max_element(h.slip_rate.begin(), h.slip_rate.end()), 0.1);
  for (std::size_t i = 0; i < h.t.size(); ++i) ASSERT_EQ(h.slip[i], -r.slip[i]) << h.t[i];
  const std::vector<double> fine = fine_step_slip(base, SlidingPlane{}, mu, 4, 0.001, 200);
  const double error = largest_difference(h.slip, fine) / largest_magnitude(h.slip);
  std::printf("two-way: s = %.9f m, against fine steps %.1e\n", h.slip.back(), error);
  EXPECT_LT(error, 1e-6);
}

// The synthetic record, horizontal and oblique (the normal force varies), on a horizontal
// plane (two-way) and an incline, against the fine-step integration: the event handling on a
// record with hundreds of starts and stops.
TEST(NewmarkSlidingBlock, SyntheticRecordMatchesAFineStepIntegration) {
  struct Case {
    double slope_deg, phi_deg;
    Eigen::Vector2d direction;
  };
  for (const Case& c : {Case{0, 15, {1, 0}}, Case{20, 30, {1, 0}}, Case{20, 30, {1, 0.6}}}) {
    const BaseAcceleration base = synthetic_accelerogram(10, 0.005, 0.5 * kG, 7, c.direction);
    const SlidingPlane plane = incline_rising_towards_x(c.slope_deg * kDeg);
    const double mu = std::tan(c.phi_deg * kDeg);
    const SlidingBlockHistory h = newmark_sliding_block(base, plane, mu, kGravity, 12, 0.005);
    ASSERT_FALSE(h.lifted_off);
    const std::vector<double> fine = fine_step_slip(base, plane, mu, 12, 0.005, 1000);
    const double error = largest_difference(h.slip, fine) / largest_magnitude(h.slip);
    std::printf(
        "synthetic, alpha %.0f deg, direction (%.1f, %.1f): s = %.9f m, max |s| %.6f m, "
        "against fine steps %.1e\n",
        c.slope_deg, c.direction.x(), c.direction.y(), h.slip.back(), largest_magnitude(h.slip),
        error);
    EXPECT_GT(largest_magnitude(h.slip), 1e-3);
    EXPECT_LT(error, 1e-6);
  }
}

// The base falling faster than g: N = g - 2 g t reaches 0 at t = 0.5 s (1e-15: N's root).
TEST(NewmarkSlidingBlock, LiftOffIsReportedWhereTheNormalAccelerationVanishes) {
  const BaseAcceleration falling{{0, 1}, {0, 0}, {0, -2 * kG}};
  const SlidingBlockHistory h =
      newmark_sliding_block(falling, SlidingPlane{}, 0.5, kGravity, 2, 0.1);
  EXPECT_TRUE(h.lifted_off);
  EXPECT_NEAR(h.t.back(), 0.5, 1e-15);
  // At once where the record jumps below -g.
  const BaseAcceleration dropped{{0, 0.3, 0.3, 1}, {0, 0, 0, 0}, {0, 0, -2 * kG, -2 * kG}};
  const SlidingBlockHistory d =
      newmark_sliding_block(dropped, SlidingPlane{}, 0.5, kGravity, 2, 0.1);
  EXPECT_TRUE(d.lifted_off);
  EXPECT_EQ(d.t.back(), 0.3);
  const BaseAcceleration sinking{{0, 1}, {0, 0}, {0, -0.9 * kG}};
  EXPECT_FALSE(newmark_sliding_block(sinking, SlidingPlane{}, 0.5, kGravity, 2, 0.1).lifted_off);
}

TEST(NewmarkSlidingBlock, RejectsBadInput) {
  const BaseAcceleration none{};
  EXPECT_THROW(newmark_sliding_block(none, {{1, 1}, {-1, 1}}, 0.5, kGravity, 1, 0.1),
               std::invalid_argument);
  EXPECT_THROW(newmark_sliding_block(none, {{1, 0}, {0.1, 1}}, 0.5, kGravity, 1, 0.1),
               std::invalid_argument);
  EXPECT_THROW(newmark_sliding_block({{1, 0}, {0, 0}, {0, 0}}, {}, 0.5, kGravity, 1, 0.1),
               std::invalid_argument);
  EXPECT_THROW(newmark_sliding_block(none, {}, -0.1, kGravity, 1, 0.1), std::invalid_argument);
}

}  // namespace
}  // namespace fissure::testing
