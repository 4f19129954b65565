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
}  // namespace scene_keys

/// Every key a scene may hold, with its full documented path:
/// "name", "materials[].density", "mechanics.dda.time_step", ...
std::vector<std::string> known_scene_keys();

/// The physics names a scene may list under `physics` (the processes that
/// coupling/process_registry.cpp can build).
std::span<const std::string_view> scene_physics_names();

}  // namespace fissure
