#include "rockmass/joints/barton_bandis.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>
#include <stdexcept>
#include <string>

#include "rockmass/joints/property_checks.h"

namespace fissure::joints {

namespace {

constexpr double kDegree = std::numbers::pi / 180;
/// Barton and Choubey's limit on the friction angle at low normal stress.
constexpr double kMaxFrictionAngle = 70 * kDegree;

/// JRC_mob / JRC_peak against delta / delta_peak (Barton 1982; Barton,
/// Bandis and Bakhtar 1985), from the point where it is 0.
constexpr double kDisplacementRatio[] = {0.3, 0.6, 1, 2, 4, 10, 100};
constexpr double kJrcRatio[] = {0, 0.75, 1, 0.85, 0.70, 0.50, 0};

// The regressions' units.
constexpr double kMPa = 1e6, kMm = 1e-3;

}  // namespace

double scaled_jrc(double jrc0, double lab_length, double field_length) {
  return jrc0 * std::pow(field_length / lab_length, -0.02 * jrc0);
}

double scaled_jcs(double jcs0, double jrc0, double lab_length, double field_length) {
  return jcs0 * std::pow(field_length / lab_length, -0.03 * jrc0);
}

double peak_shear_displacement(double jrc_n, double field_length) {
  return field_length / 500 * std::pow(jrc_n / field_length, 0.33);
}

double roughness_angle(double jrc, double jcs, double normal_stress, double residual_friction) {
  const double degrees = jrc * std::log10(jcs / normal_stress);
  return std::clamp(degrees * kDegree, 0.0, std::max(0.0, kMaxFrictionAngle - residual_friction));
}

double mobilized_jrc_ratio(double x) {
  const double* const end = std::end(kDisplacementRatio);
  if (x <= kDisplacementRatio[0]) return kJrcRatio[0];
  if (x >= end[-1]) return 0;
  const auto k = std::upper_bound(std::begin(kDisplacementRatio), end, x) -
                 std::begin(kDisplacementRatio);  // x in [ratio[k-1], ratio[k])
  const double t =
      (x - kDisplacementRatio[k - 1]) / (kDisplacementRatio[k] - kDisplacementRatio[k - 1]);
  return kJrcRatio[k - 1] + t * (kJrcRatio[k] - kJrcRatio[k - 1]);
}

double mobilized_friction_angle(double x, double roughness, double residual_friction) {
  if (x <= 0) return 0;
  if (x < kDisplacementRatio[0]) return residual_friction * x / kDisplacementRatio[0];
  return residual_friction + mobilized_jrc_ratio(x) * roughness;
}

double mobilized_dilation_angle(double x, double roughness) {
  if (x < kDisplacementRatio[0]) return 0;
  return 0.5 * mobilized_jrc_ratio(x) * roughness;
}

namespace {

/// The mean of tan over [a, b] (rad): ln(cos a / cos b) / (b - a), written
/// with cos a / cos b = cos d + tan b sin d, d = b - a, so that it stays
/// exact as d -> 0 (tan a at d = 0).
double mean_tan(double a, double b) {
  const double d = b - a;
  if (d == 0) return std::tan(a);
  const double half = std::sin(d / 2);
  return std::log1p(std::tan(b) * std::sin(d) - 2 * half * half) / d;
}

}  // namespace

double mobilized_dilation(double x, double roughness) {
  double sum = 0;
  for (std::size_t k = 0; k + 1 < std::size(kDisplacementRatio) && x > kDisplacementRatio[k]; ++k) {
    const double x0 = kDisplacementRatio[k], x1 = std::min(x, kDisplacementRatio[k + 1]);
    sum +=
        mean_tan(mobilized_dilation_angle(x0, roughness), mobilized_dilation_angle(x1, roughness)) *
        (x1 - x0);
  }
  return sum;
}

BandisClosure bandis_regression(double jrc0, double jcs0, double initial_aperture) {
  const double strength_per_aperture = (jcs0 / kMPa) / (initial_aperture / kMm);  // MPa/mm
  const double kni = -7.15 + 1.75 * jrc0 + 0.02 * strength_per_aperture;          // MPa/mm
  const double vm = -0.1032 - 0.0074 * jrc0 + 1.135 * std::pow(strength_per_aperture, -0.251);
  return {kni * kMPa / kMm, vm * kMm};
}

double bandis_normal_stress(double closure, const BandisClosure& c) {
  return c.initial_normal_stiffness * c.max_closure * closure / (c.max_closure - closure);
}

double bandis_closure(double normal_stress, const BandisClosure& c) {
  return normal_stress * c.max_closure /
         (c.initial_normal_stiffness * c.max_closure + normal_stress);
}

double bandis_normal_stiffness(double normal_stress, const BandisClosure& c) {
  const double f = 1 + normal_stress / (c.initial_normal_stiffness * c.max_closure);
  return c.initial_normal_stiffness * f * f;
}

double hydraulic_aperture(double mechanical_aperture, double jrc0) {
  if (jrc0 <= 0) return mechanical_aperture;
  const double e_um = mechanical_aperture / 1e-6;
  return std::min(e_um * e_um / std::pow(jrc0, 2.5) * 1e-6, mechanical_aperture);
}

BartonBandis::BartonBandis(const BartonBandisProperties& properties) : p_(properties) {
  const char* law = "Barton-Bandis";
  require(p_.jrc > 0 && p_.jrc <= 20, law, "JRC", "in (0, 20]", p_.jrc);
  require_positive(law, "JCS", p_.jcs);
  require_positive(law, "lab length", p_.lab_length);
  require_non_negative(law, "field length", p_.field_length);
  require(p_.residual_friction_angle >= 0 && p_.residual_friction_angle < kMaxFrictionAngle, law,
          "residual friction angle", "in [0, 70) degrees", p_.residual_friction_angle);
  require_positive(law, "initial aperture", p_.initial_aperture);
  require_non_negative(law, "initial normal stiffness", p_.initial_normal_stiffness);
  require_non_negative(law, "maximum closure", p_.max_closure);
  const BandisClosure regression = bandis_regression(p_.jrc, p_.jcs, p_.initial_aperture);
  closure_.initial_normal_stiffness = p_.initial_normal_stiffness > 0
                                          ? p_.initial_normal_stiffness
                                          : regression.initial_normal_stiffness;
  closure_.max_closure = p_.max_closure > 0 ? p_.max_closure : regression.max_closure;
  require_positive(law, "initial normal stiffness k_ni", closure_.initial_normal_stiffness);
  require(closure_.max_closure > 0 && closure_.max_closure < p_.initial_aperture, law,
          "maximum closure V_m", "in (0, E_0)", closure_.max_closure);
}

BartonBandis::Scaled BartonBandis::scaled(double field_length) const {
  Scaled s;
  s.jrc = scaled_jrc(p_.jrc, p_.lab_length, field_length);
  s.jcs = scaled_jcs(p_.jcs, p_.jrc, p_.lab_length, field_length);
  s.peak_displacement = peak_shear_displacement(s.jrc, field_length);
  return s;
}

double BartonBandis::normal_stress(double closure, double jcs) const {
  if (closure <= 0) return 0;
  // Beyond sigma_n = JCS_n (the walls' strength) the hyperbola, whose
  // stress grows without bound towards V_m, goes on as its tangent.
  const double closure_at_jcs = bandis_closure(jcs, closure_);
  if (closure < closure_at_jcs) return bandis_normal_stress(closure, closure_);
  return jcs + bandis_normal_stiffness(jcs, closure_) * (closure - closure_at_jcs);
}

double BartonBandis::normal_stiffness(double normal_stress, double jcs) const {
  return bandis_normal_stiffness(std::min(normal_stress, jcs), closure_);
}

double BartonBandis::normal_stiffness_at(double normal_stress, double length) const {
  return normal_stiffness(std::max(0.0, normal_stress), scaled(field_length(length)).jcs);
}

double BartonBandis::mobilized_displacement_for(double normal_stress, double shear_stress,
                                                double length) const {
  const Scaled s = scaled(field_length(length));
  if (!(normal_stress > 0) || shear_stress == 0) return 0;
  const double phi_r = p_.residual_friction_angle;
  const double i = roughness_angle(s.jrc, s.jcs, normal_stress, phi_r);
  const double target = std::atan(std::abs(shear_stress) / normal_stress);
  if (target >= mobilized_friction_angle(1, i, phi_r)) return s.peak_displacement;
  // The mobilized angle grows with delta up to the peak: bisection on
  // delta / delta_peak in [0, 1] (to round-off in 60 halvings).
  double lo = 0, hi = 1;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    (mobilized_friction_angle(mid, i, phi_r) < target ? lo : hi) = mid;
  }
  return hi * s.peak_displacement;
}

