// The Barton-Bandis joint (docs/joints.md section 3): Barton's JRC-JCS
// strength with the scale corrections and the mobilization of roughness,
// Bandis's hyperbolic normal closure, and the mechanical -> hydraulic
// aperture for the flow.
//
// Strength (Barton and Choubey 1977), angles in degrees inside the bracket:
//   tau_peak = sigma_n tan(JRC_n log10(JCS_n / sigma_n) + phi_r)
// with the roughness term i = JRC_n log10(JCS_n / sigma_n) kept in
// [0, 70 deg - phi_r] (Barton and Choubey's 70 degree limit at low stress; no
// negative roughness above JCS).
// Scale (Barton and Bandis 1982), L_0 the lab length, L_n the field length:
//   JRC_n = JRC_0 (L_n/L_0)^(-0.02 JRC_0),  JCS_n = JCS_0 (L_n/L_0)^(-0.03 JRC_0)
//   delta_peak = (L_n / 500) (JRC_n / L_n)^0.33     (L_n and delta_peak in m)
// Mobilization (Barton 1982; Barton, Bandis and Bakhtar 1985): the
// mobilized friction angle at the shear displacement delta is
// JRC_mob log10(JCS_n/sigma_n) + phi_r, JRC_mob / JRC_n interpolated
// linearly in delta / delta_peak through
//   0 -> -phi_r/i, 0.3 -> 0, 0.6 -> 0.75, 1 -> 1, 2 -> 0.85, 4 -> 0.70,
//   10 -> 0.50, 100 -> 0   (phi_r alone beyond 100),
// and the dilation angle is psi_mob = 0.5 JRC_mob log10(JCS_n/sigma_n) >= 0.
// Unloading and reloading inside the curve are elastic with Barton's peak
// shear stiffness K_s = tau_peak / delta_peak; loading on the curve
// advances delta (which a reversal does not reset: the strength goes on
// from the current JRC_mob).
// Normal closure (Bandis, Lumsden and Barton 1983), closure dV > 0:
//   dV = sigma_n V_m / (k_ni V_m + sigma_n),  k_n = k_ni (1 + sigma_n / (k_ni V_m))^2
// the same curve for loading and unloading, continued as a straight line
// with its tangent beyond sigma_n = JCS_n; no tension.
// Hydraulic aperture (Barton, Bandis and Bakhtar 1985): e = E^2 / JRC_0^2.5
// with e and E in micrometres, and e <= E.
//
// The step is explicit (as UDEC's): the split of a shear increment into
// elastic and mobilizing parts, the shear stiffness and the dilation use the
// normal stress at the start of the step; the normal stress then follows
// from the closure, and a loading joint's shear stress is the curve's at the
// new normal stress.
#pragma once

#include <concepts>
#include <type_traits>

#include "rockmass/joints/joint_step.h"

namespace fissure::joints {

struct BartonBandisProperties {
  double jrc = 0;                       ///< JRC_0 at the lab scale, in [0, 20]
  double jcs = 0;                       ///< JCS_0, Pa (> 0)
  double lab_length = 0;                ///< L_0, m (> 0)
  double field_length = 0;              ///< L_n, m; 0 = the contact's length at its first step
  double residual_friction_angle = 0;   ///< phi_r, rad, in [0, 70 deg)
  double initial_aperture = 0;          ///< E_0, the mechanical aperture at sigma_n = 0, m (> 0)
  double initial_normal_stiffness = 0;  ///< k_ni, Pa/m; 0 = the Bandis regression
  double max_closure = 0;               ///< V_m, m (< E_0); 0 = the Bandis regression
};

// The formulas above, one function each (SI units, angles in radians).

/// JRC_n from JRC_0 at the lab length L_0 and the field length L_n.
double scaled_jrc(double jrc0, double lab_length, double field_length);
/// JCS_n from JCS_0 (any unit) and JRC_0.
double scaled_jcs(double jcs0, double jrc0, double lab_length, double field_length);
/// delta_peak (m) of a joint of length L_n (m) and roughness JRC_n.
double peak_shear_displacement(double jrc_n, double field_length);
/// The roughness term i = JRC log10(JCS / sigma_n) in radians, in [0, 70 deg - phi_r].
double roughness_angle(double jrc, double jcs, double normal_stress, double residual_friction);
/// JRC_mob / JRC_peak at delta / delta_peak = x >= 0.3 (the table), 0 beyond 100.
double mobilized_jrc_ratio(double x);
/// The mobilized friction angle (rad) at delta / delta_peak = x >= 0, for
/// the roughness term i (rad): phi_r x / 0.3 below 0.3 (JRC_mob from
/// -phi_r/i to 0), then phi_r + JRC_mob/JRC_peak i.
double mobilized_friction_angle(double x, double roughness, double residual_friction);
/// psi_mob (rad) at x: 0.5 JRC_mob/JRC_peak i, and 0 where JRC_mob < 0.
double mobilized_dilation_angle(double x, double roughness);
/// The dilation of a shear from rest to delta / delta_peak = x >= 0 at a
/// constant roughness term i (rad), in units of delta_peak: the integral of
/// tan(psi_mob) from 0 to x, exact (psi_mob is linear in x between the
/// table's points).
double mobilized_dilation(double x, double roughness);

/// Bandis's closure parameters.
struct BandisClosure {
  double initial_normal_stiffness = 0;  ///< k_ni, Pa/m
  double max_closure = 0;               ///< V_m, m
};
/// The first-loading regressions of Bandis et al. (1983) as Barton et al.
/// (1985) give them, in MPa and mm:
///   k_ni = -7.15 + 1.75 JRC_0 + 0.02 JCS_0 / E_0            (MPa/mm)
///   V_m  = -0.1032 - 0.0074 JRC_0 + 1.135 (JCS_0 / E_0)^-0.251  (mm)
/// (SI in and out; either may come out <= 0 outside the data's range).
BandisClosure bandis_regression(double jrc0, double jcs0, double initial_aperture);
/// sigma_n (Pa) at the closure dV (m) on the hyperbola, dV in [0, V_m).
double bandis_normal_stress(double closure, const BandisClosure& c);
/// dV (m) at sigma_n >= 0 (Pa).
double bandis_closure(double normal_stress, const BandisClosure& c);
/// k_n = d sigma_n / d dV (Pa/m) at sigma_n >= 0.
double bandis_normal_stiffness(double normal_stress, const BandisClosure& c);

/// e (m) from the mechanical aperture E (m): E^2 / JRC_0^2.5 in
/// micrometres, at most E (and E itself for a smooth joint, JRC_0 = 0).
double hydraulic_aperture(double mechanical_aperture, double jrc0);

class BartonBandis {
 public:
  /// Per contact: the walls (JointWalls) and the law's own history.
  struct State : JointWalls {
    double mobilized_displacement = 0;  ///< delta: shear on the loading curve so far, m
    double field_length = 0;            ///< L_n of this contact, m (fixed at its first step)
  };

