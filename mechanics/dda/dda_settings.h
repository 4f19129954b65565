// The scene's `mechanics` section (docs/scene-reference.md "mechanics"):
// the method, the plane mode and Shi's DDA controls (theory.md 1.7, 7.1),
// validated, in SI units. Read by read_dda_settings.cpp; each default is
// written here, once.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/base/named_values.h"
#include "core/linear/linear_solver_controls.h"
#include "core/scene/scene.h"
#include "core/scene/scene_section.h"
#include "mechanics/dda/ground_motion.h"

namespace fissure {

enum class PlaneMode { Stress, Strain };

/// How closed contacts are held (docs/dda.md section 11): penalty springs
/// alone (Shi), or augmented Lagrangian multipliers on top of them, updated
/// until penetrations and stuck contacts' slips are within a tolerance.
enum class ContactMethod { Penalty, AugmentedLagrangian };
/// Their names in the scene (`contact_method`) and in summary.json.
inline constexpr EnumName<ContactMethod> kContactMethodNames[] = {
    {"penalty", ContactMethod::Penalty},
    {"augmented_lagrangian", ContactMethod::AugmentedLagrangian}};

/// mechanics.dda
struct DdaControls {
  double max_time_step = 1e-3;            ///< g1, s
  double max_displacement_ratio = 0.005;  ///< g2: max step displacement / half model size
  std::optional<double> penalty;          ///< g0, N/m; empty = automatic
  double penalty_factor = 50;             ///< automatic penalty = factor * max E * 1 m
  double shear_penalty_ratio = 1.0;       ///< p_s / p_n
  double velocity_carry_over = 1.0;       ///< k01: 1 dynamic, 0 static
  double damping_ratio = 0.1;  ///< of the blocks' elastic vibration (vibration_damping.h)
  int max_open_close_iterations = 12;
  ContactMethod contact_method = ContactMethod::Penalty;
  /// Augmented Lagrangian: the largest penetration (and elastic slip of a
  /// stuck contact) a step may end with, m; empty: 1e-4 of the median
  /// block size.
  std::optional<double> penetration_tolerance;
  int max_augmentations = 20;  ///< multiplier updates per step
  /// Blocks faster than this count as ejected (ejected_blocks.h), m/s.
  double ejection_speed = 1.0;
  bool exact_rotation = true;  ///< geometry update without block inflation (theory.md 1.8)
  LinearSolverControls solver;
};

/// mechanics.ground_motion: a recorded base motion (ground_motion.h,
/// docs/dda.md section 10) that the driven blocks follow.
struct GroundMotionControls {
  dda::GroundMotionRecord record;  ///< SI, scaled
  double start = 0;                ///< scene time of the record's t = 0 (s)
  bool baseline_correction = true;
  /// Names of the fixed blocks that follow it; none given: every fixed
  /// block; an empty list: none (the motion enters through free-field
  /// boundaries only).
  std::optional<std::vector<std::string>> blocks;
};

/// mechanics.viscous_boundaries[]: Lysmer-Kuhlemeyer dashpots on the free
/// blocks' edges that lie on a line (viscous_boundary.h).
struct ViscousBoundaryControls {
  Vec2 from = Vec2::Zero(), to = Vec2::Zero();
  /// The medium beyond the boundary (its rho c_p, rho c_s); -1: each edge's
  /// own block's material.
  int material = -1;
  /// The ground motion enters through it: the dashpots act on the velocity
  /// relative to the record's (outcrop) velocity.
  bool free_field = false;
  SourceLocation location;
};

/// mechanics
struct MechanicsControls {
  PlaneMode plane = PlaneMode::Strain;
  DdaControls dda;
  std::optional<GroundMotionControls> ground_motion;
  std::vector<ViscousBoundaryControls> viscous_boundaries;
};

namespace dda {
/// Where the scene keeps the section (Scene::sections).
inline constexpr Key<MechanicsControls> kSettings{"mechanics"};
/// The reader of the section (the registry's row of the DDA process).
extern const SectionReader kMechanicsSection;
}  // namespace dda

/// The scene's mechanics settings (section_settings).
inline MechanicsControls& mechanics_controls(Scene& scene) {
  return section_settings(scene, dda::kSettings);
}
inline const MechanicsControls& mechanics_controls(const Scene& scene) {
  return section_settings(scene, dda::kSettings);
}

}  // namespace fissure
