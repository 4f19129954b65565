// flow.regions, flow.conditions, flow.wells and the initial pressure
// (docs/scene-reference.md section 11). Whether a boundary holds fracture
// nodes is known only once the network is built: the flow process checks it
// and names the scene line (FlowBoundaryCondition::path).
#include <fmt/format.h>

#include "core/scene/time_history.h"
#include "flow/cubic_law/read_flow_settings.h"
#include "flow/network/read_fluid.h"

namespace fissure {

namespace flow {
namespace {
constexpr std::string_view kRegion[] = {"name", "min", "max"};
constexpr std::string_view kCondition[] = {"boundary", "pressure", "head", "flux", "history"};
constexpr std::string_view kWell[] = {"name", "point", "rate", "history"};
}  // namespace
const KeyTable region_table{"flow.regions[]", kRegion};
const KeyTable condition_table{"flow.conditions[]", kCondition};
const KeyTable well_table{"flow.wells[]", kWell};
}  // namespace flow

namespace {

void read_regions(const ConfigNode& node, FlowControls& flow) {
  const auto items = node.list("regions {name, min, max}", false);
  if (!items) return;
  NameRegistry names("region");
  for (const ConfigNode& item : *items) {
    ConfigMap map(item, flow::region_table);
    FlowRegion r;
    if (auto n = map.required("name", "a region name"))
      if (auto name = n->string("a region name")) {
        names.add(*name, *n);
        r.name = *name;
      }
    if (auto n = map.required("min", "the lower-left corner [x, y]"))
      if (auto p = n->vec2(quantity::length)) r.min = *p;
    if (auto n = map.required("max", "the upper-right corner [x, y]")) {
      if (auto p = n->vec2(quantity::length)) {
        r.max = *p;
        if ((r.max - r.min).minCoeff() < 0)
          n->error("found a corner below or left of `min`; expected max >= min in x and y");
      }
    }
    flow.regions.push_back(std::move(r));
  }
}

void read_conditions(const ConfigNode& node, FlowControls& flow, bool gravity_on) {
  using Type = FlowBoundaryCondition::Type;
  const auto items = node.list("conditions {boundary, pressure | head | flux}", false);
  if (!items) return;
  for (const ConfigNode& item : *items) {
    ConfigMap map(item, flow::condition_table);
    FlowBoundaryCondition c;
    c.path = item.located_path();
    if (auto n = map.required("boundary",
                              "the name of a network boundary (left, right, bottom, "
                              "top, exterior, or a region)"))
      if (auto name = n->string("a boundary name")) c.boundary = *name;
    int given = 0;
    if (auto n = map.optional("pressure")) {
      ++given;
      c.type = Type::Pressure;
      if (auto v = n->quantity(quantity::pressure)) c.value = *v;
    }
    if (auto n = map.optional("head")) {
      ++given;
      c.type = Type::Head;
      if (auto v = n->quantity(quantity::length)) c.value = *v;
      if (!gravity_on)
        n->error_at_key(
            "found a head with gravity off (flow.gravity false or gravity [0, 0]); "
            "expected a pressure");
    }
    if (auto n = map.optional("flux")) {
      ++given;
      c.type = Type::Flux;
      if (auto v = n->quantity(quantity::flow_rate)) c.value = *v;
    }
    if (given != 1)
      item.error(fmt::format("found {} of pressure, head and flux; expected exactly one", given));
    if (auto h = map.optional("history")) read_history(*h, c.history);
    flow.conditions.push_back(std::move(c));
  }
}

void read_wells(const ConfigNode& node, FlowControls& flow) {
  const auto items = node.list("wells {name, point, rate}", false);
  if (!items) return;
  NameRegistry names("well");
  for (const ConfigNode& item : *items) {
    ConfigMap map(item, flow::well_table);
    FlowWell w;
    w.path = item.located_path();
    if (auto n = map.required("name", "a well name"))
      if (auto name = n->string("a well name")) {
        names.add(*name, *n);
        w.name = *name;
      }
    if (auto n = map.required("point", "a point [x, y] on a fracture"))
      if (auto p = n->vec2(quantity::length)) w.point = *p;
    map.read_required("rate", w.rate, quantity::flow_rate);
    if (auto h = map.optional("history")) read_history(*h, w.history);
    flow.wells.push_back(std::move(w));
  }
}

}  // namespace

void read_flow_conditions(ConfigMap& map, FlowControls& flow, bool gravity_on) {
  if (auto n = map.optional("regions")) read_regions(*n, flow);
  if (auto n = map.optional("conditions")) read_conditions(*n, flow, gravity_on);
  if (auto n = map.optional("wells")) read_wells(*n, flow);
  std::optional<ConfigNode> pressure = map.optional("initial_pressure");
  if (pressure)
    if (auto v = pressure->quantity(quantity::pressure)) flow.initial_pressure = *v;
  if (auto n = map.optional("initial_head")) {
    if (auto v = n->quantity(quantity::length)) flow.initial_head = *v;
    if (pressure)
      n->error_at_key("found both initial_pressure and initial_head; expected one of them");
    else if (!gravity_on)
      n->error_at_key(
          "found an initial head with gravity off (flow.gravity false or gravity "
          "[0, 0]); expected initial_pressure");
  }
}

}  // namespace fissure
