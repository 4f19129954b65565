// A material's permeability as a law of the stress (docs/continuum.md
// section 9, docs/upscaling.md section 8): the tensor of a fractured rock
// mass whose joints close as the mean in-plane effective stress
//   sigma' = -(sxx + syy) / 2 - p
// grows (Terzaghi's: the joints carry the full pore pressure; compression
// +; at effective tension the tensor of sigma' = 0). The principal values
// k_max and k_min (about a fixed direction) follow one of:
//  * exponential: k_i = k_i,ref exp(-beta_i (sigma' - sigma_ref)), the form
//    of the DECOVALEX fractured-rock studies (Rutqvist et al. 2002) for a
//    scene that gives its parameters;
//  * table: ln k_i piecewise linear in sigma' between the states of a
//    `fissure rev` stress study (exponential between neighbouring states),
//    held at the end values outside them. A study's k-stress curve is not
//    one exponential over a repository's depths (its joints close linearly
//    towards their residual aperture, so ln k bends down: 1.9e-13 m^2 at
//    100 m, 5e-16 m^2 at 1 km in configs/sellafield_stress_study.yaml), and
//    one exponential fitted to it is off by a factor of 5 at its ends; the
//    table returns the study's tensors at its states and extrapolates
//    nothing it did not measure.
#pragma once

#include <Eigen/Core>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

namespace fissure::continuum {

struct StressPermeabilityLaw {
  /// The points of ln k_max and ln k_min against sigma' (Pa, ascending):
  /// two for an exponential law (its k_ref at sigma_ref and its slope,
  /// extended beyond them), two or more for a study's table (held beyond).
  std::vector<double> stresses;
  std::vector<Eigen::Vector2d> log_k;
  bool extrapolate = false;  ///< exponential: the line continues beyond the points
  double angle = 0;          ///< of k_max's direction from x, counter-clockwise, rad

  /// The law k_ref exp(-beta (sigma' - sigma_ref)) per principal value.
  static StressPermeabilityLaw exponential(const Eigen::Vector2d& k_ref,
                                           const Eigen::Vector2d& beta, double sigma_ref,
                                           double angle);
  /// The tensor (kxx, kyy, kxy) at mean effective stress `sigma` (Pa).
  Eigen::Vector3d at(double sigma) const;
};

/// The mean in-plane effective stress, compression +, of the total stress
/// (sxx, syy; tension +) and the pore pressure p.
inline double mean_effective_stress(double sxx, double syy, double p) {
  return -(sxx + syy) / 2 - p;
}

/// The table of a stress study's stress.json (`fissure rev` with a
/// `mechanics` section, docs/upscaling.md): the mean tensors of its largest
/// size at the states `states` (empty: the states of its first state's
/// stress ratio, the magnitude series), against their mean effective
/// stress; the direction the mean of theirs. Throws Error (naming `what`)
/// when fewer than two of them came to rest with a tensor, when two share a
/// mean stress, or when the file is not a stress study's.
StressPermeabilityLaw stress_study_table(const nlohmann::json& study,
                                         const std::vector<int>& states, const std::string& what);

}  // namespace fissure::continuum
