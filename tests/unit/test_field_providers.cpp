// Processes meet through fields, not names (docs/architecture.md): a module
// asks provides() whether a field it reads will be written, and the answer
// comes from the registry's sections, for scenes built in code as for
// scenes read from a file.
#include <gtest/gtest.h>

#include "core/scene/scene_section.h"
#include "core/state/rock_mass.h"
#include "rockmass/fields/block_thermal_strain.h"
#include "rockmass/fields/contacts.h"
#include "rockmass/fields/fracture_flow.h"

namespace fissure {
namespace {

TEST(FieldProviders, TheProcessesSwitchedOnProvideTheirFields) {
  Scene scene;
  scene.physics = {"thermal"};
  EXPECT_TRUE(provides(scene, kBlockThermalStrain.name));
  EXPECT_FALSE(provides(scene, kContacts.name));
  EXPECT_FALSE(provides(scene, kFractureFlow.name));
  scene.physics = {"mechanics", "thermal"};
  EXPECT_TRUE(provides(scene, kContacts.name));
  EXPECT_TRUE(provides(scene, block_fields::kinematics));
  EXPECT_FALSE(provides(scene, kFractureFlow.name));
  scene.physics = {"mechanics", "flow", "thermal"};
  EXPECT_TRUE(provides(scene, kFractureFlow.name));
  EXPECT_FALSE(provides(scene, "no_such_field"));
}

}  // namespace
}  // namespace fissure
