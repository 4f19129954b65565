// Fluid pressure loads on block edges, as the shared field "pressure_loads"
// (written by the flow, assembled by the mechanics; theory.md 3.5).
#pragma once

#include <vector>

#include "core/base/named_values.h"
#include "core/geometry/vec2.h"

namespace fissure {

/// Fluid pressure on a stretch a -> b of a block's edge (theory.md 3.5),
/// linear from p_a to p_b (Pa, compression positive), written by the flow
/// process and assembled by the mechanics as
///   F_i += -int p T_i^T n ds = -L/6 [(2 p_a + p_b) T_i(a)^T + (p_a + 2 p_b) T_i(b)^T] n
/// with n the block's outward unit normal there (start-of-step geometry).
///
/// A shear traction along the edge may come with it (s_a, s_b: Pa, linear,
/// positive along a -> b; the REV study's square under a shear stress,
/// coupling/upscaling/stressed_domain.cpp): F_i += int s T_i^T t ds, t the
/// unit vector a -> b. The fluid's loads have none.
struct EdgePressureLoad {
  int block = -1;
  Vec2 a = Vec2::Zero(), b = Vec2::Zero();
  double p_a = 0, p_b = 0;
  Vec2 normal = Vec2::Zero();
  double s_a = 0, s_b = 0;
  bool has_shear() const { return s_a != 0 || s_b != 0; }
  Vec2 tangent() const { return (b - a).normalized(); }
};

inline constexpr Key<std::vector<EdgePressureLoad>> kPressureLoads{"pressure_loads"};

}  // namespace fissure
