// The scene's `dem` section (docs/scene-reference.md "dem", docs/dem.md):
// the explicit distinct-element method's controls, validated, in SI units.
// Read by read_dem_settings.cpp; each default is written here, once.
#pragma once

#include <optional>

#include "core/base/named_values.h"
#include "core/scene/scene.h"
#include "core/scene/scene_section.h"

namespace fissure::dem {

/// dem
struct DemControls {
  /// UDEC's rounding length d (m): every convex corner is an arc tangent to
  /// its edges at d from it. Empty: 1 % of the blocks' median edge length.
  std::optional<double> rounding;
  SourceLocation rounding_location;  ///< for the error of a rounding longer than an edge
  /// Contacts are listed within this gap (m). Empty: the rounding length.
  std::optional<double> margin;
  /// The cycle's time step (s). Empty: safety_factor x the critical step,
  /// recomputed at every update from the contacts' current stiffness.
  std::optional<double> time_step;
  SourceLocation time_step_location;  ///< for the error of a step above the critical one
  double safety_factor = 0.5;         ///< of the critical step, in (0, 1]
  /// Cundall's local damping alpha: 0.8 (UDEC's default) for quasi-static
  /// runs, 0 (`damping: none`, or Rayleigh's) for dynamic ones.
  double local_damping = 0.8;
  /// Rayleigh damping (`damping: {rayleigh: ...}`, docs/dem.md section 10):
  /// C = a M + b K, a (1/s) on the masses, b (s) on the contacts' and the
  /// zones' stiffness; the damping ratio xi(omega) = a / (2 omega) + b omega / 2.
  double mass_damping = 0;
  double stiffness_damping = 0;
  /// Cycles per update (the process's step in the coupling), when the
  /// update is not solved to a ratio.
  long cycles_per_step = 100;
  /// Quasi-static mode: each update cycles (in pseudo-time) until the
  /// unbalanced-force ratio is below this value (UDEC's "solve ratio"),
  /// at most max_cycles. Empty: dynamic, cycles_per_step cycles of real time.
  std::optional<double> solve_ratio;
  long max_cycles = 100000;
  /// Quasi-static mode only: every block's inertia raised so that all
  /// blocks share the largest natural critical step (UDEC's density
  /// scaling; the weights stay the blocks' own).
  bool density_scaling = false;
  /// Deformable blocks: every free block meshed into triangular zones of
  /// at most this size (m), of its material's E, nu and density (UDEC's
  /// fully deformable blocks, docs/dem.md section 9). Empty: rigid blocks.
  std::optional<double> zone_size;
};

/// Where the scene keeps the section (Scene::sections).
inline constexpr Key<DemControls> kDemSettings{"dem"};
/// The reader of the section (the registry's row of the DEM process).
extern const SectionReader kDemSection;

}  // namespace fissure::dem
