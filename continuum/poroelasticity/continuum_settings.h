// The scene's `continuum` section (docs/continuum.md, docs/scene-reference.md
// section 13): a saturated poro-thermo-elastic continuum on a meshed domain
// (theory.md 5), its materials, conditions and solution scheme. Validated
// values in SI units (temperatures in degC); read by
// read_continuum_settings.cpp; each default is written here, once.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "continuum/poroelasticity/permeability_law.h"
#include "core/base/enum_names.h"
#include "core/geometry/vec2.h"
#include "core/linear/linear_solver_controls.h"
#include "core/scene/scene.h"
#include "core/scene/scene_section.h"
#include "core/scene/time_history.h"

namespace fissure {

/// The poro-thermo-elastic properties of one material of the scene
/// (continuum.materials[]); E, nu and the density are the scene material's.
struct PoroMaterial {
  double young_modulus = 0;     ///< E, Pa (from `materials`)
  double poisson_ratio = 0;     ///< nu (from `materials`)
  double density = 0;           ///< of the saturated rock, kg/m^3 (from `materials`)
  double biot_coefficient = 1;  ///< alpha, in (0, 1]
  double biot_modulus = 0;      ///< M, Pa; 1/M = phi/K_f + (alpha - phi)/K_s
  /// Intrinsic permeability k, m^2: xx, yy, xy (isotropic: xx = yy, xy = 0).
  Eigen::Vector3d permeability = Eigen::Vector3d(1e-18, 1e-18, 0);
  /// Or a law of the stress (permeability_law.h): the tensor then follows
  /// each triangle's mean effective stress, and `permeability` is unused.
  std::optional<continuum::StressPermeabilityLaw> permeability_law;
  double thermal_expansion = 0;  ///< linear alpha_T of the solid, 1/K
  /// beta_m: the volumetric thermal expansion of the pore space that
  /// pressurizes the fluid (theory.md 5.1), 1/K.
  double fluid_thermal_expansion = 0;
  double conductivity = 2.5;     ///< lambda_m, W/(m K)
  double heat_capacity = 2.5e6;  ///< (rho c)_m, J/(m^3 K)

  double shear_modulus() const { return young_modulus / (2 * (1 + poisson_ratio)); }
  double lame_lambda() const {
    return young_modulus * poisson_ratio / ((1 + poisson_ratio) * (1 - 2 * poisson_ratio));
  }
  double bulk_modulus() const { return young_modulus / (3 * (1 - 2 * poisson_ratio)); }
};

/// A condition on a named boundary (continuum.conditions[]). Mechanical:
/// displacement components, a traction vector, a normal pressure on the
/// surface, or a rigid plate (every node's component along the plate's
/// direction is one unknown, loaded by a resultant force). Hydraulic: a
/// fluid pressure or an inflow. Thermal: a temperature, an inflow of heat, or
/// heat transfer to an ambient temperature (a convective, Robin condition).
/// Values are scaled by the history factor at t (of heat transfer, the
/// ambient temperature; the coefficient stays).
struct ContinuumCondition {
  enum class Type {
    Displacement,    ///< components `fix` to `vector`
    Traction,        ///< `vector`, Pa
    NormalPressure,  ///< `value`, Pa, pushing into the domain
    RigidPlate,      ///< component `axis`, resultant force `value` (N/m)
    FluidPressure,   ///< `value`, Pa
    FluidFlux,       ///< `value`, m/s into the domain
    Temperature,     ///< `value`, degC
    HeatFlux,        ///< `value`, W/m^2 into the domain
    /// Heat inflow h (T_inf - T): `coefficient` h, W/(m^2 K); `value` T_inf, degC.
    HeatTransfer,
    /// A coupling boundary (the shared field continuum_interfaces, named
    /// after the boundary): another process gives the quantities of
    /// `gives`; the continuum gives back displacements and fluxes.
    Interface,
  };
  std::string boundary;
  Type type = Type::Displacement;
  std::array<bool, 2> fix = {false, false};
  Vec2 vector = Vec2::Zero();
  double value = 0;
  double coefficient = 0;  ///< h of HeatTransfer, W/(m^2 K)
  /// Of FluidPressure and Temperature: the value at x is value + gradient . x
  /// (per metre; before the history factor).
  Vec2 gradient = Vec2::Zero();
  int axis = 1;  ///< 0: x, 1: y
  /// Of Interface: what the other process gives (a pressure or temperature
  /// given is prescribed at the boundary's vertices; not given, it is free;
  /// traction includes forces at points, fluid_flow and heat_flow are
  /// inflows at points: docs/continuum.md 4, "Interfaces").
  struct Gives {
    bool traction = false, pressure = false, temperature = false, fluid_flow = false,
         heat_flow = false;
  } gives;
  TimeFactor time_factor;  ///< `history` or `decay`
  std::string path;        ///< "file:line:column: continuum.conditions[0]", for messages

