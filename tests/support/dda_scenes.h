// Scene builders shared by the DDA tests and benchmarks: the verification
// problems of verification.md (a)-(d) and the stability scenes of the
// foundation issue (brick wall, block on a slope), built directly as Scene
// values so that each test states its parameters in one place.
#pragma once

#include <string>

#include "core/scene/scene.h"

namespace fissure::testing {

/// Rectangle [0, w] x [0, h], rotated by `angle` (rad) about the origin, then
/// moved by `offset`.
Polygon rectangle(double w, double h, double angle = 0, const Vec2& offset = Vec2::Zero());

/// Scene with one material (rock: 2700 kg/m^3, E, nu = 0.25), one joint
/// (friction angle phi, no cohesion or tension), gravity (0, -g), mechanics
/// with DDA defaults, plane strain.
Scene base_scene(double young_modulus = 10e9, double friction_deg = 30, double g = 9.81);

BlockSpec block(const std::string& name, Polygon polygon, bool fixed = false);

/// Block of width x height (1 x 0.5 m) on a fixed plane inclined by
/// `slope_deg`, starting at rest; monitor "block" at its centroid. Geometry
/// is inclined, not gravity.
Scene incline_scene(double slope_deg, double friction_deg, double dt, double penalty,
                    double end_time, double width = 1.0, double height = 0.5);

/// Staggered wall of `courses` x `bricks` bricks (w x h) on a fixed base
/// under gravity; odd courses are offset by half a brick (with half bricks at
/// the ends). Monitor "top" at the centroid of the middle top brick.
Scene brick_wall_scene(int courses, int bricks, double w, double h, double friction_deg, double dt,
                       double penalty, double end_time);

/// Switches `s`'s contacts to augmented Lagrangian multipliers that hold
/// penetrations and stuck slips within `tolerance` (m; docs/dda.md section 11).
void use_augmented_lagrangian(Scene& s, double tolerance);

/// Grid of nx x ny square blocks (side a, gaps `gap`) dropped onto a fixed
/// floor under gravity: the settling scene for scaling runs.
Scene block_pile_scene(int nx, int ny, double a, double gap, double dt, double end_time);

/// A 1 x 0.5 m block `gap` above a fixed 3 x 1 m base under g = 9.81, for
/// static DDA steps of dt (k01 = 0: each step starts at rest, so the block
/// falls g dt^2 / 2 a step).
Scene block_above_base_scene(double gap, double dt);

}  // namespace fissure::testing
