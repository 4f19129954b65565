// A rock mass cut from a DFN runs as a DDA scene (issue 22, item 1):
// configs/dfn_network.yaml diverged at its first step ("open-close iteration
// did not converge", dt cut below time.min_step) because contacts of touching
// blocks started with spurious penetrations of centimetres
// (test_contact_detection.cpp). Its first steps now run, and the blocks
// penetrate each other only as much as the penalty springs allow.
#include <gtest/gtest.h>

#include "coupling/process_registry.h"
#include "tests/support/run_scene.h"

namespace fissure {
namespace {

TEST(GeneratedRockMass, TheDfnNetworkSceneTakesItsFirstSteps) {
  Scene scene = read_scene(std::string(FISSURE_SOURCE_DIR "/configs/dfn_network.yaml"));
  scene.time.max_steps = 20;
  scene.output.hdf5 = false;
  const testing::RunResult r = testing::run_scene(scene, "generated_rock_mass");
  ASSERT_EQ(r.summary.status, "max_steps") << r.summary.message;
  EXPECT_EQ(r.summary.steps, 20);
  // Under its own weight over microseconds: far below a millimetre.
  EXPECT_LT(r.summary.processes["mechanics"]["max_penetration"].get<double>(), 1e-4);
}

}  // namespace
}  // namespace fissure
