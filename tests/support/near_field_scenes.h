// A 20 m x 20 m square of DDA blocks tied through the interface `near_field`
// to a 100 m x 100 m continuum of the same rock (E = 10 GPa, nu = 0.25, no
// gravity), loaded on the continuum's right and top sides with rollers on
// the left and bottom, iterated with the continuum first (docs/architecture.md
// 5, "A discrete region inside the continuum"): the scene of the near-field
// tests (verification.NearFieldCoupling.*, robustness.CheckpointRestart.*).
#pragma once

#include <string>

namespace fissure::testing {

struct TiedSquare {
  std::string name = "tied_square";
  /// rock_mass.joint_sets items, each a line "    - {...}" (joint `glued`:
  /// cohesion and tensile strength 100 MPa).
  std::string joint_sets;
  /// sxx and syy of the continuum's right and top loads, MPa; also the
  /// initial stress of both when `prestressed`.
  double sxx = 0, syy = 0;
  bool prestressed = false;
  /// Appended to the top load's condition, e.g. ", history: [...]".
  std::string top_extra;
  /// The coupling.iteration map, as one YAML flow map.
  std::string iteration = "{tolerance: 1e-10, max_iterations: 100, relaxation: quasi_newton}";
  /// coupling.order.
  std::string order = "[continuum, mechanics]";
  /// Rigid DEM blocks (process `dem`, solved to an unbalanced-force ratio of
  /// 1e-10; joints 500 GPa/m) instead of the DDA's.
  bool rigid_dem = false;
  /// One step of 1e5 s (long: the DDA's static step keeps an inertia
  /// 2 M / dt^2, 1e-14 of the stiffness then), or more.
  std::string end = "100000 s";
};

std::string tied_square_scene(const TiedSquare& s);

// Water through the same square: two joint sets of 50 um (a fracture network
// of the rock mass, cubic law) in the hole of a 100 m x 100 m continuum of
// permeability `permeability`, the network's mouths tied through
// `near_field` (flow/cubic_law/flow_ties.h); 1 MPa on the continuum's left,
// 0 on its right, no flow across top and bottom; steady (steps of 1e12 s,
// 1e-6 of the continuum's diffusion time).
struct TiedNetwork {
  std::string name = "tied_network";
  std::string permeability = "1e-15 m^2";
  /// The coupling.iteration map, as one YAML flow map.
  std::string iteration = "{tolerance: 1e-12, max_iterations: 200, relaxation: quasi_newton}";
  std::string order = "[continuum, flow]";
  /// The continuum's step, and with `transient` the network's water stored
  /// too (backward Euler, one step per update).
  std::string time_step = "1e12 s";
  bool transient = false;
  std::string end = "3e12 s";
};

std::string tied_network_scene(const TiedNetwork& s);

// A circular opening (radius 2 m, 48 segments) in a square of deformable
// DEM blocks (`zone_size`; 2 half_width wide), cut every 2 m by two orthogonal
// sets of glued joints with k_n = k_s = `stiffness_ratio` E / s, under an
// isotropic in-situ stress of -10 MPa held by a 400 m continuum whose shear
// modulus is the jointed rock's, 1/G_eq = 1/G + 2/(k_n s) (E = 10 GPa, nu =
// 0.25 both), tied through `near_field` for traction; Lie steps of 1 s
// (static: the DEM solves each to an unbalanced-force ratio of 1e-7). Four
// monitors on the opening's wall at 15, 30, 45 and 60 degrees.
struct TiedOpening {
  std::string name = "tied_opening";
  double stiffness_ratio = 100;  ///< k_n s / E
  double zone_size = 0.5;        ///< m
  double half_width = 6;         ///< m
  int steps = 3;
};

std::string tied_opening_scene(const TiedOpening& s);
/// The shear modulus of its jointed rock, G_eq (Pa).
double tied_opening_shear_modulus(const TiedOpening& s);

}  // namespace fissure::testing
