// The explicit DEM's update of one degree of freedom (Cundall and Hart 1992;
// docs/theory.md, "Explicit DEM"), shared by rigid blocks
// (rigid_block_motion.h: x, y and the rotation) and the nodes of zoned
// blocks (zoned_block.h): central differences with the velocity at half
// steps,
//   v^{n+1/2} = [v^{n-1/2} (1 - a dt/2) + F dt / m] / (1 + a dt/2),
// with a mass-proportional viscous damping a, or Cundall's local damping,
// which reduces the unbalanced force F by alpha |F| in the direction of
// the motion, F - alpha |F| sign(v^{n-1/2}) (UDEC's default alpha = 0.8
// for quasi-static runs): it removes kinetic energy where the mass moves
// without a viscosity that would also resist steady motion.
#pragma once

#include <cmath>

namespace fissure::dem {

struct DampingControls {
  double local = 0;  ///< Cundall's alpha, in [0, 1)
  double mass = 0;   ///< a, 1/s: mass-proportional viscous damping
};

/// The force F after Cundall's local damping, given the half-step velocity
/// v^{n-1/2} (no damping at rest).
inline double locally_damped(double force, double velocity, double alpha) {
  if (alpha > 0 && velocity != 0)
    return force - alpha * std::abs(force) * std::copysign(1.0, velocity);
  return force;
}

/// v^{n+1/2} from v^{n-1/2} and the unbalanced force F (weight included)
/// on a mass m (or a moment on an inertia).
inline double next_velocity(double velocity, double force, double mass, double dt,
                            const DampingControls& damping) {
  const double h = 0.5 * damping.mass * dt;
  return (velocity * (1 - h) + dt * (locally_damped(force, velocity, damping.local) / mass)) /
         (1 + h);
}

/// The critical step of central differences with Rayleigh's
/// stiffness-proportional damping beta (s), from the undamped one 2 /
/// omega_max: (2 / omega) (sqrt(1 + xi^2) - xi) at omega = omega_max and
/// xi = beta omega / 2, the damping ratio there (Belytschko and Hughes
/// 1983, central differences with viscous damping; UDEC's manual, "Dynamic analysis"). The
/// mass-proportional part (implicit in next_velocity) leaves it as is.
inline double damped_critical_time_step(double undamped, double beta) {
  if (!(beta > 0) || !std::isfinite(undamped)) return undamped;
  const double omega = 2 / undamped, xi = 0.5 * beta * omega;
  return 2 / omega * (std::sqrt(1 + xi * xi) - xi);
}

/// The half-step velocity before the first step, v^{-1/2} = v^0 - F^0 dt /
/// (2 m), from which the first step gives v^{1/2} = v^0 + F^0 dt / (2 m)
/// (undamped): taking v^0 for v^{-1/2} instead leaves an O(dt) offset in
/// every later position.
inline double velocity_before_first_step(double velocity, double force, double mass, double dt) {
  return velocity - 0.5 * dt * (force / mass);
}

}  // namespace fissure::dem
