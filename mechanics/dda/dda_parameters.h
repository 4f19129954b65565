// DDA controls resolved to numbers for one run (from the scene's mechanics
// section, dda_settings.h, and the initial geometry). Every member is set by
// from_scene; the defaults of the scene keys are in dda_settings.h.
#pragma once

#include <vector>

#include "core/scene/scene.h"
#include "mechanics/dda/dda_settings.h"

namespace fissure::dda {

/// The largest step displacement, as a fraction of the median block size.
inline constexpr double kMaxStepPerBlockSize = 0.2;

/// Median over the blocks of sqrt(area) (m; 0 without blocks of positive area).
double median_block_size(const Scene& scene);

struct DdaParameters {
  double max_time_step = 0;  ///< g1 (s)
  /// g2 * w (m); w = half the larger side of the model box; at most
  /// kMaxStepPerBlockSize times the median block size.
  double max_step_displacement = 0;
  double contact_range = 0;        ///< 2.5 g2 w: vertex-edge pairs closer than this are candidates
  double normal_penalty = 0;       ///< p_n (N/m)
  double shear_penalty = 0;        ///< p_s (N/m)
  double fixed_point_penalty = 0;  ///< p_f (N/m)
  double velocity_carry_over = 0;  ///< k01
  double damping_ratio = 0;        ///< of the blocks' strain vibration (vibration_damping.h)
  int max_open_close_iterations = 0;
  ContactMethod contact_method = ContactMethod::Penalty;
  double penetration_tolerance = 0;  ///< m (augmented Lagrangian)
  /// The stiffest the augmented Lagrangian makes the springs: the automatic
  /// penalty (penalty_factor x E_max x 1 m, the stiffness the open-close
  /// iteration is tuned for), or the scene's penalty when that is stiffer.
  double stiffest_penalty = 0;
  int max_augmentations = 0;
  bool exact_rotation = false;
  PlaneMode plane = PlaneMode::Strain;
  LinearSolverControls solver;
  std::vector<double> friction_coefficients;  ///< tan(phi) per joint

  static DdaParameters from_scene(const Scene& scene);
};

}  // namespace fissure::dda
