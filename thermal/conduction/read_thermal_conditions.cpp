// thermal.conditions and thermal.sources (docs/scene-reference.md section
// 12). Whether a boundary has rock on it and whether a source lies in a block
// is known only once the blocks are meshed: the process checks it and names
// the scene line (ThermalCondition::path, HeatSource::path). The keys shared
// with the continuum section are read by rockmass/heat_keys.h and
// core/scene/time_history.h.
#include <fmt/format.h>

#include <algorithm>
#include <set>

#include "core/geometry/polygon_checks.h"
#include "core/scene/scene_section.h"
#include "core/scene/time_history.h"
#include "rockmass/heat_keys.h"

#include "thermal/conduction/read_thermal_settings.h"

namespace fissure {

namespace thermal {
namespace {
constexpr std::string_view kCondition[] = {"boundary", "temperature", "heat_flux", "heat_transfer",
                                           "history",  "decay",       "cycle"};
constexpr std::string_view kCycle[] = {"amplitude", "period", "peak"};
constexpr std::string_view kSource[] = {"name",  "point",   "line", "polygon",
                                        "power", "history", "decay"};
}  // namespace
const KeyTable condition_table{"thermal.conditions[]", kCondition};
const KeyTable heat_transfer_table{"thermal.conditions[].heat_transfer", heat_keys::kHeatTransfer};
const KeyTable source_table{"thermal.sources[]", kSource};
const KeyTable cycle_table{"thermal.conditions[].cycle", kCycle};
}  // namespace thermal

namespace {

void read_cycle(const ConfigNode& node, TemperatureCycle& cycle) {
  ConfigMap map(node, thermal::cycle_table);
  map.read_required("amplitude", cycle.amplitude, quantity::temperature_change,
                    Range::non_negative());
  map.read_required("period", cycle.period, quantity::time, Range::positive());
  map.read("peak", cycle.peak, quantity::time);
}

void read_conditions(const ConfigNode& node, ThermalControls& c,
                     const std::vector<std::string>& known) {
  using Type = ThermalCondition::Type;
  const auto items =
      node.list("conditions {boundary, temperature | heat_flux | heat_transfer}", false);
  if (!items) return;
  std::set<std::string> boundaries;
  for (const ConfigNode& item : *items) {
    ConfigMap map(item, thermal::condition_table);
    ThermalCondition t;
    t.path = item.located_path();
    if (auto n = map.required("boundary",
                              "the name of a boundary (left, right, bottom, top, exterior, or an "
                              "excavation)")) {
      if (auto name = n->string("a boundary name")) {
        t.boundary = *name;
        if (std::find(known.begin(), known.end(), *name) == known.end()) {
          std::string names;
          for (const std::string& k : known) names += (names.empty() ? "" : ", ") + k;
          n->error(fmt::format("found '{}', which names no boundary; expected one of: {}", *name,
                               names));
        } else if (!boundaries.insert(*name).second)
          n->error(
              fmt::format("found a second condition on boundary '{}'; expected one "
                          "condition per boundary",
                          *name));
      }
    }
    int given = 0;
    if (auto n = map.optional("temperature")) {
      ++given;
      t.type = Type::Temperature;
      if (auto v = n->quantity(quantity::temperature, heat_keys::temperature_range())) t.value = *v;
    }
    if (auto n = map.optional("heat_flux")) {
      ++given;
      t.type = Type::Flux;
      if (auto v = n->quantity(quantity::heat_flux)) t.value = *v;
    }
    if (auto n = map.optional("heat_transfer")) {
      ++given;
      t.type = Type::Convection;
      heat_keys::read_heat_transfer(*n, thermal::heat_transfer_table, t.value,
                                    t.external_temperature);
    }
    read_time_factor(map, t.factor);
    if (auto n = map.optional("cycle")) {
      if (t.type == Type::Flux)
        n->error_at_key(
            "found a cycle on a heat_flux; expected it on a temperature or a heat_transfer's "
            "temperature (a varying flux takes a history)");
      else
        read_cycle(*n, t.cycle);
    }
    if (given != 1)
      item.error(fmt::format(
          "found {} of temperature, heat_flux and heat_transfer; expected exactly one", given));
    c.conditions.push_back(std::move(t));
  }
}

void read_sources(const ConfigNode& node, ThermalControls& c) {
  using Shape = HeatSource::Shape;
  const auto items = node.list("sources {name, point | line | polygon, power}", false);
  if (!items) return;
  NameRegistry names("source");
  for (const ConfigNode& item : *items) {
    ConfigMap map(item, thermal::source_table);
    HeatSource s;
    s.path = item.located_path();
    if (auto n = map.required("name", "a source name"))
      if (auto name = n->string("a source name")) {
        names.add(*name, *n);
        s.name = *name;
      }
    int given = 0;
    if (auto n = map.optional("point")) {
      ++given;
      s.shape = Shape::Point;
      if (auto p = n->vec2(quantity::length)) s.points = {*p};
    }
    if (auto n = map.optional("line")) {
      ++given;
      s.shape = Shape::Line;
      if (auto p = n->points(quantity::length, true)) {
        if (p->size() != 2 || ((*p)[1] - (*p)[0]).norm() == 0)
          n->error(fmt::format("found {}; expected two distinct points [[x0, y0], [x1, y1]]",
                               n->found()));
        else
          s.points = *p;
      }
    }
    if (auto n = map.optional("polygon")) {
      ++given;
      s.shape = Shape::Area;
      if (auto p = n->points(quantity::length, true)) {
        // The mesh follows its outline: a simple polygon (tolerance as the
        // geometry checks', relative to its own size).
        Box box;
        for (const Vec2& x : *p) box.extend(x);
        const double tol = kRelativeGeometryTolerance * std::max(box.size().maxCoeff(), 1e-300);
        const std::vector<PolygonProblem> problems = check_polygon(Polygon(*p), tol);
        for (const PolygonProblem& problem : problems)
          n->error(problem.what +
                   "; expected a simple polygon with at least 3 distinct points, non-zero area, "
                   "edges that do not cross");
        if (problems.empty()) {
          s.points = *p;
          if (signed_area(s.points) < 0) std::reverse(s.points.begin(), s.points.end());
        }
      }
    }
    if (given != 1)
      item.error(fmt::format("found {} of point, line and polygon; expected exactly one", given));
    map.read_required("power", s.power, quantity::linear_power);
    read_time_factor(map, s.factor);
    c.sources.push_back(std::move(s));
  }
}

}  // namespace

void read_thermal_conditions(ConfigMap& map, ThermalControls& c,
                             const std::vector<std::string>& boundaries) {
  if (auto n = map.optional("conditions")) read_conditions(*n, c, boundaries);
  if (auto n = map.optional("sources")) read_sources(*n, c);
}

}  // namespace fissure
