// The hydraulic head written next to the fracture pressures (docs/output.md,
// docs/flow.md section 2): h = (p - rho_f g.x) / (rho_f |g|), the flow
// potential p* in metres of fluid. z up with g = (0, -|g|) this is the
// familiar h = p / (rho_f |g|) + y.
#pragma once

#include "core/geometry/vec2.h"

namespace fissure {

struct HeadDefinition {
  double fluid_density = 0;     ///< rho_f (kg/m^3)
  Vec2 gravity = Vec2::Zero();  ///< the flow's gravity (m/s^2); zero: heads are off

  bool active() const { return fluid_density > 0 && gravity.squaredNorm() > 0; }
  /// Head (m) of pressure p (Pa) at x (m); only when active().
  double head(double p, const Vec2& x) const {
    return (p - fluid_density * gravity.dot(x)) / (fluid_density * gravity.norm());
  }
};

}  // namespace fissure