  double factor(double t) const { return time_factor.at(t); }
};

/// A source at a point (continuum.sources[]), a line source across the
/// plane (per metre of thickness) or a point on the axis (axisymmetric, in
/// all), times its factor of time at t (`history` or `decay`): of heat
/// (`power`, W/m or W), or of fluid (`fluid_rate`, m^3/s per m or m^3/s;
/// negative: extraction).
struct ContinuumSource {
  enum class Kind { Heat, Fluid };
  std::string name;
  Vec2 point = Vec2::Zero();
  Kind kind = Kind::Heat;
  /// Heat: the power, W/m (W axisymmetric). Fluid: the injection rate,
  /// m^3/s per m (m^3/s axisymmetric).
  double rate = 0;
  TimeFactor time_factor;  ///< `history` or `decay`
};

/// A named polygon: a hole in the domain (continuum.holes[]: a drift, a
/// shaft), or a named line of the domain's boundary (continuum.boundaries[]:
/// an arc of a quarter model), whose boundary edges take its name.
struct NamedOutline {
  std::string name;
  std::vector<Vec2> points;
};

/// A region of the domain with its own material (continuum.regions[]).
struct ContinuumRegion {
  std::string name;
  std::vector<Vec2> polygon;
  int material = 0;
};

struct ContinuumControls {
  /// The domain: its outer polygon (counter-clockwise); its sides are the
  /// boundaries left, right, bottom, top (of its bounding box) and exterior.
  std::vector<Vec2> domain;
  /// Axisymmetric about the y axis (x = r >= 0, y = z; loads and sources
  /// are totals over the ring), or plane strain (per metre of thickness).
  bool axisymmetric = false;
  /// continuum.elements: taylor_hood (P2/P1, the default) or p1p1 (equal
  /// order, unstable: for comparison only).
  bool linear_displacement = false;
  int material = 0;  ///< of the domain outside every region
  std::vector<ContinuumRegion> regions;
  std::vector<NamedOutline> holes;       ///< closed polygons inside the domain
  std::vector<NamedOutline> boundaries;  ///< open polylines along the domain's outline
  std::vector<PoroMaterial> materials;   ///< per scene material (index of Scene::materials)

  // Mesh (docs/continuum.md 2): a structured grid of the domain's bounding
  // box (a rectangle domain) with `divisions`, or triangles of `element_size`.
  std::array<int, 2> divisions = {0, 0};
  double element_size = 0;
  /// Near the sources, holes and named boundaries: h_f + grading x
  /// distance, at most element_size (0: element_size everywhere).
  double fine_element_size = 0;
  double size_grading = 0.3;
  /// Larger estimated meshes are refused before meshing: the direct solvers
  /// of this first version factor about 4.5 unknowns per triangle.
  double max_elements = 5e4;
  std::string mesh_path = "continuum.mesh";
  std::string conditions_path = "continuum.conditions";  ///< located, for messages

  // Fluid.
  double viscosity = 1e-3;  ///< mu, Pa s
  double fluid_density = 1000;

