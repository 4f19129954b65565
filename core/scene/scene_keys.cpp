#include "core/scene/scene_keys.h"

namespace fissure {

namespace {

constexpr std::string_view kTop[] = {"name",         "physics",       "gravity",  "materials",
                                     "joints",       "default_joint", "blocks",   "rock_mass",
                                     "fixed_points", "point_loads",   "monitors", "mechanics",
                                     "flow",         "time",          "output"};
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

// flow (read_flow.cpp, read_flow_conditions.cpp)
constexpr std::string_view kFlow[] = {"fluid",        "gravity",    "apertures", "network",
                                      "regions",      "conditions", "wells",     "initial_pressure",
                                      "initial_head", "transient",  "hm",        "solver"};
constexpr std::string_view kFlowFluid[] = {"density", "viscosity", "bulk_modulus"};
constexpr std::string_view kFlowApertures[] = {"initial", "residual", "maximum"};
constexpr std::string_view kFlowNetwork[] = {"source", "domain", "traces"};
constexpr std::string_view kFlowTrace[] = {"from", "to", "aperture"};
constexpr std::string_view kFlowRegion[] = {"name", "min", "max"};
constexpr std::string_view kFlowCondition[] = {"boundary", "pressure", "head", "flux", "history"};
constexpr std::string_view kFlowWell[] = {"name", "point", "rate", "history"};
constexpr std::string_view kFlowTransient[] = {"scheme", "time_step", "relative_tolerance",
                                               "absolute_tolerance"};
constexpr std::string_view kFlowHm[] = {"normal_stiffness", "dilation_angle", "dilation_limit",
                                        "coupling_interval"};

// rock_mass (read_rock_mass.cpp, read_rock_mass_sets.cpp)
constexpr std::string_view kRockMass[] = {
    "domain",    "excavations",     "material",   "seed",          "joint_sets",  "dfn",
    "fractures", "merge_tolerance", "max_blocks", "max_fractures", "fixed_blocks"};
constexpr std::string_view kExcavation[] = {"name", "circle", "vertices"};
constexpr std::string_view kCircle[] = {"centre", "radius", "segments"};
constexpr std::string_view kJointSet[] = {
    "name",          "dip",   "spacing", "spacing_spread", "trace_length",
    "bridge_length", "phase", "stagger", "joint",          "aperture"};
constexpr std::string_view kDfnFamily[] = {"name",   "density",  "orientation",
                                           "length", "aperture", "joint"};
constexpr std::string_view kDensity[] = {"p20", "p21"};
constexpr std::string_view kOrientation[] = {"distribution", "value", "mean", "kappa"};
constexpr std::string_view kLength[] = {"distribution", "value", "min",     "max",
                                        "mean",         "std",   "exponent"};
constexpr std::string_view kAperture[] = {"distribution", "value",  "mean",
                                          "std",          "factor", "exponent"};
constexpr std::string_view kFracture[] = {"from", "to", "joint", "aperture"};
constexpr std::string_view kFixedBlocks[] = {"boundaries", "below"};

constexpr std::string_view kPhysics[] = {"mechanics", "flow"};

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
const KeyTable flow{"flow", kFlow};
const KeyTable flow_fluid{"flow.fluid", kFlowFluid};
const KeyTable flow_apertures{"flow.apertures", kFlowApertures};
const KeyTable flow_network{"flow.network", kFlowNetwork};
const KeyTable flow_trace{"flow.network.traces[]", kFlowTrace};
const KeyTable flow_region{"flow.regions[]", kFlowRegion};
const KeyTable flow_condition{"flow.conditions[]", kFlowCondition};
const KeyTable flow_well{"flow.wells[]", kFlowWell};
const KeyTable flow_transient{"flow.transient", kFlowTransient};
const KeyTable flow_hm{"flow.hm", kFlowHm};
const KeyTable flow_solver{"flow.solver", kSolver};
const KeyTable rock_mass{"rock_mass", kRockMass};
const KeyTable excavation{"rock_mass.excavations[]", kExcavation};
const KeyTable circle{"rock_mass.excavations[].circle", kCircle};
const KeyTable joint_set{"rock_mass.joint_sets[]", kJointSet};
const KeyTable dfn_family{"rock_mass.dfn[]", kDfnFamily};
const KeyTable dfn_density{"rock_mass.dfn[].density", kDensity};
const KeyTable dfn_orientation{"rock_mass.dfn[].orientation", kOrientation};
const KeyTable dfn_length{"rock_mass.dfn[].length", kLength};
const KeyTable dfn_aperture{"rock_mass.dfn[].aperture", kAperture};
const KeyTable fracture{"rock_mass.fractures[]", kFracture};
const KeyTable fixed_blocks{"rock_mass.fixed_blocks", kFixedBlocks};
}  // namespace scene_keys

std::vector<std::string> known_scene_keys() {
  const KeyTable* tables[] = {
      &scene_keys::top, &scene_keys::material, &scene_keys::joint, &scene_keys::block,
      &scene_keys::fixed_point, &scene_keys::point_load, &scene_keys::monitor,
      &scene_keys::mechanics, &scene_keys::dda, &scene_keys::solver, &scene_keys::time,
      &scene_keys::output,
      // rock_mass
      &scene_keys::rock_mass, &scene_keys::excavation, &scene_keys::circle, &scene_keys::joint_set,
      &scene_keys::dfn_family, &scene_keys::dfn_density, &scene_keys::dfn_orientation,
      &scene_keys::dfn_length, &scene_keys::dfn_aperture, &scene_keys::fracture,
      &scene_keys::fixed_blocks,
      // flow
      &scene_keys::flow, &scene_keys::flow_fluid, &scene_keys::flow_apertures,
      &scene_keys::flow_network, &scene_keys::flow_trace, &scene_keys::flow_region,
      &scene_keys::flow_condition, &scene_keys::flow_well, &scene_keys::flow_transient,
      &scene_keys::flow_hm, &scene_keys::flow_solver};
  return documented_keys(tables);
}

std::span<const std::string_view> scene_physics_names() {
  return kPhysics;
}

}  // namespace fissure
