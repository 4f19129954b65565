// One REV domain under stress (docs/upscaling.md section 2; after Min,
// Rutqvist, Tsang and Jing 2004): the square's traces are cut into blocks
// (the rock mass's cutter), every block starts at the effective stress
// sigma' = sigma + p I (tension +, Biot's alpha 1 on the joints) with its
// contacts prestressed by it, the right and top sides are loaded by the
// same stress (a pressure -n.sigma'.n on every block edge along them: the
// square is aligned with the principal axes, so the sides carry no shear),
// the left and bottom sides rest on rollers (one fixed L-shaped platen on a
// stiff frictionless joint, prestressed too; Min et al.'s boundary
// conditions),
// and the scene's block process brings the blocks to rest (the DEM solved
// to its ratio). Joints that cannot carry their share slip (and dilate) until the
// blocks are in equilibrium again. Then every fracture segment takes its
// hydraulic aperture from the walls and the contacts by its joint's
// aperture law (flow/hm, as the coupled flow does), a fracture piece inside
// one block (a trace end that cuts no block off) from the block's stress
// resolved on it, and the deformed network's permeability tensor is
// measured as the geometric study's (flow/rev/permeability.h).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/scene/scene.h"
#include "flow/hm/joint_apertures.h"
#include "flow/rev/rev_study.h"
#include "rockmass/fracture_trace.h"

namespace fissure {

/// What every domain of a stress stage shares.
struct StressedDomainSetup {
  /// The scene of the rock mass, without its generated blocks: materials,
  /// joints, the rock mass's material and tolerances, the block process's
  /// section.
  const Scene* scene = nullptr;
  std::string process = "dem";  ///< the block process that brings the blocks to rest
  int platen_joint = 0;         ///< the rollers' joint (of the scene's joints)
  /// flow.hm's aperture law: that of the fractures whose joint has no model.
  flow::HmApertureLaw aperture_law;
  double viscosity = 1e-3;     ///< Pa s
  double pressure_drop = 1e6;  ///< Pa
  /// The compliance's stress increment (Pa): the square as cut, floating
  /// under its stress on all four sides, takes it along x, along y
  /// (compression) and in shear, each solved to rest, and the moves between
  /// opposite sides give the 3x3 tangent compliance (docs/upscaling.md
  /// section 2, step 7). 0: not measured.
  double compliance_increment = 0;
};

/// The permeability (in the square's frame) of the square of side `size`
/// whose traces (in its frame, unclipped) are `traces`, under the
/// effective stress `stress` (sxx, syy, Pa, tension +; principal along the
/// square's sides).
flow::DomainSolution solve_stressed_domain(const StressedDomainSetup& setup,
                                           const std::vector<FractureTrace>& traces, double size,
                                           const Eigen::Vector2d& stress);

}  // namespace fissure
