// The explicit DEM's loops run on OpenMP threads (docs/dem.md section 2):
// each contact's loads go to its own slots and are summed per block in the
// contacts' order, so a run writes the same bytes whatever the number of
// threads. The scene is a 30 x 30 staggered wall (915 blocks, about 5,700
// contacts, above the 4,096 from which the loops run in parallel), run for
// 2 updates of 100 cycles with OMP_NUM_THREADS = 1 and 2.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/run_scene.h"
#include "tests/support/same_run.h"

namespace fissure::testing {
namespace {

namespace fs = std::filesystem;

/// `fissure run` of `scene` on `threads` threads into `out`; its exit code.
int run_on_threads(const fs::path& scene, const fs::path& out, int threads) {
  std::string command = "OMP_NUM_THREADS=";
  command += std::to_string(threads);
  command += " \"" FISSURE_APP "\" run \"";
  command += scene.string();
  command += "\" -q --no-plots -o \"";
  command += out.string();
  command += "\" --max-steps 2 > \"";
  command += out.string();
  command += ".log\" 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(DemThreads, TheSameBitsOnOneAndTwoThreads) {
  const fs::path dir = scratch_dir("dem_threads");
  const fs::path scene = dir / "wall.yaml";
  std::string text = generated_brick_wall(scene.string(), 30, 30);
  ASSERT_FALSE(text.empty());
  // The DDA's wall as a DEM scene: joints with stiffnesses, a dem section.
  text.replace(text.find("physics: [mechanics]"), 20, "physics: [dem]");
  const std::string joint = "tensile_strength: 0}";
  text.replace(text.find(joint), joint.size(),
               "tensile_strength: 0, normal_stiffness: 10 GPa/m, shear_stiffness: 5 GPa/m}");
  text = text.substr(0, text.find("mechanics:\n")) +
         "dem: {rounding: 5 mm}\ntime: {end: 1}\noutput: {every_steps: 2}\n";
  std::ofstream(scene) << text;

  ASSERT_EQ(run_on_threads(scene, dir / "one", 1), 0)
      << file_bytes((dir / "one").string() + ".log");
  ASSERT_EQ(run_on_threads(scene, dir / "two", 2), 0)
      << file_bytes((dir / "two").string() + ".log");
  const nlohmann::json summary = nlohmann::json::parse(file_bytes(dir / "two" / "summary.json"));
  const long contacts = summary["processes"]["dem"]["contacts"]["locked"].get<long>() +
                        summary["processes"]["dem"]["contacts"]["open"].get<long>() +
                        summary["processes"]["dem"]["contacts"]["sliding"].get<long>();
  EXPECT_GT(contacts, 4096) << "the loops did not run in parallel";
  expect_same_run(dir / "one", dir / "two");
}

}  // namespace
}  // namespace fissure::testing
