// The example scenes of configs/ run with the DDA and with the explicit DEM
// side by side (docs/verification.md, "DDA and DEM on the same scenes";
// benchmarks/dda_vs_dem): each is a config's own text with a few values
// changed, so the comparison follows the shipped scenes.
//
// The brick wall of brick_wall.yaml and dem_brick_wall.yaml as one model in
// both methods: rigid blocks on linear joints. The DDA's contact springs
// are point springs p at the block corners: a bed joint between two courses
// has a corner every 0.5 m with two springs at each (one of each brick
// meeting there), 4 p per metre, and the wall's base has two springs every
// metre (the bottom course's corners), 2 p per metre. With p = 2.5e9 N/m
// the DDA's joints are those of the DEM's k_n = 10 GPa/m, and its base that
// of a base joint of 5 GPa/m, which the DEM's scene is given; shear alike
// (the DDA's shear penalty is p). The DDA's blocks take E = 1 TPa, the
// largest modulus a scene takes, so that they are nearly rigid; their
// shortening is a closed form too (wall_blocks_shortening).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/scene/scene.h"

namespace fissure::testing {

/// One change of a config's text: the text, found exactly once, and what
/// replaces it.
using TextEdit = std::pair<std::string, std::string>;

/// configs/<stem>.yaml with `edits` applied, read as a scene (its output to
/// HDF5 off). A text found not exactly once throws std::runtime_error: the
/// config changed under the comparison.
Scene edited_config(const std::string& stem, const std::vector<TextEdit>& edits);

namespace wall {
inline constexpr double kDensity = 2700, kG = 9.81;
inline constexpr double kCourseHeight = 0.5, kHeight = 5.0;  ///< 10 courses
inline constexpr double kJointNormalStiffness = 10e9;        ///< Pa/m: dem_brick_wall.yaml's
inline constexpr double kBaseNormalStiffness = 5e9;          ///< Pa/m: the DDA's 2 p per metre
inline constexpr double kPenalty = 2.5e9;                    ///< N/m: k_n x 0.25 m
inline constexpr double kStiffYoungModulus = 1e12;           ///< Pa: the DDA's near-rigid blocks
inline constexpr double kPoissonRatio = 0.25;
}  // namespace wall

/// brick_wall.yaml as rigid blocks on linear joints (above): E = 1 TPa,
/// penalty 2.5e9 N/m, the DDA's step `time_step` (s) and velocity carry-over
/// k01 (0: static steps), to `end_time` (s), its one output there.
Scene stiff_wall_dda(double time_step, double velocity_carry_over, double end_time);

/// dem_brick_wall.yaml with the DDA's joints (above): k_s = k_n, and a base
/// joint of 5 GPa/m; `dem_controls` are added to its `dem` section (YAML
/// lines of two-space indent, e.g. "  solve_ratio: 1e-8\n"), to `end_time`,
/// its one output there.
Scene rigid_wall_dem(const std::string& dem_controls, double end_time);

/// The top brick's settlement from its joints (m): each bed joint k closes
/// by its overburden over its stiffness, rho g (H - y_k) / k_n, the base by
/// rho g H / k_base: rho g / k_n (sum_{k=1..9} (H - y_k) + 2 H) = 8.6083e-5.
double wall_joints_settlement();

/// The DDA's blocks' shortening under the top brick's centroid (m): each
/// brick strains uniformly under its mean overburden, in plane strain with
/// no lateral stress, (1 - nu^2) rho g (H - y_c) / E: 3.09e-7 at E = 1 TPa.
double wall_blocks_shortening(double young_modulus);

}  // namespace fissure::testing