double BartonBandis::shear_stiffness_at(double normal_stress, double length) const {
  if (!(normal_stress > 0)) return 0;
  const Scaled s = scaled(field_length(length));
  const double i = roughness_angle(s.jrc, s.jcs, normal_stress, p_.residual_friction_angle);
  return normal_stress * std::tan(p_.residual_friction_angle + i) / s.peak_displacement;
}

double BartonBandis::friction_angle_at(const State& s, double normal_stress, double length) const {
  const Scaled scaled_law = scaled(s.field_length > 0 ? s.field_length : field_length(length));
  const double phi_r = p_.residual_friction_angle;
  const double i = roughness_angle(scaled_law.jrc, scaled_law.jcs, normal_stress, phi_r);
  return mobilized_friction_angle(s.mobilized_displacement / scaled_law.peak_displacement, i,
                                  phi_r);
}

double BartonBandis::mechanical_aperture(const State& s) const {
  return std::max(0.0, p_.initial_aperture + s.normal_displacement);
}

double BartonBandis::field_length(double length) const {
  return p_.field_length > 0 ? p_.field_length : length;
}

BartonBandis::Loaded BartonBandis::loaded(double normal_stress, double shear,
                                          double field_length) const {
  const Scaled s = scaled(field_length);
  Loaded r;
  const double sigma = std::max(normal_stress, 0.0);
  // The inverse of normal_stress(): the hyperbola up to JCS_n, its tangent beyond.
  r.closure = sigma <= s.jcs ? bandis_closure(sigma, closure_)
                             : bandis_closure(s.jcs, closure_) +
                                   (sigma - s.jcs) / bandis_normal_stiffness(s.jcs, closure_);
  r.normal_stiffness = normal_stiffness(sigma, s.jcs);
  const double i = roughness_angle(s.jrc, s.jcs, sigma, p_.residual_friction_angle);
  r.dilation = mobilized_dilation(std::abs(shear) / s.peak_displacement, i) * s.peak_displacement;
  return r;
}

