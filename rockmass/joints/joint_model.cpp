#include "rockmass/joints/joint_model.h"

namespace fissure::joints {

JointModel joint_model(const JointProperties& joint) {
  if (const JointModel* model = joint.model.find(kJointModel)) return *model;
  CoulombProperties c;
  c.friction_angle = joint.friction_angle;
  c.cohesion = joint.cohesion;
  c.tensile_strength = joint.tensile_strength;
  return c;
}

}  // namespace fissure::joints
