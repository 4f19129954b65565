// The scene's `thermal` section (docs/scene-reference.md section 12): the
// materials' conductivity, capacity and thermal expansion, the mesh, the
// time integration, the initial temperature and the joints. Conditions and
// sources are in read_thermal_conditions.cpp.
#include <fmt/format.h>

#include "core/scene/time_limits.h"
#include "rockmass/fields/block_thermal_strain.h"
#include "rockmass/heat_keys.h"
#include "rockmass/rock_mass_spec.h"
#include "thermal/conduction/read_thermal_settings.h"
#include "thermal/conduction/thermal_exchanged_fields.h"
#include "thermal/conduction/thermal_mesh.h"
#include "thermal/convection/read_convection_settings.h"

namespace fissure {

namespace {

constexpr std::string_view kThermal[] = {
    "materials", "mesh",   "scheme",     "capacity", "time_step", "max_temperature_change",
    "initial",   "joints", "conditions", "sources",  "convection"};
constexpr std::string_view kMaterial[] = {"name", "conductivity", "heat_capacity", "specific_heat",
                                          "thermal_expansion"};
constexpr std::string_view kMesh[] = {"element_size", "source_element_size", "size_grading",
                                      "max_elements"};
constexpr std::string_view kInitial[] = {"temperature", "temperature_gradient", "reference_point"};
constexpr std::string_view kJoints[] = {"conductance"};
const KeyTable thermal_table{"thermal", kThermal};
const KeyTable material_table{"thermal.materials[]", kMaterial};
const KeyTable mesh_table{"thermal.mesh", kMesh};
const KeyTable initial_table{"thermal.initial", kInitial};
const KeyTable joints_table{"thermal.joints", kJoints};
/// The linear thermal expansion was a key of the shared materials before the
/// thermal process owned it; the conditions' heat flux and convection and
/// the initial gradient took the continuum's spellings (the same keys for
/// the same things in both sections, rockmass/heat_keys.h).
constexpr MovedKey kMoved[] = {
    {"materials[].thermal_expansion", "thermal.materials[].thermal_expansion"},
    {"thermal.conditions[].flux", "thermal.conditions[].heat_flux"},
    {"thermal.conditions[].transfer_coefficient", "thermal.conditions[].heat_transfer.coefficient"},
    {"thermal.conditions[].external_temperature", "thermal.conditions[].heat_transfer.temperature"},
    {"thermal.initial.gradient", "thermal.initial.temperature_gradient"}};
const KeyTable* const kTables[] = {&thermal_table,
                                   &material_table,
                                   &mesh_table,
                                   &initial_table,
                                   &joints_table,
                                   &thermal::condition_table,
                                   &thermal::source_table,
                                   &thermal::cycle_table,
                                   &thermal::heat_transfer_table,
                                   &thermal::convection_table,
                                   &thermal::fluid_table,
                                   &thermal::inlet_table};

/// Conductivity: a number (isotropic) or [kxx, kyy, kxy], positive definite.
void read_conductivity(const ConfigNode& node, ThermalMaterial& m) {
  if (node.is_list()) {
    const QuantityKind* kinds[] = {&quantity::conductivity, &quantity::conductivity,
                                   &quantity::conductivity};
    const auto k = node.numbers(kinds, "[kxx, kyy, kxy]");
    if (!k) return;
    if (!((*k)[0] > 0 && (*k)[1] > 0 && (*k)[0] * (*k)[1] - (*k)[2] * (*k)[2] > 0)) {
      node.error(
          fmt::format("found {}; expected a positive definite tensor [kxx, kyy, kxy] "
                      "(kxx > 0, kyy > 0, kxx kyy > kxy^2)",
                      node.found()));
      return;
    }
    m.conductivity = {(*k)[0], (*k)[1], (*k)[2]};
  } else if (auto k = node.quantity(quantity::conductivity, Range::positive())) {
    m.conductivity = {*k, *k, 0};
  }
}

void read_materials(const ConfigNode& node, SectionContext& context, ThermalControls& c) {
  const Scene& scene = context.scene();
  const auto items = node.list("materials {name, conductivity, heat_capacity}", false);
  std::vector<bool> given(scene.materials.size(), false);
  c.materials.assign(scene.materials.size(), ThermalMaterial{});
  if (items) {
    for (const ConfigNode& item : *items) {
      ConfigMap map(item, material_table);
      const std::optional<int> index = context.material_entry(map, given);
      ThermalMaterial m;
      if (auto n = map.required("conductivity", "a conductivity > 0 (W/m/K) or [kxx, kyy, kxy]"))
        read_conductivity(*n, m);
      std::optional<ConfigNode> capacity = map.optional("heat_capacity");
      std::optional<ConfigNode> specific = map.optional("specific_heat");
      if (capacity) {
        if (auto v = capacity->quantity(quantity::heat_capacity, Range::positive()))
          m.heat_capacity = *v;
        if (specific)
          specific->error_at_key(
              "found both heat_capacity and specific_heat; expected one of them");
      } else if (specific) {
        if (auto v = specific->quantity(quantity::specific_heat, Range::positive()))
          if (index) m.heat_capacity = *v * scene.materials[*index].density;
      } else {
        map.report_missing("heat_capacity",
                           "a volumetric heat capacity rho c > 0 (J/m^3/K), or specific_heat");
      }
      map.read("thermal_expansion", m.thermal_expansion, quantity::thermal_expansion,
               Range::non_negative());
      if (index) {
        c.materials[*index] = m;
      }
    }
  }
  // Every material of a block conducts heat: each needs its properties.
  std::vector<bool> used(scene.materials.size(), false);
  for (const BlockSpec& b : scene.blocks)
    if (b.material >= 0 && b.material < static_cast<int>(used.size())) used[b.material] = true;
  for (std::size_t i = 0; i < given.size(); ++i)
    if (used[i] && !given[i])
      node.error(
          fmt::format("found no entry for material '{}'; expected its conductivity and "
                      "heat capacity in thermal.materials",
                      scene.materials[i].name));
}

void read_mesh(const ConfigNode& node, ThermalControls& c) {
  ConfigMap map(node, mesh_table);
  c.mesh_path = node.located_path();
  map.read("element_size", c.element_size, quantity::length, Range::positive());
  map.read("source_element_size", c.source_element_size, quantity::length, Range::positive());
  map.read("size_grading", c.size_grading, quantity::dimensionless, Range::closed(0.05, 2));
  map.read("max_elements", c.max_elements, quantity::dimensionless, Range::closed(1, 1e9));
  if (c.element_size > 0 && c.source_element_size > c.element_size)
    if (auto n = map.optional("source_element_size"))
      n->error(fmt::format("found {}; expected at most element_size ({} m)", n->found(),
                           c.element_size));
}

void read_initial(const ConfigNode& node, ThermalControls& c) {
  ConfigMap map(node, initial_table);
  map.read("temperature", c.initial_temperature, quantity::temperature,
           heat_keys::temperature_range());
  // [gx, gy], or one number: the change per metre of y (the continuum's
  // temperature_gradient), e.g. -0.03 K/m for 30 K/km warmer with depth.
  if (auto n = map.optional("temperature_gradient")) {
    if (n->is_list()) {
      if (auto g = n->vec2(quantity::temperature_gradient)) c.gradient = *g;
    } else if (auto g = n->quantity(quantity::temperature_gradient)) {
      c.gradient = Vec2(0, *g);
    }
  }
  if (auto n = map.optional("reference_point"))
    if (auto p = n->vec2(quantity::length)) c.reference_point = *p;
}

void read_joints(const ConfigNode& node, ThermalControls& c) {
  ConfigMap map(node, joints_table);
  if (auto n = map.optional("conductance")) {
    if (n->is_scalar() && n->text() == "perfect") {
      c.perfect_contact = true;
    } else if (auto h = n->quantity(quantity::transfer_coefficient, Range::non_negative())) {
      c.perfect_contact = false;
      c.contact_conductance = *h;
    }
  }
}

void read_thermal(const ConfigNode& node, SectionContext& context) {
  Scene& scene = context.scene();
  ThermalControls& c = scene.sections.set(thermal::kSettings, ThermalControls{});
  ConfigMap map(node, thermal_table);
  const SourceLocation& l = node.location();
  c.mesh_path = fmt::format("{}:{}:{}: thermal", l.file, l.line, l.column);
  if (auto n = map.optional("materials"))
    read_materials(*n, context, c);
  else if (scene.has_physics("thermal"))
    map.report_missing("materials", "the conductivity and heat capacity of each material");
  if (auto n = map.optional("mesh")) read_mesh(*n, c);
  constexpr std::string_view kSchemes[] = {"backward_euler", "bdf2"};
  if (auto n = map.optional("scheme"))
    if (auto s = n->choice(kSchemes))
      c.scheme =
          *s == "bdf2" ? ThermalControls::Scheme::Bdf2 : ThermalControls::Scheme::BackwardEuler;
  constexpr std::string_view kCapacities[] = {"lumped", "consistent"};
  if (auto n = map.optional("capacity"))
    if (auto s = n->choice(kCapacities)) c.lumped_capacity = *s == "lumped";
  // Alone, nothing else sets the step: it must be there and > 0 (a value
  // that could not be read has been reported where it is).
  const bool alone =
      context.physics_read() && scene.physics.size() == 1 && scene.has_physics("thermal");
  constexpr const char* kAloneStep = "a thermal time step > 0, because thermal is the only process";
  if (auto n = map.optional("time_step")) {
    if (auto dt = n->quantity(quantity::time, Range::non_negative())) {
      c.time_step = *dt;
      check_time_step(*n, *dt, scene.time);
      if (alone && !(*dt > 0))
        n->error(fmt::format("found {}; expected {}", n->found(), kAloneStep));
    }
  } else if (alone) {
    map.report_missing("time_step", kAloneStep);
  }
  if (auto n = map.optional("max_temperature_change")) {
    if (auto d = n->quantity(quantity::temperature_change, Range::positive())) {
      c.max_temperature_change = *d;
      // The adaptive step needs its largest step (and first try).
      if (!(c.time_step > 0))
        n->error_at_key(
            "found max_temperature_change without time_step; expected thermal.time_step > 0, "
            "the largest step (and the first one tried) of the adaptive step");
    }
  }
  if (auto n = map.optional("initial")) read_initial(*n, c);
  if (auto n = map.optional("joints")) read_joints(*n, c);
  std::vector<std::string> boundaries(std::begin(thermal::kNamedSides),
                                      std::end(thermal::kNamedSides));
  if (const RockMassSpec* spec = context.scene().sections.find(kRockMassSpec))
    for (const ExcavationSpec& e : spec->excavations) boundaries.push_back(e.name);
  read_thermal_conditions(map, c, boundaries);
  read_fracture_convection(map, context, c);
}

/// What the thermal process writes in every scene (ThermalProcess::writes() starts
/// from it).
constexpr std::string_view kProvides[] = {kBlockThermalStrain.name};

}  // namespace

namespace thermal {
const SectionReader kThermalSection{
    "thermal",
    "a thermal section, because physics lists thermal (see docs/thermal.md; at least "
    "`thermal: {materials: [{name: ..., conductivity: ..., heat_capacity: ...}]}`)",
    &read_thermal,
    nullptr,
    kTables,
    kMoved,
    false,
    kProvides,
    kExchangedFields};
}  // namespace thermal

}  // namespace fissure
