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

/// The mass of each degree of freedom.
Motion inertia(const RigidBody& body) {
  return {body.mass, body.mass, body.inertia};
}

}  // namespace

Motion velocity_before_first_step(const Motion& velocity, const RigidBody& body,
                                  const BlockLoad& load, const Vec2& gravity, double dt) {
  return velocity_before_first_step(velocity, body, body, load, gravity, dt);
}

Motion velocity_before_first_step(const Motion& velocity, const RigidBody& body,
                                  const RigidBody& inertial, const BlockLoad& load,
                                  const Vec2& gravity, double dt) {
  const Motion force = unbalanced(body, load, gravity), m = inertia(inertial);
  Motion before;
  for (int i = 0; i < 3; ++i)
    before(i) = velocity_before_first_step(velocity(i), force(i), m(i), dt);
  return before;
}

Motion advance(Motion& velocity, const RigidBody& body, const BlockLoad& load, const Vec2& gravity,
               double dt, const DampingControls& damping) {
  return advance(velocity, body, body, load, gravity, dt, damping);
}

Motion advance(Motion& velocity, const RigidBody& body, const RigidBody& inertial,
               const BlockLoad& load, const Vec2& gravity, double dt,
               const DampingControls& damping) {
  const Motion force = unbalanced(body, load, gravity), m = inertia(inertial);
  for (int i = 0; i < 3; ++i) velocity(i) = next_velocity(velocity(i), force(i), m(i), dt, damping);
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
