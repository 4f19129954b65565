// The explicit DEM's loops run on OpenMP threads (docs/dem.md section 2):
// each contact's loads go to its own slots and are summed per block in the
// contacts' order, so a run writes the same bytes whatever the number of
// threads. The scene is a 30 x 30 staggered wall (915 blocks, about 5,700
// contacts, above the 4,096 from which the loops run in parallel), run for
// 2 updates of 100 cycles with OMP_NUM_THREADS = 1 and 2; and the same wall
// of deformable (zoned) bricks, whose zones' loop runs in parallel from 4,096
// zones in all.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "mechanics/dem/zone_mesh.h"
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

/// The 30 x 30 staggered wall (915 blocks) as a DEM scene in `scene`: joints
/// with stiffnesses, `dem` as its dem section; false if it was not written.
bool write_dem_wall(const fs::path& scene, const std::string& dem) {
  std::string text = generated_brick_wall(scene.string(), 30, 30);
  if (text.empty()) return false;
  // The DDA's wall as a DEM scene: joints with stiffnesses, a dem section.
  text.replace(text.find("physics: [mechanics]"), 20, "physics: [dem]");
  const std::string joint = "tensile_strength: 0}";
  text.replace(text.find(joint), joint.size(),
               "tensile_strength: 0, normal_stiffness: 10 GPa/m, shear_stiffness: 5 GPa/m}");
  text = text.substr(0, text.find("mechanics:\n")) + "dem: " + dem +
         "\ntime: {end: 1}\noutput: {every_steps: 2}\n";
  std::ofstream(scene) << text;
  return true;
}

/// The DEM's contacts in a run's summary.json.
long contacts_of(const fs::path& out) {
  const nlohmann::json summary = nlohmann::json::parse(file_bytes(out / "summary.json"));
  const nlohmann::json& c = summary["processes"]["dem"]["contacts"];
  return c["locked"].get<long>() + c["open"].get<long>() + c["sliding"].get<long>();
}

TEST(DemThreads, TheSameBitsOnOneAndTwoThreads) {
  const fs::path dir = scratch_dir("dem_threads");
  const fs::path scene = dir / "wall.yaml";
  ASSERT_TRUE(write_dem_wall(scene, "{rounding: 5 mm}"));

  ASSERT_EQ(run_on_threads(scene, dir / "one", 1), 0)
      << file_bytes((dir / "one").string() + ".log");
  ASSERT_EQ(run_on_threads(scene, dir / "two", 2), 0)
      << file_bytes((dir / "two").string() + ".log");
  EXPECT_GT(contacts_of(dir / "two"), 4096) << "the loops did not run in parallel";
  expect_same_run(dir / "one", dir / "two");
}

// Deformable bricks (dem.zone_size, docs/dem.md section 9): each zoned
// block's zones and nodes are one job of the zones' loop (its stresses,
// nodal forces and motion only its own), and the contacts' loads reach the
// nodes in the contacts' order, so the bits do not depend on the threads
// either. 0.25 m zones: 885 bricks of 1.0 x 0.5 m and 30 half bricks.
TEST(DemThreads, TheSameBitsOnOneAndTwoThreadsWithZonedBlocks) {
  const fs::path dir = scratch_dir("dem_threads_zoned");
  const fs::path scene = dir / "wall.yaml";
  ASSERT_TRUE(write_dem_wall(scene, "{rounding: 5 mm, zone_size: 0.25 m}"));
  const auto zones_of = [](double width) {
    return static_cast<long>(
        dem::mesh_block(Polygon({{0, 0}, {width, 0}, {width, 0.5}, {0, 0.5}}), 0.25).zones.size());
  };
  const long zones = 885 * zones_of(1.0) + 30 * zones_of(0.5);
  EXPECT_GE(zones, 4096) << "the zones' loop did not run in parallel";

  ASSERT_EQ(run_on_threads(scene, dir / "one", 1), 0)
      << file_bytes((dir / "one").string() + ".log");
  ASSERT_EQ(run_on_threads(scene, dir / "two", 2), 0)
      << file_bytes((dir / "two").string() + ".log");
  EXPECT_GT(contacts_of(dir / "two"), 4096) << "the contacts' loop did not run in parallel";
  expect_same_run(dir / "one", dir / "two");
}

}  // namespace
}  // namespace fissure::testing
