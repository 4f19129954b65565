// The entries of the continuum section's `conditions` and `sources`
// (docs/scene-reference.md section 13, docs/continuum.md 4): one condition
// of one kind per entry, on a named boundary; heat or fluid point sources.
// The keys shared with the thermal section are read by rockmass/heat_keys.h
// and core/scene/time_history.h.
#include "continuum/poroelasticity/read_continuum_conditions.h"

#include <fmt/format.h>

#include "core/geometry/polygon.h"
#include "core/geometry/polygon_checks.h"
#include "core/scene/config_map.h"
#include "core/scene/parse_scene.h"
#include "core/scene/time_history.h"
#include "rockmass/heat_keys.h"

namespace fissure::continuum {

namespace {

using Type = ContinuumCondition::Type;

constexpr std::string_view kCondition[] = {
    "boundary", "displacement", "traction",    "normal_pressure", "plate",
    "pressure", "flux",         "temperature", "heat_flux",       "heat_transfer",
    "history",  "decay",        "interface",   "gradient"};
constexpr std::string_view kPlate[] = {"axis", "force"};
constexpr std::string_view kSource[] = {"name", "point", "power", "fluid_rate", "history", "decay"};

/// A fluid source's rate: m^3/s per metre of thickness (plane strain), or
/// m^3/s in all (axisymmetric).
constexpr QuantityKind fluid_rate_per_thickness{
    "fluid rate per unit thickness", {0, 2, -1, 0, 0}, "m^2/s", "m^2/s", 1, 1e3};
constexpr QuantityKind fluid_rate{"fluid rate", {0, 3, -1, 0, 0}, "m^3/s", "m^3/s", 1, 1e3};

}  // namespace

const KeyTable kConditionTable{"continuum.conditions[]", kCondition};
const KeyTable kPlateTable{"continuum.conditions[].plate", kPlate};
const KeyTable kHeatTransferTable{"continuum.conditions[].heat_transfer", heat_keys::kHeatTransfer};
const KeyTable kSourceTable{"continuum.sources[]", kSource};

void read_condition(const ConfigNode& item, const std::vector<std::string>& boundaries,
                    ContinuumControls& c) {
  ConfigMap map(item, kConditionTable);
  ContinuumCondition k;
  k.path = item.located_path();
  if (auto n =
          map.required("boundary", "the name of a boundary (left, right, bottom, top, exterior)"))
    if (auto b = n->choice(std::vector<std::string_view>(boundaries.begin(), boundaries.end())))
      k.boundary = *b;
  int kinds = 0;
  if (auto n = map.optional("displacement")) {
    ++kinds;
    k.type = Type::Displacement;
    // [ux, uy], each a length or `free`.
    const auto items = n->is_list() ? n->list("displacement components", true) : std::nullopt;
    if (!items || items->size() != 2) {
      n->error(
          fmt::format("found {}; expected [ux, uy], each a displacement (m) or free", n->found()));
    } else {
      for (int comp = 0; comp < 2; ++comp) {
        const ConfigNode& e = (*items)[comp];
        if (e.is_scalar() && e.text() == "free") continue;
        if (auto v = e.quantity(quantity::length)) {
          k.fix[comp] = true;
          k.vector(comp) = *v;
        }
      }
    }
  }
  if (auto n = map.optional("traction")) {
    ++kinds;
    k.type = Type::Traction;
    if (auto v = n->vec2(quantity::stress)) k.vector = *v;
  }
  if (auto n = map.optional("normal_pressure")) {
    ++kinds;
    k.type = Type::NormalPressure;
    if (auto v = n->quantity(quantity::stress)) k.value = *v;
  }
  if (auto n = map.optional("plate")) {
    ++kinds;
    k.type = Type::RigidPlate;
    ConfigMap plate(*n, kPlateTable);
    constexpr std::string_view kAxes[] = {"x", "y"};
    if (auto a = plate.required("axis", "x or y: the component the plate holds uniform"))
      if (auto s = a->choice(kAxes)) k.axis = *s == "x" ? 0 : 1;
    // A total force on a ring; per metre of thickness in plane strain.
    plate.read_required("force", k.value, c.axisymmetric ? quantity::force : quantity::linear_force,
                        Range::any());
  }
  if (auto n = map.optional("pressure")) {
    ++kinds;
    k.type = Type::FluidPressure;
    if (auto v = n->quantity(quantity::pressure)) k.value = *v;
  }
  if (auto n = map.optional("flux")) {
    ++kinds;
    k.type = Type::FluidFlux;
    if (auto v = n->quantity(quantity::velocity)) k.value = *v;
  }
  if (auto n = map.optional("temperature")) {
    ++kinds;
    k.type = Type::Temperature;
    if (auto v = n->quantity(quantity::temperature, heat_keys::temperature_range())) k.value = *v;
  }
  if (auto n = map.optional("heat_flux")) {
    ++kinds;
    k.type = Type::HeatFlux;
    if (auto v = n->quantity(quantity::heat_flux)) k.value = *v;
  }
  if (auto n = map.optional("heat_transfer")) {
    ++kinds;
    k.type = Type::HeatTransfer;
    // Heat inflow h (T_inf - T); the history scales T_inf.
    heat_keys::read_heat_transfer(*n, kHeatTransferTable, k.coefficient, k.value);
  }
  if (auto n = map.optional("interface")) {
    ++kinds;
    k.type = Type::Interface;
    // The quantities another process gives through the shared field
    // continuum_interface_loads: traction (nodal, or forces at points),
    // pressure or fluid_flow (prescribed, or inflows at points), temperature
    // or heat_flow.
    constexpr std::string_view kGiven[] = {"traction", "pressure", "temperature", "fluid_flow",
                                           "heat_flow"};
    if (auto items = n->list("quantities given to the continuum", true)) {
      for (const ConfigNode& e : *items) {
        const auto g = e.choice(kGiven);
        if (!g) continue;
        bool& flag = *g == "traction"      ? k.gives.traction
                     : *g == "pressure"    ? k.gives.pressure
                     : *g == "temperature" ? k.gives.temperature
                     : *g == "fluid_flow"  ? k.gives.fluid_flow
                                           : k.gives.heat_flow;
        if (flag) e.error(fmt::format("found '{}' twice; expected each quantity once", *g));
        flag = true;
      }
      if (k.gives.pressure && k.gives.fluid_flow)
        n->error(
            "found both pressure and fluid_flow; expected one of them (a boundary's "
            "pressure is given, or its inflow)");
      if (k.gives.temperature && k.gives.heat_flow)
        n->error(
            "found both temperature and heat_flow; expected one of them (a boundary's "
            "temperature is given, or its inflow)");
    }
    for (const ContinuumCondition& other : c.conditions)
      if (other.type == Type::Interface && other.boundary == k.boundary && !k.boundary.empty())
        n->error_at_key(
            fmt::format("found a second interface on boundary '{}' (the first: {}); "
                        "expected one interface per boundary",
                        k.boundary, other.path));
  }
  // A pressure or temperature that varies along the boundary: value + g . x
  // (a water table that rises inland, a sea floor that deepens).
  if (auto n = map.optional("gradient")) {
    constexpr QuantityKind pressure_gradient{
        "pressure gradient", {1, -2, -2, 0, 0}, "Pa/m, MPa/m", "Pa/m", 1, 1e12};
    if (k.type == Type::FluidPressure) {
      if (auto g = n->vec2(pressure_gradient)) k.gradient = *g;
    } else if (k.type == Type::Temperature) {
      if (auto g = n->vec2(quantity::temperature_gradient)) k.gradient = *g;
    } else {
      n->error_at_key(
          "found a gradient on a condition that is not a pressure or a temperature; expected "
          "it beside `pressure` or `temperature` only");
    }
  }
  read_time_factor(map, k.time_factor);
  if (kinds != 1) {
    item.error(fmt::format(
        "found {} conditions in one entry; expected exactly one of displacement, traction, "
        "normal_pressure, plate, pressure, flux, temperature, heat_flux, heat_transfer, "
        "interface",
        kinds));
    return;
  }
  c.conditions.push_back(std::move(k));
}

void read_source(const ConfigNode& item, ContinuumControls& c) {
  ConfigMap map(item, kSourceTable);
  ContinuumSource s;
  if (auto n = map.optional("name"))
    if (auto v = n->string("a name")) s.name = *v;
  if (auto n = map.required("point", "the source's point [x, y] in the domain"))
    if (auto p = n->vec2(quantity::length)) {
      s.point = *p;
      const Polygon domain(c.domain);
      if (!c.domain.empty() &&
          locate_point(domain, *p,
                       kRelativeGeometryTolerance * bounding_box(domain).size().maxCoeff()) < 0)
        n->error(
            fmt::format("found [{:g}, {:g}], which is outside continuum.domain; expected a "
                        "point in the domain",
                        p->x(), p->y()));
    }
  // Heat (W per metre of thickness, or W in all when axisymmetric) or fluid
  // (m^3/s per metre, or m^3/s): exactly one of them.
  const bool heat = map.contains("power"), fluid = map.contains("fluid_rate");
  if (heat && fluid) {
    map.optional("power");  // read: the message is the fluid_rate's
    map.optional("fluid_rate")
        ->error_at_key(
            "found both power and fluid_rate; expected exactly one (a source gives heat or "
            "fluid)");
  } else if (fluid) {
    s.kind = ContinuumSource::Kind::Fluid;
    map.read("fluid_rate", s.rate, c.axisymmetric ? fluid_rate : fluid_rate_per_thickness,
             Range::any());
  } else if (heat) {
    map.read("power", s.rate, c.axisymmetric ? quantity::power : quantity::linear_power,
             Range::any());
  } else {
    item.error(
        c.axisymmetric
            ? "found neither power nor fluid_rate; expected one of them: a heat source's power "
              "(W) or a fluid source's rate (m^3/s, negative for extraction)"
            : "found neither power nor fluid_rate; expected one of them: a heat source's power "
              "per unit thickness (W/m) or a fluid source's rate per unit thickness (m^2/s, "
              "negative for extraction)");
  }
  read_time_factor(map, s.time_factor);
  c.sources.push_back(std::move(s));
}

}  // namespace fissure::continuum
