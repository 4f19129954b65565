// A straight fracture trace before cutting: the common output of the joint-set
// and DFN generators and the input of the block cutter.
#pragma once

#include "core/geometry/vec2.h"

namespace fissure {

struct FractureTrace {
  Vec2 a = Vec2::Zero(), b = Vec2::Zero();
  int set = -1;         ///< joint set, then DFN family index (docs/rock-mass.md); -1: explicit
  int joint = -1;       ///< index into Scene::joints; -1 = the default joint
  double aperture = 0;  ///< m

  double length() const { return (b - a).norm(); }
};

}  // namespace fissure
