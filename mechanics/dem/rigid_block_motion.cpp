#include "mechanics/dem/rigid_block_motion.h"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

namespace fissure::dem {

RigidBody rigid_body(const SectionProperties& section, double density) {
  return {density * section.area, density * (section.Ixx + section.Iyy)};
}

namespace {

/// The unbalanced force of each degree of freedom, the weight included.
Motion unbalanced(const RigidBody& body, const BlockLoad& load, const Vec2& gravity) {
  return {load.force.x() + body.mass * gravity.x(), load.force.y() + body.mass * gravity.y(),
          load.moment};
}

Motion acceleration(const RigidBody& body, const Motion& force) {
  return {force.x() / body.mass, force.y() / body.mass, force.z() / body.inertia};
}

}  // namespace

Motion velocity_before_first_step(const Motion& velocity, const RigidBody& body,
                                  const BlockLoad& load, const Vec2& gravity, double dt) {
  return velocity - 0.5 * dt * acceleration(body, unbalanced(body, load, gravity));
}

Motion advance(Motion& velocity, const RigidBody& body, const BlockLoad& load, const Vec2& gravity,
               double dt, const DampingControls& damping) {
  Motion force = unbalanced(body, load, gravity);
  if (damping.local > 0)
    for (int i = 0; i < 3; ++i)
      if (velocity(i) != 0)
        force(i) -= damping.local * std::abs(force(i)) * std::copysign(1.0, velocity(i));
  const double h = 0.5 * damping.mass * dt;
  velocity = (velocity * (1 - h) + dt * acceleration(body, force)) / (1 + h);
  return velocity * dt;
}

void move_rigidly(Polygon& polygon, Vec2& centroid, const Motion& increment) {
  const Eigen::Rotation2Dd turn(increment.z());
  const Vec2 shift(increment.x(), increment.y());
  for (Vec2& x : polygon.vertices) x = centroid + shift + turn * (x - centroid);
  centroid += shift;
}

double critical_time_step(double mass, double stiffness) {
  if (!(stiffness > 0)) return std::numeric_limits<double>::infinity();
  return 2 * std::sqrt(mass / stiffness);
}

}  // namespace fissure::dem
