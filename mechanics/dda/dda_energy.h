// Energy bookkeeping of a DDA run (J per unit thickness), for summary.json and
// the "no energy gain" checks: kinetic, gravitational potential, elastic
// strain, penalty springs (contacts, fixed points), minus the work done by
// point loads and by thermal expansion; friction dissipation is accumulated
// separately. With Newmark beta = 1/2, gamma = 1 (numerically dissipative)
// and Coulomb friction, the total can only fall.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
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
  double load_work = 0;  ///< accumulated work of point loads
  /// Accumulated work of the thermal strain (thermal_strain.h): what the
  /// thermal strain put into the blocks' elastic energy at the strain they
  /// had (docs/dda.md "Thermal strain"). Reported only when the run has a
  /// thermal strain field.
  std::optional<double> thermal_work;
  double friction_dissipation = 0;  ///< accumulated
  /// Accumulated energy the viscous boundaries took out (viscous_boundary.h),
  /// reported when the scene has one; with free-field input, net of what the
  /// incoming wave brought in.
  std::optional<double> boundary_dissipation;
  /// Accumulated work the driven blocks (a base following a ground motion)
  /// did on the others through their contacts; reported with a ground motion.
  std::optional<double> base_work;
  double total() const {
    return kinetic + gravity + strain + contact + fixed_points - load_work -
           thermal_work.value_or(0) - base_work.value_or(0);
  }
  nlohmann::json to_json() const;
};

class EnergyLedger {
 public:
  /// Work of a load over a step: force (at the end of the step) times the
  /// displacement of its point.
  void add_load_work(double work) { load_work_ += work; }
  /// Work of a step's thermal strain increment d_eps* on a block of area S
  /// (start of step), stress sigma and elasticity E: the elastic energy the
  /// increment adds at the block's start-of-step strain,
  ///   W = S (-sigma . d_eps* + 1/2 d_eps* . E d_eps*),
  /// the free strain changing at the start of the step, the blocks then
  /// answering it. Called only when the step has a thermal strain field.
  void add_thermal_work(double area, const Eigen::Vector3d& stress, const Eigen::Matrix3d& elastic,
                        const Eigen::Vector3d& thermal_strain) {
    thermal_work_ =
        thermal_work_.value_or(0) +
        area * (-stress.dot(thermal_strain) + 0.5 * thermal_strain.dot(elastic * thermal_strain));
  }
  /// Friction dissipated by the step's sliding contacts: work of the
  /// friction force minus the change of the shear springs' energy.
  void add_friction(const std::vector<DdaContact>& contacts, double shear_penalty);
  /// Work the driven blocks did through the step's contacts: the force
  /// each contact's spring carries at the end of the step times the part of
  /// its gap and slip the driven side's prescribed increment made.
  void add_base_work(const std::vector<DdaContact>& contacts);
  /// Work the viscous boundaries did on the blocks in a step (<= 0 without input).
  void add_boundary_work(double work) {
    boundary_dissipation_ = boundary_dissipation_.value_or(0) - work;
  }

  EnergyTerms evaluate(const RockMass& state, const std::vector<DdaContact>& contacts,
                       const DdaParameters& p, const BlockLoads& loads) const;

  /// The accumulated terms (core/io/checkpoint.h).
  template <class Self, class Archive>
  static void checkpoint(Self& self, Archive& a) {
    a("load_work", self.load_work_);
    a("friction_dissipation", self.friction_dissipation_);
    // Terms of some scenes only (heat, ground motion, viscous boundaries):
    // a scene without them stores none (its checkpoints stay as they were).
    optional_term(a, "thermal_work", self.thermal_work_);
    optional_term(a, "base_work", self.base_work_);
    optional_term(a, "boundary_dissipation", self.boundary_dissipation_);
  }

 private:
  /// A term written when it has a value, read when the checkpoint has it.
  template <class Archive, class Term>
  static void optional_term(Archive& a, const char* name, Term& term) {
    bool present = term.has_value();
    if constexpr (Archive::reading) present = a.has(name);
    if (!present) return;
    double w = term.value_or(0);
    a(name, w);
    if constexpr (Archive::reading) term = w;
  }

  double load_work_ = 0;
  double friction_dissipation_ = 0;
  std::optional<double> thermal_work_;
  std::optional<double> boundary_dissipation_;
  std::optional<double> base_work_;
};

}  // namespace fissure::dda
