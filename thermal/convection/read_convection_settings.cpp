// thermal.convection (docs/scene-reference.md section 12, docs/thermal.md
// 7). Whether an inlet's boundary has fracture nodes is known only once the
// flow has built its network: the process checks it and names the scene
// line (FluidInlet::path).
#include "thermal/convection/read_convection_settings.h"

#include <fmt/format.h>

#include <set>

#include "rockmass/fields/fracture_flow.h"
#include "rockmass/heat_keys.h"
#include "thermal/conduction/read_thermal_settings.h"

namespace fissure {

namespace thermal {
namespace {
constexpr std::string_view kConvection[] = {"nusselt", "fluid", "inlets"};
constexpr std::string_view kFluid[] = {"density", "specific_heat", "conductivity"};
constexpr std::string_view kInlet[] = {"boundary", "temperature"};
}  // namespace
const KeyTable convection_table{"thermal.convection", kConvection};
const KeyTable fluid_table{"thermal.convection.fluid", kFluid};
const KeyTable inlet_table{"thermal.convection.inlets[]", kInlet};
}  // namespace thermal

namespace {

void read_fluid(const ConfigNode& node, FractureConvection& c) {
  ConfigMap map(node, thermal::fluid_table);
  map.read("density", c.density, quantity::density, Range::positive());
  map.read("specific_heat", c.specific_heat, quantity::specific_heat, Range::positive());
  map.read("conductivity", c.conductivity, quantity::conductivity, Range::positive());
}

void read_inlets(const ConfigNode& node, FractureConvection& c) {
  const auto items = node.list("inlets {boundary, temperature}", false);
  if (!items) return;
  std::set<std::string> boundaries;
  for (const ConfigNode& item : *items) {
    ConfigMap map(item, thermal::inlet_table);
    FluidInlet inlet;
    inlet.path = item.located_path();
    if (auto n = map.required("boundary",
                              "the name of a boundary of the fracture network (left, right, "
                              "bottom, top, or a flow region)"))
      if (auto name = n->string("a boundary name")) {
        inlet.boundary = *name;
        if (!boundaries.insert(*name).second)
          n->error(fmt::format(
              "found a second inlet on boundary '{}'; expected one inlet per boundary", *name));
      }
    map.read_required("temperature", inlet.temperature, quantity::temperature,
                      heat_keys::temperature_range());
    c.inlets.push_back(std::move(inlet));
  }
}

}  // namespace

void read_fracture_convection(ConfigMap& thermal_map, SectionContext& context,
                              ThermalControls& controls) {
  const std::optional<ConfigNode> node = thermal_map.optional("convection");
  if (!node) return;
  FractureConvection& c = controls.convection.emplace();
  c.path = node->located_path();
  // The water's flux comes from the flow process (theory.md 6.3, H -> T).
  if (context.physics_read() && !provides(context.scene(), kFractureFlow.name))
    node->error_at_key(
        "found thermal.convection without the flow process; expected `flow` in physics (the "
        "fracture water's flux comes from the flow)");
  ConfigMap map(*node, thermal::convection_table);
  if (auto n = map.optional("nusselt")) {
    if (n->is_scalar() && n->text() == "wall_temperature") {
      c.wall_temperature = true;
    } else if (auto nu = n->quantity(quantity::dimensionless, Range::positive())) {
      c.nusselt = *nu;
    }
  }
  if (auto n = map.optional("fluid")) read_fluid(*n, c);
  if (auto n = map.optional("inlets")) read_inlets(*n, c);
}

}  // namespace fissure
