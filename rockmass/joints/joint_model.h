// A scene joint's constitutive model (docs/joints.md, docs/scene-reference.md
// section 4): which law, with which properties. core keeps it opaque in
// JointProperties::model under kJointModel; read_joint_model.cpp fills it,
// the processes build their laws from joint_model().
#pragma once

#include <variant>

#include "core/base/enum_names.h"
#include "core/base/named_values.h"
#include "core/scene/scene.h"
#include "rockmass/joints/barton_bandis.h"
#include "rockmass/joints/continuously_yielding.h"
#include "rockmass/joints/coulomb_slip.h"

namespace fissure::joints {

enum class JointModelKind { Coulomb, BartonBandis, ContinuouslyYielding };

/// The names of `joints[].model`.
inline constexpr EnumName<JointModelKind> kJointModelNames[] = {
    {"coulomb", JointModelKind::Coulomb},
    {"barton_bandis", JointModelKind::BartonBandis},
    {"continuously_yielding", JointModelKind::ContinuouslyYielding}};

/// One law's properties, in the order of JointModelKind.
using JointModel =
    std::variant<CoulombProperties, BartonBandisProperties, ContinuouslyYieldingProperties>;

/// Where JointProperties::model keeps it.
inline constexpr Key<JointModel> kJointModel{"joint_model"};

/// The model of a scene joint: the one its `model` gave, or Coulomb from its
/// friction angle, cohesion and tensile strength, with k_n = k_s = 0 (no
/// stiffness of its own: the process's contact springs, the DDA's penalty)
/// and no dilation.
JointModel joint_model(const JointProperties& joint);

inline JointModelKind kind_of(const JointModel& model) {
  return static_cast<JointModelKind>(model.index());
}

}  // namespace fissure::joints
