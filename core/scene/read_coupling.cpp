// Top-level key `coupling` (docs/scene-reference.md "coupling"; theory.md 6):
// the splitting scheme, the order in which the processes advance, the
// coupling interval of each sub-cycled process, and the initial stage that
// brings the blocks to rest before the coupled run. Process names are those of
// `physics`.
#include <fmt/format.h>

#include <algorithm>

#include "core/scene/scene_draft.h"
#include "core/scene/scene_keys.h"

namespace fissure {

namespace {

/// A name listed under `physics`; reported at `node` otherwise.
std::optional<std::string> process_name(const ConfigNode& node, const SceneDraft& draft) {
  const std::optional<std::string> name = node.string("a process name");
  if (!name || !draft.physics_read || draft.scene.has_physics(*name)) return name;
  std::string listed;
  for (const std::string& p : draft.scene.physics) listed += (listed.empty() ? "" : ", ") + p;
  node.error("found '" + *name + "', which physics does not list; expected one of: " + listed);
  return std::nullopt;
}

/// A non-empty list of names listed under `physics`, each once.
std::optional<std::vector<std::string>> process_names(const ConfigNode& node,
                                                      const SceneDraft& draft) {
  const auto items = node.list("process names", true);
  if (!items) return std::nullopt;
  std::vector<std::string> names;
  for (const ConfigNode& item : *items) {
    const std::optional<std::string> name = process_name(item, draft);
    if (!name) return std::nullopt;
    if (std::find(names.begin(), names.end(), *name) != names.end()) {
      item.error("found '" + *name + "' a second time; expected each process once");
      return std::nullopt;
    }
    names.push_back(*name);
  }
  return names;
}

void read_order(const ConfigNode& node, SceneDraft& draft) {
  std::optional<std::vector<std::string>> names = process_names(node, draft);
  if (!names) return;
  std::vector<std::string>& order = *names;
  if (draft.physics_read && order.size() != draft.scene.physics.size()) {
    node.error(fmt::format(
        "found {} of the {} processes of physics; expected every process of physics once",
        order.size(), draft.scene.physics.size()));
    return;
  }
  draft.scene.coupling.order = std::move(order);
}

void read_intervals(const ConfigNode& node, SceneDraft& draft) {
  if (!node.is_map()) {
    node.error("found " + node.found() +
               "; expected a map from process names to coupling intervals, such as "
               "{<process>: 10 ms}");
    return;
  }
  const std::string& file = node.diagnostics().file_name();
  for (auto it = node.yaml().begin(); it != node.yaml().end(); ++it) {
    const YAML::Mark mark = it->first.Mark();
    const SourceLocation at{file, mark.line + 1, mark.column + 1};
    const ConfigNode key = node.child(it->first, node.path(), at);
    const std::optional<std::string> name = process_name(key, draft);
    if (!name) continue;
    const ConfigNode value = node.child(it->second, node.path() + "." + *name, at);
    if (const auto interval = value.quantity(quantity::time, Range::non_negative()))
      draft.scene.coupling.intervals[*name] = *interval;
  }
}

void read_initial_equilibrium(const ConfigNode& node, SceneDraft& draft) {
  ConfigMap map(node, scene_keys::initial_equilibrium);
  CouplingSettings::InitialEquilibrium stage;
  if (auto list = map.optional("processes"))
    if (auto names = process_names(*list, draft)) stage.processes = std::move(*names);
  map.read("max_speed", stage.max_speed, quantity::velocity, Range::positive());
  map.read("max_time", stage.max_time, quantity::time, Range::positive());
  draft.scene.coupling.initial_equilibrium = stage;
}

}  // namespace

void read_coupling(ConfigMap& top, SceneDraft& draft) {
  std::optional<ConfigNode> node = top.optional("coupling");
  if (!node) return;
  ConfigMap map(*node, scene_keys::coupling);
  constexpr std::string_view kSchemes[] = {"lie"};
  if (auto s = map.optional("scheme")) s->choice(kSchemes);  // lie is the only one yet
  if (auto o = map.optional("order")) read_order(*o, draft);
  if (auto i = map.optional("intervals")) read_intervals(*i, draft);
  if (auto e = map.optional("initial_equilibrium")) read_initial_equilibrium(*e, draft);
  map.finish();
  const CouplingSettings& c = draft.scene.coupling;
  const bool every_one_sub_cycled =
      draft.physics_read && !draft.scene.physics.empty() &&
      std::all_of(draft.scene.physics.begin(), draft.scene.physics.end(),
                  [&c](const std::string& p) {
                    const auto it = c.intervals.find(p);
                    return it != c.intervals.end() && it->second > 0;
                  });
  if (every_one_sub_cycled)
    node->error(
        "found a coupling interval for every process; expected at least one process that "
        "advances every step (it sets the time step the others are sub-cycled in)");
}

}  // namespace fissure
