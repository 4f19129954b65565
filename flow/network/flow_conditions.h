// What the network solvers are told about a scene's flow (flow.conditions,
// flow.wells, flow.transient; docs/scene-reference.md section 11):
// conditions on named boundaries, wells, and the transient scheme. Part of
// the flow process's settings (flow/cubic_law/flow_controls.h).
#pragma once

#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "core/scene/time_history.h"

namespace fissure {

/// A condition on a named boundary of the fracture network (its nodes).
struct FlowBoundaryCondition {
  enum class Type { Pressure, Head, Flux };
  std::string boundary;  ///< "left", "exterior", a region name, ...
  Type type = Type::Pressure;
  double value = 0;     ///< Pa (pressure), m (head), m^2/s (flux: total into the network)
  TimeHistory history;  ///< (t, factor); factor 1 when empty
  std::string path;     ///< "flow.conditions[0]" with file:line:column, for messages
};

/// A well: a volume rate injected (> 0) or extracted (< 0) at a point of the network.
struct FlowWell {
  std::string name;
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  double rate = 0;  ///< m^2/s per unit thickness
  TimeHistory history;
  std::string path;
};

/// flow.transient (theory.md 3.4).
struct TransientControls {
  enum class Scheme { Cvode, Bdf2, BackwardEuler, Explicit };
  Scheme scheme = Scheme::Cvode;
  double time_step = 0;              ///< largest flow step, s; 0 = the coordinator's step
  double relative_tolerance = 1e-6;  ///< cvode
  double absolute_tolerance = 1.0;   ///< cvode, Pa
};

}  // namespace fissure