  // Initial state: stress (tension +), pressure and temperature, uniform
  // plus a gradient along y from `reference_y` (geostatic, hydrostatic,
  // geothermal).
  Eigen::Vector3d initial_stress = Eigen::Vector3d::Zero();
  Eigen::Vector3d initial_stress_gradient = Eigen::Vector3d::Zero();  ///< Pa/m along y
  double initial_pressure = 0, initial_pressure_gradient = 0;         ///< Pa, Pa/m
  double initial_temperature = 20, initial_temperature_gradient = 0;  ///< degC, K/m
  double reference_y = 0;
  double initial_pressure_at(double y) const {
    return initial_pressure + initial_pressure_gradient * (y - reference_y);
  }
  double initial_temperature_at(double y) const {
    return initial_temperature + initial_temperature_gradient * (y - reference_y);
  }
  /// The loads at t = 0 are applied at 0+: the first state is the
  /// undrained response to them (the Terzaghi and Mandel convention).
  bool undrained_start = true;

  std::vector<ContinuumCondition> conditions;
  std::vector<ContinuumSource> sources;

  // Solution (docs/continuum.md 3, theory.md 5.3).
  enum class Scheme { FixedStress, Monolithic, Drained, Undrained };
  /// Scheme's names in its order: the one table of the reader
  /// (read_continuum_settings.cpp) and of the writers (summary.json, messages).
  static constexpr EnumName<Scheme> kSchemeNames[] = {{"fixed_stress", Scheme::FixedStress},
                                                      {"monolithic", Scheme::Monolithic},
                                                      {"drained", Scheme::Drained},
                                                      {"undrained", Scheme::Undrained}};
  static std::string_view scheme_name(Scheme s) { return name_of(kSchemeNames, s); }
  Scheme scheme = Scheme::FixedStress;
  /// beta_FS = factor x alpha^2 / K_dr, K_dr = lambda + G (plane strain).
  double fixed_stress_factor = 1;
  /// tau = factor alpha^2 h^2 / (4 (lambda + 2G)) on int grad psi . grad
  /// (p - p_n) (Rodrigo, Gaspar, Hu and Zikatanov 2016): keeps the first steps
  /// after a load monotone when c dt << h^2, for both elements. It is O(h^2)
  /// but large in soft, tight rock (docs/continuum.md 3), so it is opt-in.
  /// 0: none.
  double pressure_stabilization = 0;
  /// The linear solvers (continuum_linear_solver.h): auto, direct or petsc;
  /// the Krylov solvers to 1e-12, below the staggered passes' 1e-10.
  LinearSolverControls solver{LinearSolverControls::Type::Auto, 1e-12, 2000, {}, {}, {}};
  double tolerance = 1e-10;   ///< relative increment of u and p per pass
  long max_iterations = 200;  ///< passes of a staggered scheme per step
  double time_step = 0;       ///< s; 0: the coupling step
  /// Backward Euler, or variable-step BDF2 (theory.md 5.4; the first step
  /// after the start is backward Euler).
  enum class TimeScheme { BackwardEuler, Bdf2 };
  TimeScheme time_scheme = TimeScheme::BackwardEuler;
  /// Heat is solved when a thermal condition (an interface given
  /// temperatures among them) or a heat source asks for it (a fluid source
  /// does not).
  /// Whether a material's permeability follows the stress (then every step
  /// iterates the tensors with the fields, stress_permeability.h).
  bool stress_dependent_permeability() const {
    for (const PoroMaterial& m : materials)
      if (m.permeability_law) return true;
    return false;
  }
  bool with_temperature() const {
    for (const ContinuumCondition& k : conditions)
      if (k.type == ContinuumCondition::Type::Temperature ||
          k.type == ContinuumCondition::Type::HeatFlux ||
          k.type == ContinuumCondition::Type::HeatTransfer ||
          (k.type == ContinuumCondition::Type::Interface &&
           (k.gives.temperature || k.gives.heat_flow)))
        return true;
    for (const ContinuumSource& s : sources)
      if (s.kind == ContinuumSource::Kind::Heat) return true;
    return false;
  }
};

namespace continuum {
/// Where the scene keeps the section (Scene::sections).
inline constexpr Key<ContinuumControls> kSettings{"continuum"};
/// The reader of the section (the registry's row of the continuum process).
extern const SectionReader kContinuumSection;
}  // namespace continuum

inline const ContinuumControls& continuum_controls(const Scene& scene) {
  return section_settings(scene, continuum::kSettings);
}
inline ContinuumControls& continuum_controls(Scene& scene) {
  return section_settings(scene, continuum::kSettings);
}

}  // namespace fissure
