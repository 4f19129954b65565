// Linearised contact kinematics and their springs (theory.md 1.4).
// Normal:  d  = gap0 + e.Di + g.Dj   (d > 0 separation), spring p_n d^2/2.
// Shear:   ds = es.Di + gs.Dj        (slip of P1 along P2 -> P3 in this step,
//          from its start-of-step projection P0); a stuck contact carries
//          F = Fa + p_s ds, i.e. the spring (p_s / 2) (Fa / p_s + ds)^2, with
//          Fa its anchor force (the shear force at the start of the step).
// Sliding: Coulomb force N tan(phi) along the edge against the slip, with the
//          normal force N = -p_n d taken implicitly from the same solve.
//          Shi lags N by one open-close iteration; with stiff penalties that
//          lag alone keeps the iteration from converging (a 1 % friction
//          imbalance moves a sliding block by micrometres, which opens and
//          closes its neighbours' contacts with huge forces). The implicit
//          form adds unsymmetric terms to the system.
#pragma once

#include <Eigen/Core>

#include "core/linear/block_sparse_matrix.h"
#include "core/linear/low_rank_update.h"
#include "core/state/rock_mass.h"
#include "mechanics/dda/dda_contact.h"

namespace fissure::dda {

/// Start-of-step geometry: edge length, projection of P1, the gap and slip
/// linearisations, friction directions and the tributary length.
void prepare_contact(DdaContact& c, const RockMass& state);

/// Storage indices of the contact's blocks in the system matrix (-1 where a
/// block is fixed and has no unknowns).
struct ContactSlots {
  int dof_i = -1, dof_j = -1;  ///< block rows
  int ii = -1, jj = -1, ij = -1, ji = -1;
};

struct SpringConstants {
  double normal = 0;
  double shear = 0;
};

/// Adds the springs of a closed contact: normal, and shear while locked
/// (the symmetric positive definite part of the system).
void assemble_contact_springs(const DdaContact& c, const ContactSlots& s, const SpringConstants& k,
                              BlockSparseMatrix& matrix, Eigen::VectorXd& rhs);

/// Adds the implicit Coulomb friction of a sliding contact (unsymmetric
/// terms); `friction_coefficient` = tan(phi).
void assemble_sliding_friction(const DdaContact& c, const ContactSlots& s, double normal_penalty,
                               double friction_coefficient, BlockSparseMatrix& matrix,
                               Eigen::VectorXd& rhs);

/// The step's known increments of the contact's driven blocks (null: a
/// block with unknowns, or one that stands still): their part of the gap
/// and the slip (DdaContact::prescribed_gap, prescribed_slip).
void set_prescribed_motion(DdaContact& c, const Vector6* d_i, const Vector6* d_j);

/// Adds the rank-one terms by which contact `now` (rows `now_slots`, friction
/// coefficient `now_friction`) changes the system against the same contact
/// as it was, `before` (rows `before_slots`, `before_friction`; null: open
/// or absent): each spring, and the friction of a sliding contact, is a
/// rank-one term on the contact's two blocks (the assembly above). Terms
/// with the same right vector are merged (a normal spring and the friction
/// it drives); what cancels is left out.
void add_change_terms(const DdaContact& now, const ContactSlots& now_slots,
                      const DdaContact* before, const ContactSlots& before_slots,
                      const SpringConstants& k, double now_friction, double before_friction,
                      LowRankUpdate& terms);

}  // namespace fissure::dda
