#include "tests/support/run_scene.h"

#include <filesystem>

#include "coupling/coordinator.h"

namespace fissure::testing {

std::string scratch_dir(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(FISSURE_BINARY_DIR) / "test-output" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

RunResult run_scene(const Scene& scene, const std::string& output_name) {
  RunOptions options;
  options.outdir = scratch_dir(output_name);
  options.quiet = true;
  Coordinator coordinator(scene, options);
  RunResult r;
  r.summary = coordinator.run();
  r.state = coordinator.state();
  return r;
}

}  // namespace fissure::testing
