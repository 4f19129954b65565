#include "tests/support/near_field_scenes.h"

#include <fmt/format.h>

namespace fissure::testing {

std::string tied_square_scene(const TiedSquare& s) {
  const std::string stress = fmt::format("[{:.17g} MPa, {:.17g} MPa, 0]", s.sxx, s.syy);
  const std::string prestress = s.prestressed ? "  initial_stress: " + stress + "\n" : "";
  const std::string blocks =
      s.rigid_dem ? "dem:\n  solve_ratio: 1e-10\n  max_cycles: 400000\n  damping: {local: 0.8}\n"
                  : "mechanics:\n  dda: {time_step: 100000 s, velocity_carry_over: 0, "
                    "max_displacement_ratio: 0.1}\n";
  const std::string stiffness =
      s.rigid_dem ? ", normal_stiffness: 500 GPa/m, shear_stiffness: 200 GPa/m" : "";
  return fmt::format(R"(name: {0}
physics: [continuum, {10}]
gravity: [0, 0]
materials:
  - {{name: rock, density: 2600 kg/m^3, young_modulus: 10 GPa, poisson_ratio: 0.25}}
joints:
  - {{name: glued, friction_angle: 40, cohesion: 100 MPa, tensile_strength: 100 MPa{11}}}
rock_mass:
  domain: [[-10, -10], [10, -10], [10, 10], [-10, 10]]
  material: rock
  joint_sets:
{1}
{2}{12}continuum:
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
                     s.top_extra, s.iteration, s.end, s.order, s.rigid_dem ? "dem" : "mechanics",
                     stiffness, blocks);
}

std::string tied_network_scene(const TiedNetwork& s) {
  return fmt::format(R"(name: {0}
physics: [continuum, flow]
gravity: [0, 0]
materials:
  - {{name: rock, density: 2600 kg/m^3, young_modulus: 10 GPa, poisson_ratio: 0.25}}
rock_mass:
  domain: [[-10, -10], [10, -10], [10, 10], [-10, 10]]
  material: rock
  joint_sets:
    - {{name: gentle, dip: 25, spacing: 6 m, aperture: 50 um}}
    - {{name: steep, dip: 105, spacing: 8 m, aperture: 50 um}}
flow:
  fluid: {{density: 1000 kg/m^3, viscosity: 1e-3 Pa*s}}
  network: {{source: rock_mass}}
  apertures: {{residual: 1 um}}
{5}continuum:
  domain: [[-50, -50], [50, -50], [50, 50], [-50, 50]]
  holes:
    - {{name: near_field, polygon: [[-10, -10], [10, -10], [10, 10], [-10, 10]]}}
  mesh: {{element_size: 10 m, fine_element_size: 2 m, size_grading: 0.3}}
  materials:
    - {{name: rock, biot_coefficient: 1e-6, biot_modulus: 10 GPa, permeability: {1}}}
  conditions:
    - {{boundary: left, displacement: [0, free]}}
    - {{boundary: bottom, displacement: [free, 0]}}
    - {{boundary: left, pressure: 1 MPa}}
    - {{boundary: right, pressure: 0 MPa}}
    - {{boundary: near_field, interface: [fluid_flow]}}
  scheme: monolithic
  time_step: {6}
coupling:
  scheme: iterated
  order: {2}
  iteration: {3}
time: {{end: {4}}}
output:
)",
                     s.name, s.permeability, s.order, s.iteration, s.end,
                     s.transient ? "  transient: {scheme: backward_euler}\n" : "", s.time_step);
}

namespace {
constexpr double kOpeningE = 10e9, kOpeningNu = 0.25, kOpeningSpacing = 2;
}  // namespace

double tied_opening_shear_modulus(const TiedOpening& s) {
  const double g = kOpeningE / (2 * (1 + kOpeningNu));
  const double kn = s.stiffness_ratio * kOpeningE / kOpeningSpacing;
  return 1 / (1 / g + 2 / (kn * kOpeningSpacing));
}

std::string tied_opening_scene(const TiedOpening& s) {
  const double kn = s.stiffness_ratio * kOpeningE / kOpeningSpacing;
  const double e_continuum = 2 * tied_opening_shear_modulus(s) * (1 + kOpeningNu);
  return fmt::format(R"(name: {0}
physics: [continuum, dem]
gravity: [0, 0]
materials:
  - {{name: rock, density: 2600 kg/m^3, young_modulus: 10 GPa, poisson_ratio: 0.25}}
  - {{name: jointed, density: 2600 kg/m^3, young_modulus: {1:.17g} Pa, poisson_ratio: 0.25}}
joints:
  - {{name: glued, friction_angle: 40, cohesion: 1000 MPa, tensile_strength: 1000 MPa,
     normal_stiffness: {2:.17g} Pa/m, shear_stiffness: {2:.17g} Pa/m}}
rock_mass:
  domain: [[-{5}, -{5}], [{5}, -{5}], [{5}, {5}], [-{5}, {5}]]
  material: rock
  excavations:
    - {{name: opening, circle: {{centre: [0, 0], radius: 2 m, segments: 48}}}}
  joint_sets:
    - {{name: flat, dip: 0, spacing: 2 m, joint: glued}}
    - {{name: steep, dip: 90, spacing: 2 m, joint: glued}}
  initial_stress: [-10 MPa, -10 MPa, 0]
monitors:
  - {{name: w15, point: [1.9318516525781366, 0.5176380902050415]}}
  - {{name: w30, point: [1.7320508075688772, 1.0000000000000002]}}
  - {{name: w45, point: [1.4142135623730951, 1.4142135623730951]}}
  - {{name: w60, point: [1.0000000000000002, 1.7320508075688772]}}
dem:
  zone_size: {3:.17g} m
  solve_ratio: 1e-7
  max_cycles: 400000
  density_scaling: true
continuum:
  domain: [[-200, -200], [200, -200], [200, 200], [-200, 200]]
  holes:
    - {{name: near_field, polygon: [[-{5}, -{5}], [{5}, -{5}], [{5}, {5}], [-{5}, {5}]]}}
  material: jointed
  mesh: {{element_size: 40 m, fine_element_size: 1 m, size_grading: 0.25}}
  materials:
    - {{name: jointed, biot_coefficient: 1e-6, biot_modulus: 10 GPa, permeability: 1e-18 m^2}}
  initial: {{stress: [-10 MPa, -10 MPa, 0]}}
  conditions:
    - {{boundary: left, displacement: [0, free]}}
    - {{boundary: bottom, displacement: [free, 0]}}
    - {{boundary: right, traction: [-10 MPa, 0]}}
    - {{boundary: top, traction: [0, -10 MPa]}}
    - {{boundary: near_field, interface: [traction]}}
  scheme: monolithic
  time_step: 1 s
coupling:
  scheme: lie
  order: [continuum, dem]
time: {{end: {4} s}}
output:
  every_steps: 1
)",
                     s.name, e_continuum, kn, s.zone_size, s.steps, s.half_width);
}

}  // namespace fissure::testing
