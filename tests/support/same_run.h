// Two output folders that must hold the same run to the bit (docs/output.md,
// "Checkpoint and restart"): a restarted run and its uninterrupted run, or
// two runs of the same scene on the same ranks.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>

namespace fissure::testing {

/// summary.json as a restarted run must match its uninterrupted run: without
/// measured times and exactly the counts docs/output.md lists as differing
/// after a restart ("Checkpoint and restart", "Restart").
nlohmann::json comparable_summary(const std::filesystem::path& file);

/// monitors.csv and results.xdmf byte for byte, every dataset below
/// results.h5's /frames to the bit, and the comparable summaries.
void expect_same_run(const std::filesystem::path& uninterrupted,
                     const std::filesystem::path& restarted);

}  // namespace fissure::testing