JointResponse BartonBandis::update(const State& before, const JointIncrement& step,
                                   State& after) const {
  after = before;
  after.normal_displacement += step.normal;
  after.shear_displacement += step.shear;
  if (after.field_length <= 0) after.field_length = field_length(step.length);
  if (!(after.field_length > 0))
    throw std::invalid_argument(
        "Barton-Bandis: no field length (the properties give none and the step's contact "
        "length is " +
        std::to_string(step.length) + ")");
  const Scaled s = scaled(after.field_length);
  const double phi_r = p_.residual_friction_angle;
  JointResponse r;

  // 1. Shear, explicit in the normal stress at the start of the step: a
  // joint that was open carries no shear in the step it closes.
  const double sigma0 = before.normal_stress;
  bool loading = false;
  double tau = 0, direction = 0;
  if (sigma0 > 0) {
    const double i0 = roughness_angle(s.jrc, s.jcs, sigma0, phi_r);
    const double ks = sigma0 * std::tan(phi_r + i0) / s.peak_displacement;
    tau = before.shear_stress + ks * step.shear;  // elastic, inside the curve
    if (step.shear != 0) {
      direction = step.shear > 0 ? 1 : -1;
      const double x0 = before.mobilized_displacement / s.peak_displacement;
      const double on_curve = sigma0 * std::tan(mobilized_friction_angle(x0, i0, phi_r));
      const double elastic_part = std::max(0.0, (on_curve - direction * before.shear_stress) / ks);
      if (std::abs(step.shear) > elastic_part) {
        loading = true;
        const double advance = std::abs(step.shear) - elastic_part;
        // Dilation at the middle of the advance (second order in it).
        const double middle = (before.mobilized_displacement + advance / 2) / s.peak_displacement;
        r.dilation = std::tan(mobilized_dilation_angle(middle, i0)) * advance;
        r.plastic_shear = advance;
        after.mobilized_displacement += advance;
        after.dilation += r.dilation;
      }
    }
  }

  // 2. Normal: Bandis's closure after the step's dilation.
  const double closure = after.dilation - after.normal_displacement;
  if (closure <= 0) {
    after.normal_stress = after.shear_stress = 0;
    r.open = true;
    return r;
  }
  const double sigma = normal_stress(closure, s.jcs);
  const double i = roughness_angle(s.jrc, s.jcs, sigma, phi_r);
  const double x = after.mobilized_displacement / s.peak_displacement;
  const double strength = sigma * std::tan(mobilized_friction_angle(x, i, phi_r));
  if (loading) tau = direction * strength;
  after.normal_stress = sigma;
  after.shear_stress = tau;
  r.normal_stress = sigma;
  r.shear_stress = tau;
  r.slipping = loading;
  r.normal_stiffness = normal_stiffness(sigma, s.jcs);
  r.shear_strength = strength;
  return r;
}

}  // namespace fissure::joints
