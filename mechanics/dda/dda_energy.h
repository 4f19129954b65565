// Energy bookkeeping of a DDA run (J per unit thickness), for summary.json and
// the "no energy gain" checks: kinetic, gravitational potential, elastic
// strain, penalty springs (contacts, fixed points), minus the work done by
// point loads; friction dissipation is accumulated separately. With Newmark
// beta = 1/2, gamma = 1 (numerically dissipative) and Coulomb friction, the
// total can only fall.
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "core/state/rock_mass.h"
#include "mechanics/dda/block_system.h"
#include "mechanics/dda/dda_contact.h"
#include "mechanics/dda/dda_parameters.h"

namespace fissure::dda {

struct EnergyTerms {
  double kinetic = 0;
  double gravity = 0;  ///< potential -m g.x of the centroids
  double strain = 0;
  double contact = 0;  ///< normal and (locked) shear penalty springs
  double fixed_points = 0;
  double load_work = 0;             ///< accumulated work of point loads
  double friction_dissipation = 0;  ///< accumulated
  double total() const { return kinetic + gravity + strain + contact + fixed_points - load_work; }
  nlohmann::json to_json() const;
};

class EnergyLedger {
 public:
  /// Work of a load over a step: force (at the end of the step) times the
  /// displacement of its point.
  void add_load_work(double work) { load_work_ += work; }
  /// Friction dissipated by the step's sliding contacts: work of the
  /// friction force minus the change of the shear springs' energy.
  void add_friction(const std::vector<DdaContact>& contacts, double shear_penalty);

  EnergyTerms evaluate(const RockMass& state, const std::vector<DdaContact>& contacts,
                       const DdaParameters& p, const BlockLoads& loads) const;

  /// The accumulated terms (core/io/checkpoint.h).
  template <class Archive>
  void checkpoint(Archive& a) {
    a("load_work", load_work_);
    a("friction_dissipation", friction_dissipation_);
  }

 private:
  double load_work_ = 0;
  double friction_dissipation_ = 0;
};

}  // namespace fissure::dda
