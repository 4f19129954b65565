// Top-level keys `fixed_points`, `point_loads` and `monitors`. The points are
// attached to blocks later (resolve_points.cpp), after the block polygons
// have been checked.
#include <fmt/format.h>

#include "core/scene/scene_draft.h"
#include "core/scene/scene_keys.h"
#include "core/scene/time_history.h"

namespace fissure {

namespace {

using Owner = PointToResolve::Owner;

/// Reads `point` and `block` of one item into a PointToResolve.
PointToResolve read_point_and_block(ConfigMap& map, Owner owner, int index) {
  PointToResolve p;
  p.owner = owner;
  p.index = index;
  p.path = map.node().path();
  p.point_at = map.node().location();
  if (auto node = map.required("point", "a point [x, y]")) {
    p.point_at = node->location();
    p.point = node->vec2(quantity::length);
  }
  if (auto node = map.optional("block")) {
    p.block_node = node;
    p.block = node->string("the name of a block");
  }
  return p;
}

void read_directions(const ConfigNode& node, FixedPoint& f) {
  constexpr std::string_view kDirections[] = {"x", "y"};
  const std::optional<ConfigList> items = node.list("directions (x, y)", true);
  if (!items) return;
  bool x = false, y = false;
  for (const ConfigNode& item : *items) {
    const std::optional<std::string> d = item.choice(kDirections);
    if (!d) return;
    bool& flag = *d == "x" ? x : y;
    if (flag) item.error("found '" + *d + "' a second time; expected each direction once");
    flag = true;
  }
  f.fix_x = x;
  f.fix_y = y;
}

bool valid_monitor_name(const std::string& name) {
  return name.find_first_of(",.\"\n\r") == std::string::npos;
}

}  // namespace

void read_points(ConfigMap& top, SceneDraft& draft) {
  Scene& scene = draft.scene;

  if (auto node = top.optional("fixed_points")) {
    if (auto items = node->list("fixed points", false)) {
      for (const ConfigNode& item : *items) {
        ConfigMap map(item, scene_keys::fixed_point);
        FixedPoint f;
        const int index = static_cast<int>(scene.fixed_points.size());
        draft.points.push_back(read_point_and_block(map, Owner::FixedPoint, index));
        f.point = draft.points.back().point.value_or(Vec2::Zero());
        if (auto d = map.optional("directions")) read_directions(*d, f);
        scene.fixed_points.push_back(f);
      }
    }
  }

  if (auto node = top.optional("point_loads")) {
    if (auto items = node->list("point loads", false)) {
      for (const ConfigNode& item : *items) {
        ConfigMap map(item, scene_keys::point_load);
        PointLoad load;
        const int index = static_cast<int>(scene.point_loads.size());
        draft.points.push_back(read_point_and_block(map, Owner::PointLoad, index));
        load.point = draft.points.back().point.value_or(Vec2::Zero());
        if (auto f = map.required("force", "a force [fx, fy] (N, kN, MN)"))
          if (auto v = f->vec2(quantity::force)) load.force = *v;
        if (auto h = map.optional("history")) read_history(*h, load.history);
        scene.point_loads.push_back(std::move(load));
      }
    }
  }

  if (auto node = top.optional("monitors")) {
    if (auto items = node->list("monitors", false)) {
      NameRegistry names("monitor");
      for (const ConfigNode& item : *items) {
        ConfigMap map(item, scene_keys::monitor);
        Monitor m;
        if (auto n = map.required("name", "a monitor name")) {
          if (auto name = n->string("a monitor name")) {
            if (!valid_monitor_name(*name))
              n->error("found " + n->found() +
                       "; expected a name without commas, dots, quotes or line breaks (it "
                       "prefixes the columns of monitors.csv)");
            names.add(*name, *n);
            m.name = *name;
          }
        }
        const int index = static_cast<int>(scene.monitors.size());
        draft.points.push_back(read_point_and_block(map, Owner::Monitor, index));
        m.point = draft.points.back().point.value_or(Vec2::Zero());
        m.location = draft.points.back().point_at;
        scene.monitors.push_back(std::move(m));
      }
    }
  }
}

}  // namespace fissure
