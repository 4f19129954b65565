#include "mechanics/dda/dda_energy.h"

#include <Eigen/LU>
#include <cmath>

#include "mechanics/dda/block_kinematics.h"

namespace fissure::dda {

nlohmann::json EnergyTerms::to_json() const {
  nlohmann::json j = {{"kinetic", kinetic},
                      {"gravity_potential", gravity},
                      {"strain", strain},
                      {"contact_springs", contact},
                      {"fixed_point_springs", fixed_points},
                      {"load_work", load_work},
                      {"friction_dissipation", friction_dissipation},
                      {"total", total()}};
  if (thermal_work) j["thermal_work"] = *thermal_work;
  if (boundary_dissipation) j["boundary_dissipation"] = *boundary_dissipation;
  if (base_work) j["base_work"] = *base_work;
  return j;
}

void EnergyLedger::add_friction(const std::vector<DdaContact>& contacts, double shear_penalty) {
  for (const DdaContact& c : contacts)
    if (c.state == ContactState::Sliding)
      friction_dissipation_ +=
          c.shear_force * c.shear -
          (c.shear_force * c.shear_force - c.shear_force_start * c.shear_force_start) /
              (2 * shear_penalty);
}

void EnergyLedger::add_base_work(const std::vector<DdaContact>& contacts) {
  double work = 0;
  for (const DdaContact& c : contacts)
    if (c.state != ContactState::Open)  // compression > 0 closes the gap: d(gap) < 0 is work in
      work += -c.normal_force * c.prescribed_gap + c.shear_force * c.prescribed_slip;
  base_work_ = base_work_.value_or(0) + work;
}

EnergyTerms EnergyLedger::evaluate(const RockMass& state, const std::vector<DdaContact>& contacts,
                                   const DdaParameters& p, const BlockLoads& loads) const {
  EnergyTerms e;
  for (const Block& b : state.blocks) {
    if (b.fixed) continue;
    const Material& m = state.materials[b.material];
    e.kinetic += kinetic_energy(b, m.density, b.velocity);
    e.gravity -=
        current_density(b, m.density) * b.section.area * state.gravity.dot(b.section.centroid);
    const Eigen::Matrix3d compliance = elastic_matrix(m, p.plane).inverse();
    e.strain += 0.5 * b.section.area * b.stress.dot(compliance * b.stress);
  }
  for (const DdaContact& c : contacts) {
    if (c.state == ContactState::Open) continue;
    e.contact += 0.5 * p.normal_penalty * c.gap * c.gap +
                 0.5 * c.shear_force * c.shear_force / p.shear_penalty;
  }
  for (std::size_t f = 0; f < loads.fixed_points.size(); ++f) {
    const FixedPoint& fp = loads.fixed_points[f];
    const Vec2 off = state.points[loads.first_fixed_point + f].current - fp.point;
    e.fixed_points += 0.5 * p.fixed_point_penalty *
                      ((fp.fix_x ? off.x() * off.x() : 0) + (fp.fix_y ? off.y() * off.y() : 0));
  }
  e.load_work = load_work_;
  e.thermal_work = thermal_work_;
  e.friction_dissipation = friction_dissipation_;
  e.boundary_dissipation = boundary_dissipation_;
  e.base_work = base_work_;
  return e;
}

}  // namespace fissure::dda