  /// Fills k_ni and V_m from the regression where they are 0. Throws
  /// std::invalid_argument for properties out of range, or when the
  /// regression gives k_ni <= 0 or V_m outside (0, E_0).
  explicit BartonBandis(const BartonBandisProperties& properties);

  const BartonBandisProperties& properties() const { return p_; }
  const BandisClosure& closure() const { return closure_; }
  State initial_state() const { return State{}; }
  JointResponse update(const State& before, const JointIncrement& step, State& after) const;

  /// E = E_0 + u_n (m, >= 0): the walls' separation for the flow, with the
  /// closure and the dilation.
  double mechanical_aperture(const State& s) const;

  /// The tangent normal stiffness (Bandis's, Pa/m) at sigma_n (Pa) of a
  /// contact of this length (m; field_length(length) is its L_n).
  double normal_stiffness_at(double normal_stress, double length) const;
  /// The mobilized displacement delta (m) at which the loading curve at
  /// sigma_n (Pa) reaches |tau| (Pa), for a contact of this length: the
  /// history of a joint that carries tau at the start (the rock mass's
  /// initial stress). delta_peak when |tau| is at or above the peak.
  double mobilized_displacement_for(double normal_stress, double shear_stress, double length) const;
  /// Barton's peak shear stiffness sigma_n tan(phi_r + i) / delta_peak (Pa/m).
  double shear_stiffness_at(double normal_stress, double length) const;
  /// The mobilized friction angle phi_mob (rad) of a contact with the
  /// history `s` at sigma_n (Pa; the roughness term's 70 degree cap at
  /// sigma_n <= 0): JRC_mob log10(JCS_n / sigma_n) + phi_r at its
  /// delta / delta_peak, the strength update() gives over sigma_n. The
  /// contact's field length is its state's, else field_length(length).
  double friction_angle_at(const State& s, double normal_stress, double length) const;

  /// L_n of a contact or fracture of this length (m): the properties'
  /// field length where they give one.
  double field_length(double length) const;

  /// The joint sheared monotonically from rest under a constant normal
  /// stress, the path of Barton's tables (what the flow's apertures use,
  /// docs/joints.md 3.4).
  struct Loaded {
    double closure = 0;           ///< dV on the normal curve of update(), m
    double normal_stiffness = 0;  ///< its tangent d sigma_n / d dV, Pa/m
    double dilation = 0;          ///< the integral of tan(psi_mob) over the shear, m
  };
  /// At sigma_n >= 0 (Pa), after the shear |u_s| (m), at the field length L_n (m).
  Loaded loaded(double normal_stress, double shear, double field_length) const;

 private:
  /// The law at a contact's field length.
  struct Scaled {
    double jrc = 0, jcs = 0, peak_displacement = 0;
  };
  Scaled scaled(double field_length) const;
  double normal_stress(double closure, double jcs) const;
  double normal_stiffness(double normal_stress, double jcs) const;

  BartonBandisProperties p_;
  BandisClosure closure_;
};

template <class Archive, class State>
requires std::same_as<std::remove_const_t<State>, BartonBandis::State>
void checkpoint_fields(Archive& e, State& s) {
  checkpoint_walls(e, s);
  e("mobilized_displacement", s.mobilized_displacement);
  e("field_length", s.field_length);
}

}  // namespace fissure::joints
