#include "mechanics/dda/dda_parameters.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace fissure::dda {

double median_block_size(const Scene& scene) {
  std::vector<double> sizes;
  sizes.reserve(scene.blocks.size());
  for (const BlockSpec& b : scene.blocks) {
    const double area = section_properties(b.polygon).area;
    if (area > 0) sizes.push_back(std::sqrt(area));
  }
  if (sizes.empty()) return 0;
  auto middle = sizes.begin() + sizes.size() / 2;
  std::nth_element(sizes.begin(), middle, sizes.end());
  return *middle;
}

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
  // ... but a step must stay small beside the blocks: DDA's first-order
  // kinematics and its contact detection assume it (theory.md 1.6, 1.8), and
  // the contact range (below) decides how many vertex-edge pairs a step
  // carries. In a model much larger than its blocks (or one long sliver
  // stretching the box) g2 w would reach across several blocks and every
  // vertex would pair with hundreds of edges. Hence g2 w is capped at a
  // fifth of the median block size (sqrt of the area; the median, so that
  // one odd block does not set it): the contact range is then at most half
  // a typical block.
  const double size = median_block_size(scene);
  if (size > 0)
    p.max_step_displacement = std::min(p.max_step_displacement, kMaxStepPerBlockSize * size);
  // Both blocks of a pair may move g2 w towards each other in one step.
  p.contact_range = 2.5 * p.max_step_displacement;

  double e_max = 0;
  for (const Material& m : scene.materials) e_max = std::max(e_max, m.young_modulus);
  const double automatic_penalty = c.penalty_factor * e_max * 1.0 /* m */;
  p.normal_penalty = c.penalty ? *c.penalty : automatic_penalty;
  p.stiffest_penalty = std::max(automatic_penalty, p.normal_penalty);
  p.shear_penalty = c.shear_penalty_ratio * p.normal_penalty;
  p.fixed_point_penalty = p.normal_penalty;
  p.velocity_carry_over = c.velocity_carry_over;
  p.damping_ratio = c.damping_ratio;
  p.max_open_close_iterations = c.max_open_close_iterations;
  p.contact_method = c.contact_method;
  // 1e-4 of a typical block: far below what any joint's roughness or the
  // step's geometry resolve, far above round-off.
  p.penetration_tolerance = c.penetration_tolerance.value_or(1e-4 * (size > 0 ? size : 1.0));
  p.max_augmentations = c.max_augmentations;
  p.exact_rotation = c.exact_rotation;
  p.plane = mechanics.plane;
  p.solver = c.solver;
  for (const JointProperties& j : scene.joints)
    p.friction_coefficients.push_back(std::tan(j.friction_angle));
  return p;
}

}  // namespace fissure::dda
