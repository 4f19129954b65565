// Runs a Scene through the coordinator into a scratch output folder
// (build/test-output/<name>) and returns the summary and the final state.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "core/io/summary_writer.h"
#include "core/scene/scene.h"
#include "core/state/rock_mass.h"

namespace fissure {
class Coordinator;  // coupling/coordinator.h
}

namespace fissure::testing {

struct RunResult {
  RunSummary summary;
  RockMass state;
  std::string outdir;  ///< where the run wrote its files
  /// The run's coordinator, for its processes' inner state after the run.
  std::shared_ptr<Coordinator> coordinator;
};

RunResult run_scene(const Scene& scene, const std::string& output_name);

/// A file's bytes (empty, with a test failure, when it cannot be read).
std::string file_bytes(const std::string& file);

/// summary.json without the measured times (keys "seconds", "*_seconds"),
/// which differ run to run by nature; the model costs the solvers decide by
/// ("model_seconds") are kept.
nlohmann::json without_measured_times(nlohmann::json j);

/// Scratch folder for a test's files (created, emptied):
/// build/test-output/<name>/<suite>.<test> inside a GoogleTest test.
std::string scratch_dir(const std::string& name);

/// A staggered brick wall of `courses` x `bricks` DDA scene written to
/// `file` by scripts/generate_brick_wall.py; its text (empty, with a test
/// failure, when the script fails).
std::string generated_brick_wall(const std::string& file, int courses, int bricks);

}  // namespace fissure::testing
