// DDA controls resolved to numbers for one run (from the scene's
// mechanics.dda section and the initial geometry).
#pragma once

#include <vector>

#include "core/scene/scene.h"

namespace fissure::dda {

struct DdaParameters {
  double max_time_step = 1e-3;       ///< g1 (s)
  double max_step_displacement = 0;  ///< g2 * w (m); w = half the larger side of the model box
  double contact_range = 0;        ///< 2.5 g2 w: vertex-edge pairs closer than this are candidates
  double normal_penalty = 0;       ///< p_n (N/m)
  double shear_penalty = 0;        ///< p_s (N/m)
  double fixed_point_penalty = 0;  ///< p_f (N/m)
  double velocity_carry_over = 1;  ///< k01
  int max_open_close_iterations = 12;
  bool exact_rotation = true;
  PlaneMode plane = PlaneMode::Strain;
  LinearSolverControls solver;
  std::vector<double> friction_coefficients;  ///< tan(phi) per joint

  static DdaParameters from_scene(const Scene& scene);
};

}  // namespace fissure::dda
