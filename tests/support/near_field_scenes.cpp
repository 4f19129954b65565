#include "tests/support/near_field_scenes.h"

#include <fmt/format.h>

namespace fissure::testing {

std::string tied_square_scene(const TiedSquare& s) {
  const std::string stress = fmt::format("[{:.17g} MPa, {:.17g} MPa, 0]", s.sxx, s.syy);
  const std::string prestress = s.prestressed ? "  initial_stress: " + stress + "\n" : "";
  return fmt::format(R"(name: {0}
physics: [continuum, mechanics]
gravity: [0, 0]
materials:
  - {{name: rock, density: 2600 kg/m^3, young_modulus: 10 GPa, poisson_ratio: 0.25}}
joints:
  - {{name: glued, friction_angle: 40, cohesion: 100 MPa, tensile_strength: 100 MPa}}
rock_mass:
  domain: [[-10, -10], [10, -10], [10, 10], [-10, 10]]
  material: rock
  joint_sets:
{1}
{2}mechanics:
  dda: {{time_step: 100000 s, velocity_carry_over: 0, max_displacement_ratio: 0.1}}
continuum:
  domain: [[-50, -50], [50, -50], [50, 50], [-50, 50]]
  holes:
    - {{name: near_field, polygon: [[-10, -10], [10, -10], [10, 10], [-10, 10]]}}
  mesh: {{element_size: 10 m, fine_element_size: 2 m, size_grading: 0.3}}
  materials:
    - {{name: rock, biot_coefficient: 1e-6, biot_modulus: 10 GPa, permeability: 1e-18 m^2}}
{3}  conditions:
    - {{boundary: left, displacement: [0, free]}}
    - {{boundary: bottom, displacement: [free, 0]}}
    - {{boundary: right, traction: [{4:.17g} MPa, 0]}}
    - {{boundary: top, traction: [0, {5:.17g} MPa]{6}}}
    - {{boundary: near_field, interface: [traction]}}
  scheme: monolithic
  time_step: 100000 s
coupling:
  scheme: iterated
  order: {9}
  iteration: {7}
time: {{end: {8}}}
output:
)",
                     s.name, s.joint_sets, prestress,
                     s.prestressed ? "  initial: {stress: " + stress + "}\n" : "", s.sxx, s.syy,
                     s.top_extra, s.iteration, s.end, s.order);
}

}  // namespace fissure::testing
