#include "core/scene/scene_keys.h"

namespace fissure {

namespace {

constexpr std::string_view kTop[] = {
    "name",         "physics",     "gravity",  "materials", "joints", "default_joint", "blocks",
    "fixed_points", "point_loads", "monitors", "mechanics", "time",   "output"};
constexpr std::string_view kMaterial[] = {"name", "density", "young_modulus", "poisson_ratio"};
constexpr std::string_view kJoint[] = {"name", "friction_angle", "cohesion", "tensile_strength"};
constexpr std::string_view kBlock[] = {"name",  "material", "joint",          "vertices",
                                       "holes", "fixed",    "initial_stress", "initial_velocity"};
constexpr std::string_view kFixedPoint[] = {"point", "block", "directions"};
constexpr std::string_view kPointLoad[] = {"point", "block", "force", "history"};
constexpr std::string_view kMonitor[] = {"name", "point", "block"};
constexpr std::string_view kMechanics[] = {"method", "plane", "dda"};
constexpr std::string_view kDda[] = {"time_step",
                                     "max_displacement_ratio",
                                     "penalty",
                                     "penalty_factor",
                                     "shear_penalty_ratio",
                                     "velocity_carry_over",
                                     "max_open_close_iterations",
                                     "exact_rotation",
                                     "solver"};
constexpr std::string_view kSolver[] = {"type", "relative_tolerance", "max_iterations",
                                        "petsc_options"};
constexpr std::string_view kTime[] = {"end", "max_steps", "min_step"};
constexpr std::string_view kOutput[] = {"interval", "every_steps", "hdf5"};

constexpr std::string_view kPhysics[] = {"mechanics"};

}  // namespace

namespace scene_keys {
const KeyTable top{"", kTop};
const KeyTable material{"materials[]", kMaterial};
const KeyTable joint{"joints[]", kJoint};
const KeyTable block{"blocks[]", kBlock};
const KeyTable fixed_point{"fixed_points[]", kFixedPoint};
const KeyTable point_load{"point_loads[]", kPointLoad};
const KeyTable monitor{"monitors[]", kMonitor};
const KeyTable mechanics{"mechanics", kMechanics};
const KeyTable dda{"mechanics.dda", kDda};
const KeyTable solver{"mechanics.dda.solver", kSolver};
const KeyTable time{"time", kTime};
const KeyTable output{"output", kOutput};
}  // namespace scene_keys

std::vector<std::string> known_scene_keys() {
  const KeyTable* tables[] = {
      &scene_keys::top,     &scene_keys::material,    &scene_keys::joint,
      &scene_keys::block,   &scene_keys::fixed_point, &scene_keys::point_load,
      &scene_keys::monitor, &scene_keys::mechanics,   &scene_keys::dda,
      &scene_keys::solver,  &scene_keys::time,        &scene_keys::output};
  std::vector<std::string> keys;
  for (const KeyTable* t : tables)
    for (std::string_view k : t->keys)
      keys.push_back(t->section.empty() ? std::string(k)
                                        : std::string(t->section) + "." + std::string(k));
  return keys;
}

std::span<const std::string_view> scene_physics_names() {
  return kPhysics;
}

}  // namespace fissure
