#include "flow/rev/rev_dfn_source.h"

#include <fmt/format.h>

#include <cstdint>
#include <memory>

#include "core/scene/config_map.h"
#include "rockmass/block_estimate.h"
#include "rockmass/dfn_generator.h"
#include "rockmass/read_rock_mass.h"

namespace fissure {

namespace {

constexpr std::string_view kDfn[] = {"region", "seed", "families"};
const KeyTable dfn_table{"network.dfn", kDfn};

/// Per realization: the fractures of every family are kept in memory by
/// flow::TraceSource, and every domain of every size and rotation clips them
/// and builds its network (5.7e5 fractures: 15 s per realization of
/// configs/flow_rev_study.yaml), so a study that would draw more is refused.
constexpr double kMaxExpectedFractures = 1e5;

/// Stream of family f in realization r: realization 0 uses the rock mass's
/// streams (rockmass/generate_rock_mass.h), every realization its own.
constexpr std::uint64_t kDfnStream = 0x10000;

struct RevDfn {
  std::vector<DfnFamilySpec> families;
  Box region;
  std::uint64_t seed = 1;
};

std::unique_ptr<flow::DomainSource> read_dfn_source(const ConfigNode& node, const Vec2& centre) {
  const std::size_t problems = node.diagnostics().size();
  ConfigMap map(node, dfn_table);
  auto dfn = std::make_shared<RevDfn>();
  double side = 0;
  map.read_required("region", side, quantity::length, Range::positive());
  if (auto s = map.optional("seed"))
    if (auto v = s->integer(0)) dfn->seed = static_cast<std::uint64_t>(*v);
  NameRegistry names("DFN family");
  if (auto s = map.required("families", "a list of DFN families (docs/rock-mass.md section 3)"))
    if (auto items = s->list("DFN families", true))
      for (const ConfigNode& item : *items) dfn->families.push_back(read_dfn_family(item, names));
  map.finish();
  if (node.diagnostics().size() > problems) return nullptr;
  dfn->region.extend(centre - Vec2(side / 2, side / 2));
  dfn->region.extend(centre + Vec2(side / 2, side / 2));
  double expected = 0;
  for (const DfnFamilySpec& family : dfn->families)
    expected += expected_dfn_fractures(family, dfn->region);
  if (!(expected <= kMaxExpectedFractures)) {  // also NaN: moments that overflow
    node.error(fmt::format(
        "found {:.3g} fractures expected per realization in the {} m region; expected at most "
        "{:.0g} (a smaller region or lower densities)",
        expected, side, kMaxExpectedFractures));
    return nullptr;
  }
  std::string description = fmt::format("rock-mass DFN of {} families in a {} m square (seed {})",
                                        dfn->families.size(), side, dfn->seed);
  double traces_per_area = 0;
  for (const DfnFamilySpec& family : dfn->families) traces_per_area += dfn_p20(family);
  return std::make_unique<flow::TraceSource>(
      [dfn](int realization) {
        return draw_dfn_traces(dfn->families, dfn->region, dfn->seed, realization);
      },
      centre, std::move(description),
      flow::TraceDensity{traces_per_area, dfn_crossing_density(dfn->families)});
}

}  // namespace

std::vector<flow::Trace> draw_dfn_traces(const std::vector<DfnFamilySpec>& families,
                                         const Box& region, std::uint64_t seed, int realization) {
  std::vector<flow::Trace> traces;
  for (std::size_t f = 0; f < families.size(); ++f) {
    Rng rng(seed, (static_cast<std::uint64_t>(realization) << 32) + kDfnStream + f);
    for (const DfnFracture& fracture : generate_dfn_family(families[f], region, rng)) {
      const FractureTrace t = fracture.trace(static_cast<int>(f), -1);
      traces.push_back(
          flow::Trace{t.a, t.b, t.aperture, static_cast<int>(traces.size()), static_cast<int>(f)});
    }
  }
  return traces;
}

flow::DfnSourceFactory rev_dfn_source_factory() {
  return read_dfn_source;
}

std::vector<std::string> rev_dfn_study_keys() {
  std::vector<std::string> keys;
  for (std::string_view k : dfn_table.keys)
    keys.push_back(std::string(dfn_table.section) + "." + std::string(k));
  for (std::string_view k : rock_mass_keys::dfn_family.keys)
    keys.push_back(std::string(dfn_table.section) + ".families[]." + std::string(k));
  return keys;
}

}  // namespace fissure
