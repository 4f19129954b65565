// The pictures of `fissure run` (docs/output.md, "Pictures"): every run
// leaves monitors.png and final_state.png beside its results when python3
// has h5py and matplotlib, and the pictures are best effort: output with
// nothing to draw (no results.h5, a results file without frames) leaves a
// note, never a failed run.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/io/hdf5_file.h"
#include "coupling/plot_script.h"
#include "tests/support/run_scene.h"

namespace fissure::testing {
namespace {

namespace fs = std::filesystem;

/// True when the system's python3 can draw (the scripts' modules).
bool python_can_plot() {
  return std::system("/usr/bin/python3 -c 'import h5py, matplotlib, numpy' > /dev/null 2>&1") == 0;
}

/// `fissure run SCENE -q -o OUT [extra]` with its stdout and stderr in OUT.log;
/// returns the exit code.
int run_fissure(const fs::path& scene, const fs::path& out, const std::string& extra = "") {
  const std::string command = std::string("\"") + FISSURE_APP + "\" run \"" + scene.string() +
                              "\" -q -o \"" + out.string() + "\" " + extra + " > \"" +
                              out.string() + ".log\" 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// A PNG file: its 8-byte signature.
bool is_png(const fs::path& file) {
  return fs::exists(file) && file_bytes(file.string()).rfind("\x89PNG\r\n\x1a\n", 0) == 0;
}

TEST(RunPictures, ACoupledRunLeavesMonitorsAndFinalStatePngs) {
  if (!python_can_plot()) GTEST_SKIP() << "/usr/bin/python3 lacks h5py or matplotlib";
  const fs::path dir = scratch_dir("run_pictures");
  const fs::path out = dir / "out";
  // A picture of an earlier run in the folder must not pass for this run's.
  fs::create_directories(out);
  std::ofstream(out / "final_state.png") << "an earlier run's picture";
  // Blocks and fractures with flow: both layers of the picture.
  const fs::path scene = fs::path(FISSURE_SOURCE_DIR) / "configs" / "flow_hm_injection.yaml";
  ASSERT_EQ(run_fissure(scene, out, "--max-steps 2"), 0) << file_bytes(out.string() + ".log");
  EXPECT_TRUE(is_png(out / "monitors.png"));
  EXPECT_TRUE(is_png(out / "final_state.png"));
  const std::string log = file_bytes(out.string() + ".log");
  EXPECT_NE(log.find("picture: " + (out / "final_state.png").string()), std::string::npos) << log;
}

TEST(RunPictures, NoPlotsDrawsNothing) {
  const fs::path dir = scratch_dir("run_pictures");
  const fs::path scene = fs::path(FISSURE_SOURCE_DIR) / "configs" / "flow_hm_injection.yaml";
  ASSERT_EQ(run_fissure(scene, dir / "out", "--max-steps 1 --no-plots"), 0);
  EXPECT_FALSE(fs::exists(dir / "out" / "monitors.png"));
  EXPECT_FALSE(fs::exists(dir / "out" / "final_state.png"));
  EXPECT_EQ(file_bytes((dir / "out").string() + ".log").find("  picture: "), std::string::npos);
}

TEST(RunPictures, ARunWithoutResultsFileSucceedsWithANote) {
  const fs::path dir = scratch_dir("run_pictures");
  const fs::path scene = dir / "no_hdf5.yaml";
  std::ofstream(scene) << R"(name: no_hdf5
physics: [mechanics]
materials:
  - {name: rock, density: 2700, young_modulus: 10 GPa, poisson_ratio: 0.25}
joints:
  - {name: joint, friction_angle: 30}
blocks:
  - {name: floor, vertices: [[-5, -1], [5, -1], [5, 0], [-5, 0]], fixed: true}
  - {name: block, vertices: [[0, 0], [1, 0], [1, 1], [0, 1]]}
monitors:
  - {name: block, point: [0.5, 0.5], block: block}
mechanics:
  dda: {time_step: 1 ms}
time: {end: 0.003}
output: {interval: 0.001, hdf5: false}
)";
  const fs::path out = dir / "out";
  ASSERT_EQ(run_fissure(scene, out), 0) << file_bytes(out.string() + ".log");
  EXPECT_FALSE(fs::exists(out / "results.h5"));
  EXPECT_FALSE(fs::exists(out / "final_state.png"));
  const std::string log = file_bytes(out.string() + ".log");
  EXPECT_NE(log.find("picture: final_state.png not made"), std::string::npos) << log;
  if (python_can_plot()) {
    EXPECT_TRUE(is_png(out / "monitors.png")) << log;
  }
}

TEST(RunPictures, AResultsFileWithoutFramesLeavesANote) {
  // What a run killed before its first frame leaves: the file and an empty /frames.
  const fs::path dir = scratch_dir("run_pictures");
  {
    Hdf5File file(dir / "results.h5");
    file.write_attribute(file.root(), "format", std::string("fissure-results"));
    file.create_group(file.root(), "frames");
  }
  ::testing::internal::CaptureStdout();
  draw_run_pictures(dir.string());
  std::fflush(stdout);
  const std::string printed = ::testing::internal::GetCapturedStdout();
  EXPECT_FALSE(fs::exists(fs::path(dir) / "final_state.png"));
  EXPECT_NE(printed.find("picture: final_state.png not made"), std::string::npos) << printed;
}

}  // namespace
}  // namespace fissure::testing
