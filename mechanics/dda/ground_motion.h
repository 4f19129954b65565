// Recorded ground motion (docs/dda.md section 10): a time history of the
// base's horizontal and vertical acceleration, velocity or displacement,
// turned into a motion that can be evaluated at any time with its
// acceleration, velocity and displacement consistent with one another.
//
// Each interval of the record carries a cubic displacement
//   u(t_k + s) = u_k + v_k s + a_k s^2 / 2 + j_k s^3 / 6,
// exact for an acceleration record linear between its samples (the usual
// reading of an accelerogram), for a velocity record linear between its
// samples (j = 0, a constant per interval) and for a displacement record
// linear between its samples (a = j = 0, v constant per interval).
//
// An accelerogram integrated twice drifts: the record's baseline (instrument
// offset, a lost pre-event portion) gives a residual velocity at its end and
// a displacement that grows without bound. The quadratic baseline
// correction (Boore 2001, "Effect of baseline corrections on displacements
// and response spectra") fits v_b(t) = b1 t + b2 t^2 to the velocity by
// least squares, through the record's end velocity, and removes its
// derivative b1 + 2 b2 t from the acceleration: the corrected ground starts
// and ends at rest, and its acceleration is again linear between the
// samples.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/base/enum_names.h"
#include "core/geometry/polygon.h"

namespace fissure::dda {

enum class MotionQuantity { Acceleration, Velocity, Displacement };
/// Their names in the scene (`quantity`) and in summary.json.
inline constexpr EnumName<MotionQuantity> kMotionQuantityNames[] = {
    {"acceleration", MotionQuantity::Acceleration},
    {"velocity", MotionQuantity::Velocity},
    {"displacement", MotionQuantity::Displacement}};

/// A record as read: times (s, strictly increasing, the first >= 0) and the
/// horizontal (x) and vertical (y) components, SI, of `quantity`.
struct GroundMotionRecord {
  MotionQuantity quantity = MotionQuantity::Acceleration;
  std::vector<double> time;
  std::vector<Vec2> values;
  std::string source;  ///< the file(s), for reports
};

class GroundMotion {
 public:
  GroundMotion() = default;
  /// The record's motion, starting at scene time `start` (at rest before
  /// it); with `baseline_correction` (acceleration records only) the
  /// quadratic velocity baseline is removed.
  GroundMotion(const GroundMotionRecord& record, double start, bool baseline_correction);

  bool empty() const { return time_.empty(); }
  Vec2 acceleration(double t) const;
  Vec2 velocity(double t) const;
  Vec2 displacement(double t) const;

  /// Peaks, the baseline's coefficients, the velocity and displacement at
  /// the record's end before and after the correction (summary.json).
  nlohmann::json report() const;

 private:
  struct Sample {
    Vec2 u, v, a, jerk;  ///< at the interval's start; jerk over the interval
  };
  /// The polynomial of the interval that holds scene time t (at rest before
  /// the record, without acceleration after it), and t's offset s into it.
  Sample at(double t, double& s) const;
  /// Fills samples_' motion exactly from the quantity the record holds.
  void integrate();

  double start_ = 0;
  MotionQuantity quantity_ = MotionQuantity::Acceleration;
  std::vector<double> time_;     ///< record times + start
  std::vector<Sample> samples_;  ///< corrected
  std::string source_;
  bool corrected_ = false;
  Vec2 baseline_b1_ = Vec2::Zero(), baseline_b2_ = Vec2::Zero();
  Vec2 raw_end_velocity_ = Vec2::Zero(), raw_end_displacement_ = Vec2::Zero();
};

}  // namespace fissure::dda
