#include "mechanics/dem/dem_energy.h"

namespace fissure::dem {

RigidStepEnergy rigid_step_energy(const RigidBody& body, const RigidBody& inertial,
                                  const Motion& before, const Motion& after, const BlockLoad& load,
                                  const BlockLoad& applied, const Vec2& gravity, double dt,
                                  bool damped) {
  const Motion mean = 0.5 * (before + after);
  const Motion m(body.mass, body.mass, body.inertia);
  const Motion moved(inertial.mass, inertial.mass, inertial.inertia);
  const Motion weight(body.mass * gravity.x(), body.mass * gravity.y(), 0);
  const Motion force = Motion(load.force.x(), load.force.y(), load.moment) + weight;
  RigidStepEnergy e;
  e.kinetic = 0.5 * mean.dot(m.cwiseProduct(mean));
  e.gravity = weight.dot(mean) * dt;
  e.applied = (applied.force.dot(mean.head<2>()) + applied.moment * mean.z()) * dt;
  // The work of the undamped force less the change of the kinetic energy
  // (as ZonedBlock::move_nodes): zero without damping, to round-off.
  if (damped) e.dissipated = (force * dt - moved.cwiseProduct(after - before)).dot(mean);
  return e;
}

double contact_work(double normal_before, double shear_before, double normal_after,
                    double shear_after, const DisplacementIncrement& du, double length) {
  return length * (0.5 * (normal_before + normal_after) * -du.normal +
                   0.5 * (shear_before + shear_after) * du.shear);
}

double contact_elastic_energy(const joints::JointLaw& law, double normal_stress,
                              double shear_stress, double length) {
  if (normal_stress == 0 && shear_stress == 0) return 0;
  const joints::JointStiffness k = law.stiffness(normal_stress, length);
  double e = 0;
  if (k.normal > 0) e += normal_stress * normal_stress / (2 * k.normal);
  if (k.shear > 0) e += shear_stress * shear_stress / (2 * k.shear);
  return length * e;
}

}  // namespace fissure::dem
