// Newmark's rigid-plastic sliding block (Newmark 1965, "Effects of earthquakes on dams and
// embankments", Geotechnique 15(2); Kramer 1996, "Geotechnical Earthquake Engineering", ch. 10;
// Jibson 2011, Engineering Geology 122): the reference for the DDA's blocks under earthquake base
// motion, plus the base motions to drive both with. Plain std and Eigen, no solver code, so that a
// mistake in the DDA cannot hide in the reference. SI units.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace fissure::testing {

/// A base acceleration history (m/s^2), piecewise linear between the samples (t_i, ax_i, ay_i).
/// The times must not decrease; a repeated time is a jump (the later sample holds from it on).
/// Outside [t.front(), t.back()] the base does not accelerate.
struct BaseAcceleration {
  std::vector<double> t, ax, ay;

  /// a_b(time); at a jump the value after it.
  Eigen::Vector2d at(double time) const;
};

/// A plane fixed to the base. The slip s is measured along `tangent` (unit); `normal` (unit,
/// perpendicular to it) points from the base into the block.
struct SlidingPlane {
  Eigen::Vector2d tangent{1, 0};
  Eigen::Vector2d normal{0, 1};
};

/// The plane of tests/support/dda_scenes.h's incline_scene: rising towards +x at `slope`
/// (radians). tangent = downslope = -(cos, sin), normal = (-sin, cos). A horizontal plane is
/// SlidingPlane{} (s > 0 towards +x).
SlidingPlane incline_rising_towards_x(double slope);

/// Relative slip of the block on the plane, s(t) and s'(t), at the output times.
struct SlidingBlockHistory {
  std::vector<double> t, slip, slip_rate;
  /// The normal acceleration N reached 0 (the block would leave the plane): the history stops
  /// there, its last entry at the lift-off time.
  bool lifted_off = false;
};

/// A rigid block at rest on `plane` from t = 0, friction coefficient mu = tan(phi) (no cohesion),
/// under `gravity` (e.g. (0, -9.81)) while the base accelerates by a_b(t). In the base's frame
/// the block feels g - a_b: driving D = (g - a_b).tangent, normal N = -(g - a_b).normal. Stuck
/// while |D| <= mu N; sliding s'' = D - sign(s') mu N until s' returns to 0 (Newmark 1965), in
/// either direction. Exact for the piecewise-linear a_b: the slip is a cubic in time between
/// events, the starts (|D| = mu N) and the stops (s' = 0) are roots of linear and quadratic
/// functions, so only rounding errors remain. Output at 0, dt_output, 2 dt_output, ... and
/// t_end. Throws std::invalid_argument on a bad record, plane or parameter.
SlidingBlockHistory newmark_sliding_block(const BaseAcceleration& base, const SlidingPlane& plane,
                                          double mu, const Eigen::Vector2d& gravity, double t_end,
                                          double dt_output);

/// The shape of synthetic_accelerogram's record; the defaults are firm ground.
struct AccelerogramShape {
  double ground_frequency = 2.5;      // f_g, Hz (Kanai-Tajimi)
  double ground_damping = 0.6;        // zeta_g
  double high_pass_frequency = 0.25;  // f_f, Hz (Clough-Penzien: less drift of velocity)
  double high_pass_damping = 0.6;     // zeta_f
  double low_pass_frequency = 12.5;   // f_max, Hz (recorded spectra fall above it; 0: none)
  double peak_time = 0.2;             // Saragoni-Hart envelope: its peak at this fraction of
  double end_level = 0.05;            // the duration, and this fraction of the peak at the end
};

/// A deterministic "recorded-like" accelerogram along `direction`: white noise through
/// Kanai-Tajimi and Clough-Penzien filters and a low pass at f_max, times a Saragoni-Hart envelope
/// (Boore 2003) tapered to 0 over the last 5 % of the duration, scaled to the peak |a| = pga.
/// Samples at t_k = k dt up to `duration` (rounded up to whole steps); the first and last are 0.
/// The noise is std::mt19937_64(seed) through its own uniform and polar Box-Muller transform (the
/// standard library's distributions differ between implementations): the same seed gives the same
/// bits (another libm may round log, exp, pow differently in the last bit). The velocity at the
/// end is not made 0. scripts/synthetic_accelerogram.py writes the scenes' records by the same
/// recipe without the low pass (not the same samples).
BaseAcceleration synthetic_accelerogram(double duration, double dt, double pga, std::uint64_t seed,
                                        const Eigen::Vector2d& direction = Eigen::Vector2d::UnitX(),
                                        const AccelerogramShape& shape = {});

/// amplitude sin(2 pi frequency t) along `direction`, sampled at t_k = k dt up to `duration`
/// (rounded up to whole steps). Between samples the chords: dt of a period / 200 keeps them within
/// 1.2e-4 of the amplitude (pi^2 / (2 200^2)).
BaseAcceleration sinusoidal_base(double amplitude, double frequency, double duration, double dt,
                                 const Eigen::Vector2d& direction = Eigen::Vector2d::UnitX());

}  // namespace fissure::testing
