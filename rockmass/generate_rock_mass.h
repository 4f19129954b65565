// From a scene's `rock_mass` section to blocks and a fracture graph
// (docs/rock-mass.md): size estimate, joint sets, DFN families and explicit
// fractures, block cutting, block specs with per-edge joints, fixed blocks.
// Deterministic for a given seed.
#pragma once

#include <vector>

#include "core/scene/scene.h"
#include "rockmass/block_cutter.h"
#include "rockmass/fracture_graph.h"
#include "rockmass/fracture_trace.h"
#include "rockmass/rock_mass_spec.h"

namespace fissure {

/// The blocks and fracture graph generated from a `rock_mass` section.
struct GeneratedRockMass {
  std::vector<BlockSpec> blocks;  ///< oriented (outer loop counter-clockwise, holes clockwise)
  FractureGraph fractures;        ///< block indices into `blocks`
  RockMassStatistics statistics;
};

/// Every trace of the rock mass before cutting: joint sets (set index s),
/// then DFN families (set index n_joint_sets + f), then explicit fractures
/// (set -1). Random streams: joint set s uses stream s, DFN family f stream
/// 0x10000 + f, both of the rock mass's seed.
std::vector<FractureTrace> generate_traces(const RockMassSpec& spec);

/// Realization r of the same rock mass (a REV study's, docs/upscaling.md):
/// every stream of generate_traces shifted by 2^32 r (realization 0 is
/// generate_traces(spec); the REV study's DFN source uses the same streams).
std::vector<FractureTrace> generate_traces(const RockMassSpec& spec, int realization);

/// The cutter's input for the spec: its domain, excavations, merge tolerance
/// and freshly generated traces.
CutInput cut_input(const RockMassSpec& spec);

/// The rock mass of a section (read_rock_mass.h generates with it). Throws
/// GeometryError when the estimate exceeds max_fractures or max_blocks (the
/// message gives the estimate), or when the cut produces more than
/// max_blocks blocks.
GeneratedRockMass generate_rock_mass(const RockMassSpec& spec);

/// Name of the joint set or DFN family with set index `set` ("" for -1).
std::string set_name(const RockMassSpec& spec, int set);

}  // namespace fissure
