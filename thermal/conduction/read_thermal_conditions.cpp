// thermal.conditions and thermal.sources (docs/scene-reference.md section
// 12). Whether a boundary has rock on it and whether a source lies in a block
// is known only once the blocks are meshed: the process checks it and names
// the scene line (ThermalCondition::path, HeatSource::path).
#include <fmt/format.h>

#include <algorithm>
#include <set>

#include "core/geometry/polygon_checks.h"
#include "core/scene/scene_section.h"

#include "thermal/conduction/read_thermal_settings.h"

namespace fissure {

namespace thermal {
namespace {
constexpr std::string_view kCondition[] = {"boundary", "temperature", "flux",
                                           "transfer_coefficient", "external_temperature"};
constexpr std::string_view kSource[] = {"name",  "point",   "line", "polygon",
                                        "power", "history", "decay"};
}  // namespace
const KeyTable condition_table{"thermal.conditions[]", kCondition};
const KeyTable source_table{"thermal.sources[]", kSource};
}  // namespace thermal

namespace {

std::string located(const ConfigNode& node) {
  const SourceLocation& l = node.location();
  return fmt::format("{}:{}:{}: {}", l.file, l.line, l.column, node.path());
}

void read_conditions(const ConfigNode& node, ThermalControls& c) {
  using Type = ThermalCondition::Type;
  const auto items =
      node.list("conditions {boundary, temperature | flux | transfer_coefficient}", false);
  if (!items) return;
  std::set<std::string> boundaries;
  for (const ConfigNode& item : *items) {
    ConfigMap map(item, thermal::condition_table);
    ThermalCondition t;
    t.path = located(item);
    if (auto n = map.required("boundary",
                              "the name of a boundary (left, right, bottom, top, exterior, or an "
                              "excavation)")) {
      if (auto name = n->string("a boundary name")) {
        t.boundary = *name;
        if (!boundaries.insert(*name).second)
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
      if (auto v = n->quantity(quantity::temperature, Range::open(-273.15, 1e4))) t.value = *v;
    }
    if (auto n = map.optional("flux")) {
      ++given;
      t.type = Type::Flux;
      if (auto v = n->quantity(quantity::heat_flux)) t.value = *v;
    }
    if (auto n = map.optional("transfer_coefficient")) {
      ++given;
      t.type = Type::Convection;
      if (auto v = n->quantity(quantity::transfer_coefficient, Range::positive())) t.value = *v;
      map.read_required("external_temperature", t.external_temperature, quantity::temperature,
                        Range::open(-273.15, 1e4));
    } else if (auto n = map.optional("external_temperature")) {
      n->error_at_key("found external_temperature without transfer_coefficient; expected both");
    }
    if (given != 1)
      item.error(fmt::format(
          "found {} of temperature, flux and transfer_coefficient; expected exactly one", given));
    c.conditions.push_back(std::move(t));
  }
}

/// [[t, factor], ...] with increasing t, or [[a, tau], ...] with tau > 0.
void read_pairs(const ConfigNode& node, const QuantityKind& first, const QuantityKind& second,
                std::string_view components, bool increasing,
                std::vector<std::pair<double, double>>& out) {
  const auto items = node.list(components, true);
  if (!items) return;
  const QuantityKind* kinds[] = {&first, &second};
  std::optional<double> previous;
  for (const ConfigNode& item : *items) {
    const auto pair = item.numbers(kinds, components);
    if (!pair) continue;
    if (increasing && previous && (*pair)[0] <= *previous)
      item.error(fmt::format("found t = {} s after t = {} s; expected strictly increasing times",
                             (*pair)[0], *previous));
    if (!increasing && !((*pair)[1] > 0))
      item.error(fmt::format("found tau = {} s; expected a decay time > 0", (*pair)[1]));
    previous = (*pair)[0];
    out.emplace_back((*pair)[0], (*pair)[1]);
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
    s.path = located(item);
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
    std::optional<ConfigNode> history = map.optional("history");
    if (history)
      read_pairs(*history, quantity::time, quantity::dimensionless, "pairs [t, factor]", true,
                 s.history);
    if (auto n = map.optional("decay")) {
      read_pairs(*n, quantity::dimensionless, quantity::time, "pairs [a, tau]", false, s.decay);
      if (history) n->error_at_key("found both history and decay; expected one of them");
    }
    c.sources.push_back(std::move(s));
  }
}

}  // namespace

void read_thermal_conditions(ConfigMap& map, ThermalControls& c) {
  if (auto n = map.optional("conditions")) read_conditions(*n, c);
  if (auto n = map.optional("sources")) read_sources(*n, c);
}

}  // namespace fissure
