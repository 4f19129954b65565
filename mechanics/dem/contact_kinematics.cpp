#include "mechanics/dem/contact_kinematics.h"

namespace fissure::dem {

namespace {

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

BlockLoad load_at(const Vec2& point, const Vec2& force, const Vec2& centroid) {
  return {force, cross(point - centroid, force)};
}

Vec2 force_on_i(const Vec2& normal, double normal_stress, double shear_stress, double length) {
  return (-normal_stress * normal + shear_stress * tangent_of(normal)) * length;
}

}  // namespace

Vec2 point_velocity(const Motion& v, const Vec2& centroid, const Vec2& p) {
  const Vec2 r = p - centroid;
  return Vec2(v.x() - v.z() * r.y(), v.y() + v.z() * r.x());
}

DisplacementIncrement relative_displacement(const Vec2& normal, const Vec2& velocity_i,
                                            const Vec2& velocity_j, double dt) {
  const Vec2 v = velocity_j - velocity_i;
  return {v.dot(normal) * dt, v.dot(tangent_of(normal)) * dt};
}

DisplacementIncrement relative_displacement(const Vec2& point, const Vec2& normal,
                                            const Motion& velocity_i, const Vec2& centroid_i,
                                            const Motion& velocity_j, const Vec2& centroid_j,
                                            double dt) {
  return relative_displacement(normal, point_velocity(velocity_i, centroid_i, point),
                               point_velocity(velocity_j, centroid_j, point), dt);
}

BlockLoad load_on_i(const Vec2& point, const Vec2& normal, double normal_stress,
                    double shear_stress, double length, const Vec2& centroid_i) {
  return load_at(point, force_on_i(normal, normal_stress, shear_stress, length), centroid_i);
}

BlockLoad load_on_j(const Vec2& point, const Vec2& normal, double normal_stress,
                    double shear_stress, double length, const Vec2& centroid_j) {
  return load_at(point, -force_on_i(normal, normal_stress, shear_stress, length), centroid_j);
}

}  // namespace fissure::dem
