// summary.json (docs/architecture.md 6).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/scene/units.h"

namespace fissure {

struct RunSummary {
  std::string scene;
  /// The scene file, absolute (recorded_file_path); empty for a scene built
  /// in code. A run without -o refuses a folder whose summary names another
  /// file (coupling/output_folder.h).
  std::string scene_file;
  std::string status = "running";  ///< completed | diverged | failed | running
  std::string message;             ///< why it stopped when not completed
  long steps = 0;
  double simulated_time = 0;  ///< s
  TimeUnit time_unit;         ///< the scene's unit of time, for readers (docs/output.md)
  double wall_seconds = 0;
  int output_frames = 0;
  nlohmann::json processes = nlohmann::json::object();  ///< per-process statistics
  nlohmann::json monitors = nlohmann::json::object();   ///< final monitor values
  /// The monitor columns the command line prints when the run ends (not
  /// written to the file).
  std::vector<std::string> brief_monitor_columns;
  nlohmann::json energy = nlohmann::json::object();  ///< energy terms (J per unit thickness)
  /// The generated rock mass (blocks, fractures, connectivity); written only
  /// when not empty (`fissure mesh`; docs/rock-mass.md).
  nlohmann::json rock_mass = nlohmann::json::object();
};

/// How a command's output records its input file: absolute, normalized,
/// symbolic links resolved; empty for an empty path.
std::string recorded_file_path(const std::filesystem::path& file);

/// Writes atomically (temporary file + rename), so a reader never sees half a file.
void write_summary(const std::filesystem::path& file, const RunSummary& summary);

}  // namespace fissure
