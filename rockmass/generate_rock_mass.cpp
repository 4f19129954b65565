#include "rockmass/generate_rock_mass.h"

#include "core/base/stopwatch.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/base/errors.h"
#include "rockmass/block_cutter.h"
#include "rockmass/block_estimate.h"
#include "rockmass/dfn_generator.h"
#include "rockmass/joint_sets.h"

namespace fissure {

namespace {

constexpr std::uint64_t kDfnStream = 0x10000;

/// Refuses a rock mass that would be too large, before anything is built.
void check_size(const RockMassSpec& spec, const RockMassEstimate& e) {
  // A length law whose moments overflow (a power law of exponent 10 down to
  // 1e-40 m) would draw a NaN number of fractures: refused, not drawn as none.
  if (!std::isfinite(e.fractures) || !std::isfinite(e.blocks))
    throw GeometryError(
        "found joint sets or DFN families whose size cannot be estimated (a length "
        "distribution whose moments overflow double precision); expected length parameters "
        "within a few orders of magnitude of the domain");
  if (e.fractures > static_cast<double>(spec.max_fractures))
    throw GeometryError(fmt::format(
        "found joint sets and DFN families that would generate about {:.3g} fractures, more "
        "than max_fractures = {}; expected lower densities, larger spacings or a larger "
        "max_fractures",
        e.fractures, spec.max_fractures));
  if (e.blocks > static_cast<double>(spec.max_blocks))
    throw GeometryError(fmt::format(
        "found joint sets and DFN families that would cut the rock into about {:.3g} blocks "
        "({:.3g} fractures, {:.3g} expected intersections), more than max_blocks = {}; "
        "expected lower densities, larger spacings or a larger max_blocks",
        e.blocks, e.fractures, e.intersections, spec.max_blocks));
}

bool touches(const CutBlock& block, const std::vector<std::vector<std::string>>& names,
             const std::vector<std::string>& wanted) {
  for (int source : block.edge_source) {
    if (source >= 0) continue;
    for (const std::string& n : names[-1 - source])
      if (std::find(wanted.begin(), wanted.end(), n) != wanted.end()) return true;
  }
  return false;
}

}  // namespace

std::string set_name(const RockMassSpec& spec, int set) {
  const int n_sets = static_cast<int>(spec.joint_sets.size());
  if (set < 0) return "";
  if (set < n_sets) return spec.joint_sets[set].name;
  if (set - n_sets < static_cast<int>(spec.dfn.size())) return spec.dfn[set - n_sets].name;
  return "";
}

std::vector<FractureTrace> generate_traces(const RockMassSpec& spec) {
  return generate_traces(spec, 0);
}

std::vector<FractureTrace> generate_traces(const RockMassSpec& spec, int realization) {
  const std::uint64_t shift = static_cast<std::uint64_t>(realization) << 32;
  Box box;
  for (const Vec2& p : spec.domain) box.extend(p);
  std::vector<FractureTrace> traces;
  const int n_sets = static_cast<int>(spec.joint_sets.size());
  for (int s = 0; s < n_sets; ++s) {
    Rng rng(spec.seed, shift + static_cast<std::uint64_t>(s));
    generate_joint_set(spec.joint_sets[s], s, box, rng, traces);
  }
  for (int f = 0; f < static_cast<int>(spec.dfn.size()); ++f) {
    Rng rng(spec.seed, shift + kDfnStream + static_cast<std::uint64_t>(f));
    for (const DfnFracture& fracture : generate_dfn_family(spec.dfn[f], box, rng))
      traces.push_back(fracture.trace(n_sets + f, spec.dfn[f].joint));
  }
  for (const FractureSpec& f : spec.fractures)
    traces.push_back(FractureTrace{f.from, f.to, -1, f.joint, f.aperture});
  return traces;
}

CutInput cut_input(const RockMassSpec& spec) {
  CutInput input;
  input.domain = spec.domain;
  input.excavations = spec.excavations;
  input.traces = generate_traces(spec);
  input.merge_tolerance = spec.merge_tolerance;
  return input;
}

GeneratedRockMass generate_rock_mass(const RockMassSpec& spec) {
  GeneratedRockMass out;
  RockMassStatistics& stats = out.statistics;

  // 1. Size check, then the traces.
  const RockMassEstimate estimate = estimate_rock_mass(spec);
  check_size(spec, estimate);  // refuses an estimate that is not a number before it is cast
  stats.estimated_blocks = static_cast<long>(estimate.blocks);
  Stopwatch clock;
  const CutInput input = cut_input(spec);
  stats.generated_fractures = static_cast<long>(input.traces.size());
  stats.generation_seconds = clock.lap();

  // 2. Cutting.
  CutResult cut = cut_blocks(input);
  stats.cutting_seconds = clock.lap();
  stats.cut_fractures = cut.statistics.traces_used;
  stats.slivers_merged = cut.statistics.slivers_merged;
  stats.vertices_merged = cut.statistics.vertices_merged;
  stats.invalid_merged = cut.statistics.invalid_merged;
  if (static_cast<long>(cut.blocks.size()) > spec.max_blocks)
    throw GeometryError(
        fmt::format("found {} blocks after cutting, more than max_blocks = {}; "
                    "expected fewer fractures or a larger max_blocks",
                    cut.blocks.size(), spec.max_blocks));

  // 3. Block specs: per-edge joints from the fractures, fixed blocks.
  out.blocks.reserve(cut.blocks.size());
  for (size_t b = 0; b < cut.blocks.size(); ++b) {
    CutBlock& c = cut.blocks[b];
    BlockSpec block;
    block.name = fmt::format("rock{}", b);
    block.material = spec.material;
    block.edge_joint.reserve(c.edge_source.size());
    for (int source : c.edge_source)
      block.edge_joint.push_back(source >= 0 ? input.traces[source].joint : -1);
    const SectionProperties section = section_properties(c.polygon);
    block.fixed =
        (!spec.fixed.boundaries.empty() && touches(c, cut.boundary_names, spec.fixed.boundaries)) ||
        (spec.fixed.below && section.centroid.y() < *spec.fixed.below);
    block.initial_stress = spec.initial_stress;
    block.polygon = std::move(c.polygon);
    out.blocks.push_back(std::move(block));
  }
  out.fractures = std::move(cut.graph);
  for (const JointSetSpec& s : spec.joint_sets) out.fractures.set_names.push_back(s.name);
  for (const DfnFamilySpec& f : spec.dfn) out.fractures.set_names.push_back(f.name);
  return out;
}

}  // namespace fissure
