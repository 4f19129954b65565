// The keys of every map in a scene file: the single list that the parser
// reads from (ConfigMap refuses a key not in its table) and that the
// documentation test checks against docs/scene-reference.md.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/scene/config_map.h"

namespace fissure {

namespace scene_keys {
extern const KeyTable top;          ///< the document
extern const KeyTable material;     ///< materials[]
extern const KeyTable joint;        ///< joints[]
extern const KeyTable block;        ///< blocks[]
extern const KeyTable fixed_point;  ///< fixed_points[]
extern const KeyTable point_load;   ///< point_loads[]
extern const KeyTable monitor;      ///< monitors[]
extern const KeyTable mechanics;    ///< mechanics
extern const KeyTable dda;          ///< mechanics.dda
extern const KeyTable solver;       ///< mechanics.dda.solver
extern const KeyTable time;         ///< time
extern const KeyTable output;       ///< output
extern const KeyTable rock_mass;        ///< rock_mass
extern const KeyTable excavation;       ///< rock_mass.excavations[]
extern const KeyTable circle;           ///< rock_mass.excavations[].circle
extern const KeyTable joint_set;        ///< rock_mass.joint_sets[]
extern const KeyTable dfn_family;       ///< rock_mass.dfn[]
extern const KeyTable dfn_density;      ///< rock_mass.dfn[].density
extern const KeyTable dfn_orientation;  ///< rock_mass.dfn[].orientation
extern const KeyTable dfn_length;       ///< rock_mass.dfn[].length
extern const KeyTable dfn_aperture;     ///< rock_mass.dfn[].aperture
extern const KeyTable fracture;         ///< rock_mass.fractures[]
extern const KeyTable fixed_blocks;     ///< rock_mass.fixed_blocks
// flow (docs/scene-reference.md section 11)
extern const KeyTable flow;             ///< flow
extern const KeyTable flow_fluid;       ///< flow.fluid
extern const KeyTable flow_apertures;   ///< flow.apertures
extern const KeyTable flow_network;     ///< flow.network
extern const KeyTable flow_trace;       ///< flow.network.traces[]
extern const KeyTable flow_region;      ///< flow.regions[]
extern const KeyTable flow_condition;   ///< flow.conditions[]
extern const KeyTable flow_well;        ///< flow.wells[]
extern const KeyTable flow_transient;   ///< flow.transient
extern const KeyTable flow_hm;          ///< flow.hm
extern const KeyTable flow_solver;      ///< flow.solver
}  // namespace scene_keys

/// Every key a scene may hold, with its full documented path:
/// "name", "materials[].density", "mechanics.dda.time_step", ...
std::vector<std::string> known_scene_keys();

/// The physics names a scene may list under `physics` (the processes that
/// coupling/process_registry.cpp can build).
std::span<const std::string_view> scene_physics_names();

}  // namespace fissure
