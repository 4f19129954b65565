// The reader of a `joints[]` entry's `model` and the model's keys
// (docs/scene-reference.md section 4), which core calls after the Coulomb
// keys (core/scene/joint_models.h; installed by coupling/process_registry.cpp).
#pragma once

#include "core/scene/joint_models.h"

namespace fissure::joints {

/// The keys it reads, as "joints[]" keys.
extern const KeyTable kJointModelKeys;
extern const JointModelReader kJointModelReader;

}  // namespace fissure::joints
