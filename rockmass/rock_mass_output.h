// What `fissure mesh` writes (docs/rock-mass.md section 7): the generated
// blocks and fracture graph of a scene as frame 0 of results.h5 /
// results.xdmf, and summary.json with the counts and the connectivity of the
// fracture network, without running any physics.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/scene/scene.h"

namespace fissure {

/// Counts (blocks, fixed blocks, fractures, graph nodes and segments), the
/// connectivity analysis (components, isolated and dead-end components,
/// dead-end segments, percolation between every pair of named boundaries),
/// the merges and the generation and cutting times.
nlohmann::json rock_mass_summary(const Scene& scene);

/// Writes OUTDIR/results.h5, results.xdmf (frame 0 at t = 0) and
/// summary.json (status "meshed", the summary above under "rock_mass").
void write_rock_mass(const Scene& scene, const std::filesystem::path& outdir);

}  // namespace fissure
