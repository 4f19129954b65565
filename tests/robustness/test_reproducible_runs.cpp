// Reproducible to the bit (issue 22, item 5): the same scene with the same
// options on the same build writes the same bytes, however loaded the
// machine is. The scene is a 420-brick dynamic wall above the `auto`
// solver's direct threshold, where the choice between pcg and the reused
// factorization used to be made from measured times: three runs of its 120
// steps gave three different monitors.csv before the choice was made by
// model costs (core/linear/linear_cost.h). The runs share the cores with
// threads that keep them busy, so that a decision taken from the clock would
// show.
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "tests/support/run_scene.h"

namespace fissure::testing {
namespace {

namespace fs = std::filesystem;

/// Keeps every core busy with a spinning thread while it lives.
class BusyCores {
 public:
  BusyCores() {
    const unsigned n = std::max(1u, std::thread::hardware_concurrency());
    for (unsigned k = 0; k < n; ++k)
      threads_.emplace_back([this] {
        volatile double x = 1;
        while (!stop_.load(std::memory_order_relaxed)) x = x * 1.0000001 + 1e-9;
      });
  }
  ~BusyCores() {
    stop_ = true;
    for (std::thread& t : threads_) t.join();
  }

 private:
  std::atomic<bool> stop_{false};
  std::vector<std::thread> threads_;
};

TEST(ReproducibleRuns, ThreeRunsOfADynamicWallWriteTheSameBytesOnBusyCores) {
  const fs::path dir = scratch_dir("reproducible_runs");
  const fs::path scene = dir / "wall_420.yaml";
  ASSERT_FALSE(generated_brick_wall(scene.string(), 20, 20).empty());

  const BusyCores busy;
  std::vector<fs::path> runs;
  for (int run = 0; run < 3; ++run) {
    const fs::path out = dir / ("run" + std::to_string(run));
    const std::string command = std::string("\"") + FISSURE_APP + "\" run \"" + scene.string() +
                                "\" -q --no-plots --max-steps 120 -o \"" + out.string() +
                                "\" > \"" + (dir / "log.txt").string() + "\" 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << file_bytes(dir / "log.txt");
    runs.push_back(out);
  }

  // Above the direct threshold, with both back ends in use.
  const nlohmann::json summary = nlohmann::json::parse(file_bytes(runs[0] / "summary.json"));
  const nlohmann::json& solver = summary["processes"]["mechanics"]["linear_solver"];
  EXPECT_GT(solver["reused_factorization"]["solves"].get<long>(), 0);
  EXPECT_GT(solver["pcg"]["solves"].get<long>() + solver["pcg_fallbacks"].get<long>(), 0);

  for (const char* file : {"monitors.csv", "results.h5", "results.xdmf"}) {
    const std::string first = file_bytes(runs[0] / file);
    EXPECT_GT(first.size(), 0u) << file;
    for (std::size_t run = 1; run < runs.size(); ++run)
      EXPECT_TRUE(file_bytes(runs[run] / file) == first)
          << file << " of run " << run << " differs from run 0's";
  }
  const nlohmann::json first = without_measured_times(summary);
  for (std::size_t run = 1; run < runs.size(); ++run)
    EXPECT_EQ(without_measured_times(nlohmann::json::parse(file_bytes(runs[run] / "summary.json"))),
              first)
        << "summary.json of run " << run;
}

}  // namespace
}  // namespace fissure::testing
