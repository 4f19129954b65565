#include "tests/support/run_scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "coupling/coordinator.h"

namespace fissure::testing {

std::string scratch_dir(const std::string& name) {
  // ctest runs every test in its own process, in parallel: each test gets
  // its own folder under `name`, so that one test never empties another's.
  std::filesystem::path dir = std::filesystem::path(FISSURE_BINARY_DIR) / "test-output" / name;
  if (const auto* info = ::testing::UnitTest::GetInstance()->current_test_info()) {
    std::string test = std::string(info->test_suite_name()) + "." + info->name();
    std::replace(test.begin(), test.end(), '/', '_');
    dir /= test;
  }
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
  r.outdir = options.outdir;
  return r;
}

}  // namespace fissure::testing
