#include "core/scene/scene_keys.h"

namespace fissure {

namespace {

constexpr std::string_view kTop[] = {
    "name",         "physics",     "gravity",  "materials", "joints", "default_joint", "blocks",
    "fixed_points", "point_loads", "monitors", "coupling",  "time",   "output"};
constexpr std::string_view kMaterial[] = {"name", "density", "young_modulus", "poisson_ratio"};
constexpr std::string_view kJoint[] = {"name", "friction_angle", "cohesion", "tensile_strength"};
constexpr std::string_view kBlock[] = {"name",  "material", "joint",          "vertices",
                                       "holes", "fixed",    "initial_stress", "initial_velocity"};
constexpr std::string_view kFixedPoint[] = {"point", "block", "directions"};
constexpr std::string_view kPointLoad[] = {"point", "block", "force", "history"};
constexpr std::string_view kMonitor[] = {"name", "point", "block"};
constexpr std::string_view kCoupling[] = {
    "scheme", "order", "intervals", "iteration", "initial_equilibrium", "quasi_static"};
constexpr std::string_view kIteration[] = {"tolerance", "max_iterations",      "relaxation",
                                           "omega",     "freeze_states_after", "fields"};
constexpr std::string_view kFieldTolerance[] = {"relative", "absolute"};
constexpr std::string_view kInitialEquilibrium[] = {"processes", "max_speed", "max_time"};
constexpr std::string_view kQuasiStatic[] = {"processes", "max_speed", "max_steps"};
constexpr std::string_view kTime[] = {"end", "max_steps", "min_step"};
constexpr std::string_view kOutput[] = {"interval", "every_steps", "hdf5", "checkpoint_steps",
                                        "checkpoint_wall_time"};
constexpr std::string_view kLinearSolver[] = {"type", "relative_tolerance", "max_iterations",
                                              "petsc_options"};
constexpr std::string_view kRefinedLinearSolver[] = {"type", "relative_tolerance", "max_iterations",
                                                     "petsc_options", "refinement"};

}  // namespace

namespace scene_keys {
const KeyTable top{"", kTop};
const KeyTable material{"materials[]", kMaterial};
const KeyTable joint{"joints[]", kJoint};
const KeyTable block{"blocks[]", kBlock};
const KeyTable fixed_point{"fixed_points[]", kFixedPoint};
const KeyTable point_load{"point_loads[]", kPointLoad};
const KeyTable monitor{"monitors[]", kMonitor};
const KeyTable coupling{"coupling", kCoupling};
const KeyTable iteration{"coupling.iteration", kIteration};
const KeyTable field_tolerance{"coupling.iteration.fields.FIELD", kFieldTolerance};
const KeyTable initial_equilibrium{"coupling.initial_equilibrium", kInitialEquilibrium};
const KeyTable quasi_static{"coupling.quasi_static", kQuasiStatic};
const KeyTable time{"time", kTime};
const KeyTable output{"output", kOutput};
const std::span<const std::string_view> linear_solver{kLinearSolver};
const std::span<const std::string_view> refined_linear_solver{kRefinedLinearSolver};
}  // namespace scene_keys

std::span<const KeyTable* const> shared_key_tables() {
  static const KeyTable* const tables[] = {&scene_keys::top,
                                           &scene_keys::material,
                                           &scene_keys::joint,
                                           &scene_keys::block,
                                           &scene_keys::fixed_point,
                                           &scene_keys::point_load,
                                           &scene_keys::monitor,
                                           &scene_keys::coupling,
                                           &scene_keys::iteration,
                                           &scene_keys::field_tolerance,
                                           &scene_keys::initial_equilibrium,
                                           &scene_keys::quasi_static,
                                           &scene_keys::time,
                                           &scene_keys::output};
  return tables;
}

}  // namespace fissure
