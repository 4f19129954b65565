// Glue for `fissure rev`: the REV study (flow/rev) takes its DFN realizations
// from a pluggable source; a source built on the rock-mass geometry's DFN
// generator (mechanics/blocks) must live here, since flow/ may not include
// mechanics/ (architecture.md 1).
#pragma once

#include "flow/rev/read_rev_study.h"

namespace fissure {

/// The factory for a study's `network: {type: dfn, dfn: {...}}`; empty while
/// no DFN generator is available in mechanics/ (the study then says so).
flow::DfnSourceFactory rev_dfn_source_factory();

}  // namespace fissure
