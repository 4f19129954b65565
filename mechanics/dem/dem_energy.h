// The energy ledger of the explicit DEM's cycle (docs/dem.md section 10):
// what each cycle puts into and takes out of the blocks, the contacts and
// the zones, in J per metre of thickness, at the time t^n of the cycle's
// positions.
//
// Two kinds of terms, each exact to the central-difference scheme's order:
//  * the blocks' (and nodes') side: the kinetic energy with the mean of the
//    two half-step velocities, v^n = (v^{n-1/2} + v^{n+1/2}) / 2, and the
//    works of the weight, of the applied loads and of the damping, each
//    cycle's share F^n . v^n dt summed by the trapezoidal rule (CycleSum),
//    as the zoned blocks' EnergyBalance does (zoned_block.h);
//  * the contacts' side: the work done on each contact's springs in the
//    cycle that moved its walls by du (from x^{n-1} to x^n),
//    L [(sigma_n^{n-1} + sigma_n^n) / 2 (-du_n) + (tau^{n-1} + tau^n) / 2 du_s],
//    trapezoidal in the stresses and so exact for a linear spring; the
//    stored (elastic) part is the law's spring energy at the stresses now
//    (contact_elastic_energy), and the rest of the work is what the slip
//    dissipated (slip_dissipated = work - change of the stored energy: the
//    plastic work of the return mapping, with the bonds' failure).
// Both sides approximate the same integrals of F . v to O(dt^2), so in a
// closed system kinetic + stored + dissipated - work stays at its start to
// O(dt^2) while the contacts' frames do not turn; a turning frame (a block
// rocking on a stressed contact) adds (dt/2) int sigma L (dD/dt) v dt, of
// the third order in the motion's amplitude (D maps the blocks' velocities
// to the contact's relative one).
#pragma once

#include <string>

#include "mechanics/dem/contact_kinematics.h"
#include "mechanics/dem/rigid_block_motion.h"
#include "rockmass/joints/joint_law.h"

namespace fissure::dem {

/// The ledger's terms (J/m) at the time of the last cycle.
struct DemEnergy {
  double kinetic = 0;             ///< blocks and nodes
  double contacts_elastic = 0;    ///< stored in the contacts' springs
  double zones_strain = 0;        ///< stored in the zoned blocks' zones
  double gravity_work = 0;        ///< of the weight, since the start
  double external_work = 0;       ///< of applied loads, supports, the heat's expansion
  double damping_dissipated = 0;  ///< local, mass- and stiffness-proportional
  double slip_dissipated = 0;     ///< by the contacts' slip and failure
  /// kinetic + stored + dissipated - work: at its start to O(dt^2).
  double balance() const {
    return kinetic + contacts_elastic + zones_strain + damping_dissipated + slip_dissipated -
           gravity_work - external_work;
  }
};

/// A work or a dissipation that each cycle n adds a share of, F^n . v^n dt,
/// read at t^n: the trapezoidal rule, the last share halved (O(dt^2)).
/// A work's first share is halved too (zero at t^0). The damping's is
/// whole: the first cycle damps from v^{-1/2} = v^0 - a^0 dt / 2, taken
/// without damping (central_difference.h), so all of its damping acts on
/// the motion after t^0 (halved, the balance would be off by O(dt) when the
/// blocks start moving).
class CycleSum {
 public:
  enum class FirstShare { Half, Whole };
  explicit CycleSum(FirstShare first = FirstShare::Half) : first_(first) {}

  void add(double share) {
    total_ += started_ || first_ == FirstShare::Whole ? share : 0.5 * share;
    last_ = share;
    started_ = true;
  }
  /// A share that belongs wholly before t^n (the motion a stop took away).
  void add_whole(double amount) { total_ += amount; }
  double at_cycle_time() const { return total_ - 0.5 * last_; }

  template <class Self, class Archive>
  static void checkpoint(Self& self, Archive& a, const std::string& name) {
    a(name + "_total", self.total_);
    a(name + "_last", self.last_);
    a(name + "_started", self.started_);
  }

 private:
  FirstShare first_;
  double total_ = 0, last_ = 0;
  bool started_ = false;
};

/// A rigid block's kinetic energy at the velocity (x, y, rotation).
inline double kinetic_energy(const RigidBody& body, const Motion& velocity) {
  return 0.5 * body.mass * velocity.head<2>().squaredNorm() +
         0.5 * body.inertia * velocity.z() * velocity.z();
}

/// A rigid block's shares of one cycle, from v^{n-1/2} to v^{n+1/2}.
struct RigidStepEnergy {
  double kinetic = 0;     ///< 1/2 m v^n . v^n (x, y and the rotation)
  double gravity = 0;     ///< m g . v^n dt
  double applied = 0;     ///< the applied loads' F . v^n dt (moment included)
  double dissipated = 0;  ///< by the damping: (F dt - m (v^{n+1/2} - v^{n-1/2})) . v^n
};

/// `load`: the undamped load without the weight (contacts and applied),
/// `applied` its applied part; `damped`: local or mass damping acts (else
/// nothing is dissipated, not even round-off). `inertial`: the inertia the
/// step moved (raised by density scaling, rigid_block_motion.h; the
/// damping's share is taken with it, the kinetic energy and the weight
/// with `body`).
RigidStepEnergy rigid_step_energy(const RigidBody& body, const RigidBody& inertial,
                                  const Motion& before, const Motion& after, const BlockLoad& load,
                                  const BlockLoad& applied, const Vec2& gravity, double dt,
                                  bool damped);

/// The work (J/m) done on a contact of length L whose walls moved by du
/// while its stresses went from `before` to `after` (sigma_n compression
/// +, tau): trapezoidal, exact for a linear spring.
double contact_work(double normal_before, double shear_before, double normal_after,
                    double shear_after, const DisplacementIncrement& du, double length);

/// The elastic energy (J/m) of a contact at its stresses: L (sigma_n^2 /
/// (2 k_n) + tau^2 / (2 k_s)), exact for a Coulomb joint (linear springs,
/// in tension too); for the stress-dependent laws (Barton-Bandis,
/// continuously yielding) the same at the tangent stiffnesses, an estimate
/// whose difference from the springs' true energy the slip term then takes.
double contact_elastic_energy(const joints::JointLaw& law, double normal_stress,
                              double shear_stress, double length);

}  // namespace fissure::dem
