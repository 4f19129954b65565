// The scene's `flow` section (docs/scene-reference.md section 11, docs/flow.md):
// cubic-law fracture network flow (theory.md 3) and its coupling with the
// block mechanics (theory.md 3.5, 6). Validated values in SI units; read by
// core/scene/read_flow.cpp, used by flow/.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/linear/linear_solver_controls.h"

namespace fissure {

/// A condition on a named boundary of the fracture network (its nodes).
struct FlowBoundaryCondition {
  enum class Type { Pressure, Head, Flux };
  std::string boundary;  ///< "left", "exterior", a region name, ...
  Type type = Type::Pressure;
  double value = 0;  ///< Pa (pressure), m (head), m^2/s (flux: total into the network)
  std::vector<std::pair<double, double>> history;  ///< (t, factor); factor 1 when empty
  std::string path;  ///< "flow.conditions[0]" with file:line:column, for messages
};

/// A well: a volume rate injected (> 0) or extracted (< 0) at a point of the network.
struct FlowWell {
  std::string name;
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  double rate = 0;  ///< m^2/s per unit thickness
  std::vector<std::pair<double, double>> history;
  std::string path;
};

/// A named region: the network nodes inside the box form a boundary of that name.
struct FlowRegion {
  std::string name;
  Eigen::Vector2d min = Eigen::Vector2d::Zero(), max = Eigen::Vector2d::Zero();
};

/// An explicit fracture trace (network source `traces`).
struct FlowTrace {
  Eigen::Vector2d from = Eigen::Vector2d::Zero(), to = Eigen::Vector2d::Zero();
  double aperture = 0;  ///< e0, m
};

struct FlowControls {
  // Fluid (theory.md 3.1, 3.4).
  double density = 1000;        ///< kg/m^3
  double viscosity = 1e-3;      ///< Pa s
  double bulk_modulus = 2.2e9;  ///< Pa
  bool gravity = true;          ///< heads: p* = p - rho g.x with the scene's gravity

  // Apertures (theory.md 3.1).
  double initial_aperture = 1e-4;   ///< e0 where the network source gives none, m
  double residual_aperture = 1e-6;  ///< e_res, m
  double maximum_aperture = 0;      ///< e_max, m; 0 = no cap

  // Network.
  enum class NetworkSource { Blocks, Traces, RockMass };
  NetworkSource network = NetworkSource::Blocks;
  std::optional<std::pair<Eigen::Vector2d, Eigen::Vector2d>> domain;  ///< traces: clip box
  std::vector<FlowTrace> traces;
  std::vector<FlowRegion> regions;

  // Conditions and initial state.
  std::vector<FlowBoundaryCondition> conditions;
  std::vector<FlowWell> wells;
  double initial_pressure = 0;         ///< Pa
  std::optional<double> initial_head;  ///< m: hydrostatic start instead of initial_pressure

  // Transient (theory.md 3.4); steady when not set.
  struct Transient {
    enum class Scheme { Cvode, Bdf2, BackwardEuler, Explicit };
    Scheme scheme = Scheme::Cvode;
    double time_step = 0;              ///< largest flow step, s; 0 = the coordinator's step
    double relative_tolerance = 1e-6;  ///< cvode
    double absolute_tolerance = 1.0;   ///< cvode, Pa
  };
  std::optional<Transient> transient;

  // Hydro-mechanical coupling (theory.md 3.1, 3.5, 6), with mechanics only.
  struct Hm {
    double normal_stiffness = 0;   ///< k_n of the aperture law u_n = -sigma_n' / k_n, Pa/m
    double dilation_angle = 0;     ///< psi, rad
    double dilation_limit = 0;     ///< shear displacement beyond which dilation stops, m; 0 = none
    double coupling_interval = 0;  ///< flow step of the Lie splitting, s; 0 = every mechanics step
  };
  Hm hm;

  /// Linear solver of the network systems (type, tolerance, PETSc options).
  /// Network systems span conductances of ~1e9: a tighter tolerance and a
  /// larger iteration limit than the DDA's.
  LinearSolverControls solver{LinearSolverControls::Type::Auto, 1e-12, 5000, {}};
};

}  // namespace fissure
