// The DFN realizations of a REV study (`network: {type: dfn}`), drawn with
// the rock mass's DFN generator (rockmass/dfn_generator.h), so that a study
// and a scene with the same families and seed see the same fractures. The
// study reader takes its DFN source as a factory (read_rev_study.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/geometry/polygon.h"
#include "flow/network/trace_network.h"
#include "flow/rev/read_rev_study.h"
#include "rockmass/rock_mass_spec.h"

namespace fissure {

/// The factory for a study's `network: {type: dfn, dfn: {region, seed,
/// families}}` (docs/flow.md section 8): the families have the keys of a
/// scene's `rock_mass.dfn[]` items (docs/rock-mass.md section 3) and are drawn
/// over the square `region` centred on `network.centre`. Realization r draws
/// family f from the stream (seed, 2^32 r + 0x10000 + f), so realization 0 is
/// the DFN of a rock mass with the same seed, families and domain.
flow::DfnSourceFactory rev_dfn_source_factory();

/// Realization r of the DFN `families` over `region` (the streams above), as
/// flow traces; also the networks of the flow benchmarks.
std::vector<flow::Trace> draw_dfn_traces(const std::vector<DfnFamilySpec>& families,
                                         const Box& region, std::uint64_t seed, int realization);

/// Keys of `network.dfn` with their documented paths ("network.dfn.region",
/// "network.dfn.families[].density", ...), for the documentation test.
std::vector<std::string> rev_dfn_study_keys();

}  // namespace fissure
