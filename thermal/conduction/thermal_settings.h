// The scene's `thermal` section (docs/scene-reference.md section 12,
// docs/thermal.md): heat conduction in the blocks (theory.md 4.1). Validated
// values in SI units (temperatures in degC, differences in K); read by
// read_thermal_settings.cpp; each default is written here, once.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/base/named_values.h"
#include "core/geometry/vec2.h"
#include "core/scene/scene.h"
#include "core/scene/scene_section.h"
#include "core/scene/time_history.h"
#include "thermal/convection/convection_settings.h"

namespace fissure {

/// Thermal properties of one material of the scene (thermal.materials[]).
struct ThermalMaterial {
  /// lambda: xx, yy, xy in W/(m K) (isotropic: xx = yy, xy = 0).
  Eigen::Vector3d conductivity = Eigen::Vector3d(3, 3, 0);
  double heat_capacity = 2.5e6;  ///< volumetric rho c, J/(m^3 K)
  /// Linear thermal expansion alpha_T (1/K): the free strain per kelvin of
  /// the block's temperature change, published for the mechanics as
  /// block_thermal_strain (theory.md 4.3). 0: no thermal strain.
  double thermal_expansion = 0;
};

/// A periodic temperature (daily or seasonal), added to a condition's:
/// amplitude cos(2 pi (t - peak) / period); none while the amplitude is 0.
struct TemperatureCycle {
  double amplitude = 0;  ///< K
  double period = 0;     ///< s
  double peak = 0;       ///< a time of the maximum, s
  double at(double t) const;
};

/// A heat source (thermal.sources[]): a point (a line source across the
/// plane, W per metre of thickness), a segment in the plane (W/m of
/// thickness, spread evenly along it) or a polygon (W/m, spread evenly over
/// its area). Its power is `power` times the history factor at t.
struct HeatSource {
  enum class Shape { Point, Line, Area };
  std::string name;
  Shape shape = Shape::Point;
  std::vector<Vec2> points;  ///< 1 (point), 2 (line) or the polygon (counter-clockwise)
  double power = 0;          ///< W per metre of thickness
  TimeFactor factor;         ///< of the power
  std::string path;          ///< "file:line:column: thermal.sources[0]", for run-time messages
};

/// A condition on a named boundary (thermal.conditions[]). Its temperature
/// (fixed or external) or flux is the value times `factor` at t, plus the
/// `cycle` for a temperature; the transfer coefficient is constant.
struct ThermalCondition {
  enum class Type { Temperature, Flux, Convection };
  std::string boundary;  ///< left, right, bottom, top, exterior, or an excavation's name
  Type type = Type::Temperature;
  double value = 0;                 ///< degC (temperature), W/m^2 into the rock (flux), h W/(m^2 K)
  double external_temperature = 0;  ///< T_ext of a convective condition, degC
  TimeFactor factor;
  TemperatureCycle cycle;
  std::string path;

  /// The fixed temperature (degC) or the flux (W/m^2) at t.
  double value_at(double t) const;
  /// T_ext (degC) at t.
  double external_temperature_at(double t) const;
};

struct ThermalControls {
  std::vector<ThermalMaterial> materials;  ///< per scene material (index of Scene::materials)

  // Mesh (docs/thermal.md 2).
  double element_size = 0;  ///< h: largest edge of a triangle, m; 0: 1/20 of the rock's extent
  double source_element_size = 0;          ///< h at the heat sources; 0: element_size / 4
  double size_grading = 0.3;               ///< dh/dr away from the sources
  double max_elements = 2e6;               ///< larger estimated meshes are refused before meshing
  std::string mesh_path = "thermal.mesh";  ///< "file:line:column: thermal.mesh", for messages

  // Time integration (docs/thermal.md 3).
  enum class Scheme { BackwardEuler, Bdf2 };
  Scheme scheme = Scheme::BackwardEuler;
  bool lumped_capacity = true;
  double time_step = 0;  ///< s; 0: the coupling step (required when thermal runs alone)
  /// K: the largest nodal change a step may cause (the adaptive step,
  /// temperature_step_control.h; time_step is then the largest step); 0: off.
  double max_temperature_change = 0;

  // Initial temperature: T0 + gradient . (x - reference).
  double initial_temperature = 20;  ///< degC
  Vec2 gradient = Vec2::Zero();     ///< K/m
  Vec2 reference_point = Vec2::Zero();
  /// The initial temperature at x (degC).
  double initial_temperature_at(const Vec2& x) const {
    return initial_temperature + gradient.dot(x - reference_point);
  }

  /// Joints: the contact conductance h_c (W/(m^2 K)); perfect: the faces
  /// share their temperature.
  bool perfect_contact = true;
  double contact_conductance = 0;

  std::vector<ThermalCondition> conditions;
  std::vector<HeatSource> sources;

  /// The heat the fracture water carries (docs/thermal.md 7); none: the
  /// blocks conduct only.
  std::optional<FractureConvection> convection;
};

namespace thermal {
/// Where the scene keeps the section (Scene::sections).
inline constexpr Key<ThermalControls> kSettings{"thermal"};
/// The reader of the section (the registry's row of the thermal process).
extern const SectionReader kThermalSection;
}  // namespace thermal

/// The scene's thermal settings (section_settings).
inline ThermalControls& thermal_controls(Scene& scene) {
  return section_settings(scene, thermal::kSettings);
}
inline const ThermalControls& thermal_controls(const Scene& scene) {
  return section_settings(scene, thermal::kSettings);
}

}  // namespace fissure
