// The keys of every map of a scene that core/scene reads (the keys all
// modules share): the single list that the parser reads from (ConfigMap
// refuses a key not in its table) and that the documentation test checks
// against docs/scene-reference.md. Each module lists the keys of its own
// section next to its reader (SectionReader::keys).
#pragma once

#include <span>
#include <string>
#include <vector>

#include "core/scene/config_map.h"

namespace fissure {

namespace scene_keys {
extern const KeyTable top;              ///< the document's shared keys (modules add their sections)
extern const KeyTable material;         ///< materials[]
extern const KeyTable joint;            ///< joints[]
extern const KeyTable block;            ///< blocks[]
extern const KeyTable fixed_point;      ///< fixed_points[]
extern const KeyTable point_load;       ///< point_loads[]
extern const KeyTable monitor;          ///< monitors[]
extern const KeyTable coupling;         ///< coupling
extern const KeyTable iteration;        ///< coupling.iteration
extern const KeyTable field_tolerance;  ///< coupling.iteration.fields.<field>
extern const KeyTable initial_equilibrium;  ///< coupling.initial_equilibrium
extern const KeyTable quasi_static;         ///< coupling.quasi_static
extern const KeyTable time;                 ///< time
extern const KeyTable output;               ///< output
/// The `solver` map of a module's section: type, tolerance, iteration
/// limit, PETSc options (read_linear_solver.h).
extern const std::span<const std::string_view> linear_solver;
/// The same and `refinement`, for a section whose direct solvers can refine
/// (the continuum's).
extern const std::span<const std::string_view> refined_linear_solver;
}  // namespace scene_keys

/// The shared keys with their full documented paths: "name",
/// "materials[].density", "coupling.order", ...
std::span<const KeyTable* const> shared_key_tables();

}  // namespace fissure
