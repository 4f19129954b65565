#include "flow/rev/read_rev_study.h"

#include <fmt/format.h>

#include <fstream>
#include <sstream>

#include "core/base/errors.h"
#include "core/scene/config_map.h"
#include "core/scene/parse_scene.h"
#include "flow/network/read_fluid.h"

namespace fissure::flow {

namespace {

constexpr std::string_view kTop[] = {"name",         "fluid",         "network",   "sizes",
                                     "realizations", "rotation_step", "rotations", "pressure_drop",
                                     "criterion",    "threads",       "max_nodes", "mechanics"};
constexpr std::string_view kNetwork[] = {"type", "centre", "sets", "traces", "dfn", "scene"};
constexpr std::string_view kSet[] = {"angle", "spacing", "aperture", "offset"};
constexpr std::string_view kTrace[] = {"from", "to", "aperture"};
constexpr std::string_view kSizes[] = {"from", "to", "count"};
constexpr std::string_view kCriterion[] = {"cv_max", "misfit_max"};

const KeyTable top_table{"", kTop};
const KeyTable fluid_table{"fluid", kFluidKeys};
const KeyTable network_table{"network", kNetwork};
const KeyTable set_table{"network.sets[]", kSet};
const KeyTable trace_table{"network.traces[]", kTrace};
const KeyTable sizes_table{"sizes", kSizes};
const KeyTable criterion_table{"criterion", kCriterion};

void read_sizes(const ConfigNode& node, std::vector<double>& sizes) {
  if (node.is_list()) {
    if (auto items = node.list("sizes (lengths)", true))
      for (const ConfigNode& item : *items)
        if (auto v = item.quantity(quantity::length, Range::positive())) {
          if (!sizes.empty() && *v <= sizes.back())
            item.error("found " + item.found() + "; expected sizes in increasing order");
          sizes.push_back(*v);
        }
    return;
  }
  ConfigMap map(node, sizes_table);
  double from = 0, to = 0;
  int count = 0;
  map.read_required("from", from, quantity::length, Range::positive());
  map.read_required("to", to, quantity::length, Range::positive());
  if (auto c = map.required("count", "an integer >= 1"))
    if (auto n = c->integer(1, 1000)) count = static_cast<int>(*n);
  if (count == 1) sizes.push_back(from);
  for (int i = 0; count > 1 && i < count; ++i)
    sizes.push_back(from + (to - from) * i / (count - 1));
  if (count > 1 && to <= from) map.node().error("found to <= from; expected increasing sizes");
}

std::unique_ptr<DomainSource> read_network(const ConfigNode& node, const RevStudyReaders& readers) {
  ConfigMap map(node, network_table);
  constexpr std::string_view kTypes[] = {"regular", "traces", "dfn", "scene"};
  std::optional<std::string> type;
  if (auto t = map.required("type", "regular, traces, dfn or scene")) type = t->choice(kTypes);
  std::optional<Vec2> given_centre;
  if (auto c = map.optional("centre")) given_centre = c->vec2(quantity::length);
  const Vec2 centre = given_centre.value_or(Vec2::Zero());
  if (!type) return nullptr;
  if (*type == "scene") {
    std::optional<ConfigNode> scene = map.required("scene", "the scene file of the rock mass");
    if (!readers.scene) {
      (scene ? *scene : map.node())
          .error(
              "found network type 'scene', but this program has no scene reader; expected "
              "type regular, traces or dfn");
      return nullptr;
    }
    return scene ? readers.scene(*scene, given_centre) : nullptr;
  }
  const DfnSourceFactory& dfn = readers.dfn;
  if (*type == "regular") {
    std::vector<ParallelSet> sets;
    if (auto s = map.required("sets", "a list of parallel sets {angle, spacing, aperture}"))
      if (auto items = s->list("parallel sets", true))
        for (const ConfigNode& item : *items) {
          ConfigMap m(item, set_table);
          ParallelSet set;
          m.read_required("angle", set.angle, quantity::angle);
          m.read_required("spacing", set.spacing, quantity::length, Range::positive());
          m.read_required("aperture", set.aperture, quantity::length, Range::positive());
          m.read("offset", set.offset, quantity::length);
          sets.push_back(set);
        }
    return std::make_unique<ParallelSetsSource>(std::move(sets), centre);
  }
  if (*type == "traces") {
    std::vector<Trace> traces;
    if (auto s = map.required("traces", "a list of traces {from, to, aperture}"))
      if (auto items = s->list("traces", true))
        for (const ConfigNode& item : *items) {
          ConfigMap m(item, trace_table);
          Trace t;
          if (auto n = m.required("from", "a point [x, y]"))
            if (auto p = n->vec2(quantity::length)) t.a = *p;
          if (auto n = m.required("to", "a point [x, y]"))
            if (auto p = n->vec2(quantity::length)) t.b = *p;
          m.read_required("aperture", t.aperture, quantity::length, Range::positive());
          t.fracture = static_cast<int>(traces.size());
          traces.push_back(t);
        }
    auto shared = std::make_shared<std::vector<Trace>>(std::move(traces));
    return std::make_unique<TraceSource>(
        [shared](int) { return *shared; }, centre,
        fmt::format("{} explicit traces", shared->size()),
        TraceDensity{.fixed_traces = static_cast<double>(shared->size())}, 1);
  }
  std::optional<ConfigNode> d = map.required("dfn", "the DFN generator's settings");
  if (!dfn) {
    (d ? *d : map.node())
        .error(
            "found network type 'dfn', but this program has no DFN generator; "
            "expected type regular or traces");
    return nullptr;
  }
  return d ? dfn(*d, centre) : nullptr;
}

}  // namespace

std::vector<std::string> known_rev_study_keys() {
  const KeyTable* tables[] = {&top_table,   &fluid_table, &network_table,  &set_table,
                              &trace_table, &sizes_table, &criterion_table};
  return documented_keys(tables);
}

RevStudy read_rev_study_text(const std::string& yaml, const std::string& file_name,
                             const DfnSourceFactory& dfn) {
  return read_rev_study_text(yaml, file_name, RevStudyReaders{dfn, {}, {}});
}

RevStudy read_rev_study(const std::filesystem::path& file, const RevStudyReaders& readers) {
  return read_rev_study_text(read_input_file(file, "a REV study (YAML)"), file.string(), readers);
}

RevStudy read_rev_study_text(const std::string& yaml, const std::string& file_name,
                             const RevStudyReaders& readers) {
  Diagnostics diagnostics(file_name);
  const std::optional<ConfigNode> doc = load_document(yaml, "REV study", diagnostics);
  diagnostics.throw_if_any();
  RevStudy study;
  RevStudyConfig& c = study.config;
  c.name = std::filesystem::path(file_name).stem().string();
  {
    ConfigMap map(*doc, top_table);
    if (auto n = map.optional("name"))
      if (auto s = n->string("a study name")) c.name = *s;
    if (auto f = map.optional("fluid")) read_fluid(*f, fluid_table, c.fluid);
    if (auto n = map.required("network", "a network section {type: regular | traces | dfn, ...}")) {
      study.source = read_network(*n, readers);
      c.network_location = n->located_path();
    }
    if (auto n = map.required("sizes", "a list of sizes, or {from, to, count}")) {
      read_sizes(*n, c.sizes);
      c.sizes_location = n->located_path();
    }
    map.read("realizations", c.realizations, 1);
    map.read("rotation_step", c.rotation_step, quantity::angle, Range::open(0, 3.15));
    map.read("rotations", c.rotations, 1);
    map.read("pressure_drop", c.pressure_drop, quantity::pressure, Range::positive());
    if (auto n = map.optional("criterion")) {
      ConfigMap m(*n, criterion_table);
      m.read("cv_max", c.cv_max, quantity::dimensionless, Range::positive());
      m.read("misfit_max", c.misfit_max, quantity::dimensionless, Range::positive());
    }
    map.read("threads", c.threads, 0);
    map.read("max_nodes", c.max_nodes, quantity::dimensionless, Range::positive());
    if (auto n = map.optional("mechanics")) {
      if (readers.mechanics)
        readers.mechanics(*n);
      else
        n->error("found a mechanics section, but this program has no stress stage");
    }
  }
  diagnostics.throw_if_any();
  return study;
}

RevStudy read_rev_study(const std::filesystem::path& file, const DfnSourceFactory& dfn) {
  return read_rev_study_text(read_input_file(file, "a REV study (YAML)"), file.string(), dfn);
}

}  // namespace fissure::flow
