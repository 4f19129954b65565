#include "mechanics/dda/dda_parameters.h"

#include <algorithm>
#include <cmath>

namespace fissure::dda {

DdaParameters DdaParameters::from_scene(const Scene& scene) {
  const MechanicsControls& mechanics = mechanics_controls(scene);
  const DdaControls& c = mechanics.dda;
  DdaParameters p;
  p.max_time_step = c.max_time_step;

  // Shi's w0: half the size of the model (its larger side).
  Box model;
  for (const BlockSpec& b : scene.blocks) model.extend(bounding_box(b.polygon));
  const double w = 0.5 * std::max(model.size().x(), model.size().y());
  p.max_step_displacement = c.max_displacement_ratio * w;
  // Both blocks of a pair may move g2 w towards each other in one step.
  p.contact_range = 2.5 * p.max_step_displacement;

  double e_max = 0;
  for (const Material& m : scene.materials) e_max = std::max(e_max, m.young_modulus);
  p.normal_penalty = c.penalty ? *c.penalty : c.penalty_factor * e_max * 1.0 /* m */;
  p.shear_penalty = c.shear_penalty_ratio * p.normal_penalty;
  p.fixed_point_penalty = p.normal_penalty;
  p.velocity_carry_over = c.velocity_carry_over;
  p.damping_ratio = c.damping_ratio;
  p.max_open_close_iterations = c.max_open_close_iterations;
  p.exact_rotation = c.exact_rotation;
  p.plane = mechanics.plane;
  p.solver = c.solver;
  for (const JointProperties& j : scene.joints)
    p.friction_coefficients.push_back(std::tan(j.friction_angle));
  return p;
}

}  // namespace fissure::dda
