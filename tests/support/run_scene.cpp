#include "tests/support/run_scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "coupling/coordinator.h"

namespace fissure::testing {

std::string file_bytes(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  EXPECT_TRUE(in.good()) << file;
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

nlohmann::json without_measured_times(nlohmann::json j) {
  if (j.is_object()) {
    nlohmann::json kept = nlohmann::json::object();
    for (auto& [key, value] : j.items()) {
      const bool measured = key != "model_seconds" && key.size() >= 7 &&
                            key.compare(key.size() - 7, 7, "seconds") == 0;
      if (!measured) kept[key] = without_measured_times(value);
    }
    return kept;
  }
  if (j.is_array())
    for (auto& item : j) item = without_measured_times(item);
  return j;
}

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

std::string generated_brick_wall(const std::string& file, int courses, int bricks) {
  const std::string generate = "python3 \"" FISSURE_SOURCE_DIR
                               "/scripts/generate_brick_wall.py\" --courses " +
                               std::to_string(courses) + " --bricks " + std::to_string(bricks) +
                               " -o \"" + file + "\" > /dev/null";
  const int status = std::system(generate.c_str());
  EXPECT_EQ(status, 0) << generate;
  return status == 0 ? file_bytes(file) : std::string();
}

RunResult run_scene(const Scene& scene, const std::string& output_name) {
  RunOptions options;
  options.outdir = scratch_dir(output_name);
  options.quiet = true;
  RunResult r;
  r.coordinator = std::make_shared<Coordinator>(scene, options);
  r.summary = r.coordinator->run();
  r.state = r.coordinator->state();
  r.outdir = options.outdir;
  return r;
}

}  // namespace fissure::testing
