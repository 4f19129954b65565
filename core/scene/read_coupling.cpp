// Top-level key `coupling` (docs/scene-reference.md "coupling"; theory.md 6):
// the splitting scheme and the iterated scheme's controls, the order in which
// the processes advance, the coupling interval of each sub-cycled process (a
// time, or `own`: the process's own proposed step), and the initial stage that
// brings the blocks to rest before the coupled run. Process names are those of
// `physics`.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "core/scene/coupling_names.h"
#include "core/scene/scene_draft.h"
#include "core/scene/scene_keys.h"
#include "core/scene/scene_section.h"

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
  draft.scene.coupling.order_location = node.location();
}

/// A scalar that starts with a letter: a name, not a quantity.
bool is_word(const ConfigNode& node) {
  return node.is_scalar() && !node.text().empty() &&
         std::isalpha(static_cast<unsigned char>(node.text()[0]));
}

void read_intervals(const ConfigNode& node, SceneDraft& draft) {
  if (!node.is_map()) {
    node.error("found " + node.found() +
               "; expected a map from process names to coupling intervals, such as "
               "{<process>: 10 ms}");
    return;
  }
  for (std::size_t k = 0; k < node.entries(); ++k) {
    const std::optional<std::string> name = process_name(node.key(k), draft);
    if (!name) continue;
    const ConfigNode value = node.value(k, node.path() + "." + *name);
    if (is_word(value)) {
      if (value.text() == "own")
        draft.scene.coupling.own_intervals.insert(*name);
      else
        value.error("found " + value.found() +
                    "; expected a time >= 0 or 'own' (the process's own proposed step)");
    } else if (const auto interval = value.quantity(quantity::time, Range::non_negative())) {
      draft.scene.coupling.intervals[*name] = *interval;
    }
  }
}

/// `iteration.fields`: a map from exchanged field names (those the scene's
/// processes declare, SectionReader::exchanges) to their own tolerances, the
/// absolute one in the field's unit.
void read_field_tolerances(const ConfigNode& node, SceneDraft& draft) {
  if (!node.is_map()) {
    node.error("found " + node.found() +
               "; expected a map from exchanged field names to tolerances, such as "
               "{<field>: {relative: 1e-6, absolute: <a value in its unit>}}");
    return;
  }
  for (std::size_t k = 0; k < node.entries(); ++k) {
    const ConfigNode key = node.key(k);
    const std::optional<std::string> name = key.string("an exchanged field name");
    if (!name) continue;
    const ExchangedFieldKind* field = exchanged_field(draft.scene, *name);
    if (!field) {
      if (draft.physics_read) {
        const std::string names = exchanged_field_names(draft.scene);
        key.error(
            "found '" + *name + "', which no process of physics exchanges; expected " +
            (names.empty() ? std::string("no fields (none is exchanged)") : "one of: " + names));
      }
      continue;
    }
    ConfigMap map(node.value(k, node.path() + "." + *name), scene_keys::field_tolerance);
    CouplingSettings::Iteration::FieldTolerance& t = draft.scene.coupling.iteration.fields[*name];
    if (auto r = map.optional("relative"))
      t.relative = r->quantity(quantity::dimensionless, Range::open(0, 1));
    if (auto a = map.optional("absolute"))
      t.absolute = a->quantity(*field->quantity, Range::positive());
  }
}

void read_iteration(const ConfigNode& node, SceneDraft& draft) {
  ConfigMap map(node, scene_keys::iteration);
  CouplingSettings::Iteration& it = draft.scene.coupling.iteration;
  map.read("tolerance", it.tolerance, quantity::dimensionless, Range::open(0, 1));
  map.read("max_iterations", it.max_iterations, 1);
  if (auto r = map.optional("relaxation"))
    if (const auto name = r->choice(enum_names(kRelaxationNames)))
      it.relaxation = value_of(kRelaxationNames, *name);
  // Aitken's factor is clipped to [0.05, 1] (theory.md 6.1); so is its start.
  map.read("omega", it.omega, quantity::dimensionless, Range::closed(0.05, 1));
  map.read("freeze_states_after", it.freeze_states_after, 0);
  if (auto f = map.optional("fields")) read_field_tolerances(*f, draft);
  map.finish();
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

void read_quasi_static(const ConfigNode& node, SceneDraft& draft) {
  ConfigMap map(node, scene_keys::quasi_static);
  CouplingSettings::QuasiStatic q;
  if (auto list = map.required("processes", "a list of process names"))
    if (auto names = process_names(*list, draft)) q.processes = std::move(*names);
  map.read("max_speed", q.max_speed, quantity::velocity, Range::open(0, 1e4));
  map.read("max_steps", q.max_steps, 1);
  draft.scene.coupling.quasi_static = q;
}

}  // namespace

void read_coupling(ConfigMap& top, SceneDraft& draft) {
  std::optional<ConfigNode> node = top.optional("coupling");
  if (!node) return;
  ConfigMap map(*node, scene_keys::coupling);
  using Scheme = CouplingSettings::Scheme;
  if (auto s = map.optional("scheme"))
    if (const auto name = s->choice(enum_names(kSchemeNames)))
      draft.scene.coupling.scheme = value_of(kSchemeNames, *name);
  if (auto o = map.optional("order")) read_order(*o, draft);
  if (auto i = map.optional("intervals")) read_intervals(*i, draft);
  if (auto i = map.optional("iteration")) {
    if (draft.scene.coupling.scheme == Scheme::Iterated)
      read_iteration(*i, draft);
    else
      i->error_at_key(
          "found the iterated scheme's controls; expected them only with "
          "coupling.scheme: iterated");
  }
  if (auto e = map.optional("initial_equilibrium")) read_initial_equilibrium(*e, draft);
  if (auto q = map.optional("quasi_static")) read_quasi_static(*q, draft);
  map.finish();
  const CouplingSettings& c = draft.scene.coupling;
  const bool every_one_sub_cycled =
      draft.physics_read && !draft.scene.physics.empty() &&
      std::all_of(draft.scene.physics.begin(), draft.scene.physics.end(),
                  [&c](const std::string& p) {
                    const auto it = c.intervals.find(p);
                    return (it != c.intervals.end() && it->second > 0) || c.own_intervals.count(p);
                  });
  if (every_one_sub_cycled)
    node->error(
        "found a coupling interval for every process; expected at least one process that "
        "advances every step (it sets the time step the others are sub-cycled in)");
}

}  // namespace fissure
