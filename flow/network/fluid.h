// Fluid properties of the fracture flow (theory.md 3.1, 3.4).
#pragma once

#include "core/geometry/vec2.h"

namespace fissure::flow {

struct FluidProperties {
  double density = 1000;        ///< rho_f, kg/m^3
  double viscosity = 1e-3;      ///< mu, Pa s
  double bulk_modulus = 2.2e9;  ///< K_f, Pa (storage of the transient solver)
};

/// Throws SceneError naming the property when a value is not physical
/// (viscosity <= 0, density < 0, bulk modulus <= 0, or not finite).
void check_fluid(const FluidProperties& fluid);

/// The hydrostatic term of the flow potential p* = p - rho_f g.x (theory.md
/// 3.1, z up: p* = p + rho_f g z). `gravity` is the gravity vector (m/s^2);
/// zero switches heads off. Returns rho_f g.x at x.
inline double hydrostatic_offset(const FluidProperties& fluid, const Vec2& gravity, const Vec2& x) {
  return fluid.density * gravity.dot(x);
}

}  // namespace fissure::flow
