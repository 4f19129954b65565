// Runs a Scene through the coordinator into a scratch output folder
// (build/test-output/<name>) and returns the summary and the final state.
#pragma once

#include <string>

#include "core/io/summary_writer.h"
#include "core/scene/scene.h"
#include "core/state/rock_mass.h"

namespace fissure::testing {

struct RunResult {
  RunSummary summary;
  RockMass state;
  std::string outdir;  ///< where the run wrote its files
};

RunResult run_scene(const Scene& scene, const std::string& output_name);

/// Scratch folder for a test's files (created, emptied):
/// build/test-output/<name>/<suite>.<test> inside a GoogleTest test.
std::string scratch_dir(const std::string& name);

}  // namespace fissure::testing
