// Thermal scenes built in code for the thermal tests: blocks of one
// material, the thermal process alone, stepped directly (no coordinator),
// and the temperature at any point of the block meshes.
#pragma once

#include <memory>
#include <vector>

#include "core/scene/scene.h"
#include "core/state/rock_mass.h"
#include "tests/support/run_scene.h"
#include "thermal/conduction/thermal_process.h"

namespace fissure::testing {

/// A scene with these blocks (counter-clockwise outer loops) of one material
/// with these thermal properties, `physics: [thermal]`.
Scene thermal_scene(const std::vector<std::vector<Vec2>>& blocks, const ThermalControls& controls,
                    const ThermalMaterial& material);

struct ThermalRun {
  explicit ThermalRun(const Scene& scene);
  /// `steps` steps of dt from the current time.
  void run(double dt, int steps);
  /// The thermal process's inner state.
  const thermal::ThermalState& thermal() const;
  /// The temperature at a point of the reference geometry (degC);
  /// NaN outside the meshes.
  double temperature_at(const Vec2& p) const;

  Scene scene;
  RockMass state;
  std::unique_ptr<thermal::ThermalProcess> process;
};

/// The thermal process's inner state after a run through the coordinator
/// (run_scene.h).
const thermal::ThermalState& thermal_state(const RunResult& run);

/// The line-source set-up of verification.md (l): a 1 kW/m point heater
/// "heater" at the origin, BDF2, elements of h, of h_source at the heater
/// growing by `grading` per metre from it, the rock at `initial` degC.
ThermalControls line_source_controls(double h, double h_source, double grading, double initial);

/// Corners of the box [x0, x1] x [y0, y1], counter-clockwise.
std::vector<Vec2> box(double x0, double y0, double x1, double y1);

}  // namespace fissure::testing
