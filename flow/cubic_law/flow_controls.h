// The scene's `flow` section (docs/scene-reference.md section 11, docs/flow.md):
// cubic-law fracture network flow (theory.md 3) and its coupling with the
// block mechanics (theory.md 3.5, 6). Validated values in SI units; read by
// read_flow_settings.cpp; each default is written here, once.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/base/named_values.h"
#include "core/linear/linear_solver_controls.h"
#include "core/scene/scene.h"
#include "core/scene/scene_section.h"
#include "flow/network/flow_conditions.h"
#include "flow/network/fluid.h"

namespace fissure {

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
  flow::FluidProperties fluid;  ///< flow.fluid (theory.md 3.1, 3.4)
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
  /// Where the scene chooses the network ("FILE:LINE:COLUMN: flow.network.source",
  /// or the traces, or the flow section for the default), for the messages of
  /// the checks that need the network built.
  std::string network_path;

  // Conditions and initial state.
  std::vector<FlowBoundaryCondition> conditions;
  std::vector<FlowWell> wells;
  double initial_pressure = 0;         ///< Pa
  std::optional<double> initial_head;  ///< m: hydrostatic start instead of initial_pressure

  // Transient (theory.md 3.4); steady when not set.
  using Transient = TransientControls;
  std::optional<Transient> transient;

  // Hydro-mechanical coupling (theory.md 3.1, 3.5, 6): apertures from the
  // walls of the moving blocks and their contacts, pressures as loads on the
  // blocks. Present exactly when the scene has mechanics (flow.hm).
  struct Hm {
    double normal_stiffness = 0;  ///< k_n of the aperture law u_n = -sigma_n' / k_n, Pa/m
    double dilation_angle = 0;    ///< psi, rad
    double dilation_limit = 0;    ///< shear displacement beyond which dilation stops, m; 0 = none
  };
  std::optional<Hm> hm;

  /// Linear solver of the network systems (type, tolerance, PETSc options).
  /// Network systems span conductances of ~1e9: a tighter tolerance and a
  /// larger iteration limit than the DDA's.
  LinearSolverControls solver{LinearSolverControls::Type::Auto, 1e-12, 5000, {}, {}, {}};
};

namespace flow {
/// Where the scene keeps the section (Scene::sections).
inline constexpr Key<FlowControls> kSettings{"flow"};
/// The reader of the section (the registry's row of the flow process).
extern const SectionReader kFlowSection;
}  // namespace flow

/// The scene's flow settings (section_settings).
inline FlowControls& flow_controls(Scene& scene) {
  return section_settings(scene, flow::kSettings);
}
inline const FlowControls& flow_controls(const Scene& scene) {
  return section_settings(scene, flow::kSettings);
}

}  // namespace fissure
