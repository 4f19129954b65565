// REV study output (docs/flow.md "REV study"): OUTDIR/
//   domains.csv  one row per square: size, realization, rotation, kxx, kyx, kxy, kyy, ...
//   fits.csv     one row per (size, realization): fitted tensor, principal values, misfit
//   sizes.csv    one row per size: means, spreads, CV, misfit, criterion met
//   rev.json     configuration, per-size statistics, REV size, timings
// The PNG plots come from scripts/plot_rev.py OUTDIR.
#pragma once

#include <filesystem>

#include "flow/rev/rev_study.h"

namespace fissure::flow {

void write_rev_output(const RevStudyResult& result, const std::filesystem::path& outdir);

}  // namespace fissure::flow
