// What a monitor reports (docs/architecture.md 6): position, displacement and
// velocity of its material point and the stress of its block.
#pragma once

#include "core/state/rock_mass.h"

namespace fissure {

struct MonitorValues {
  Vec2 position = Vec2::Zero();
  Vec2 displacement = Vec2::Zero();
  Vec2 velocity = Vec2::Zero();
  Vector3 stress = Vector3::Zero();  ///< sxx, syy, sxy of the block (Pa)
};

MonitorValues evaluate_monitor(const RockMass& state, int point_index);

/// Velocity of the material at x in block b (DDA displacement function, theory.md 1.1).
Vec2 block_velocity_at(const Block& block, const Vec2& x);

/// The largest speed (m/s) of a vertex of any block: zero at rest (the
/// criterion of an initial equilibrium stage; a block's fastest point is a
/// vertex, the velocity field being linear).
double fastest_block_point(const RockMass& state);

}  // namespace fissure
