// The DDA equilibrium system of one time step (theory.md 1.3, 1.4):
//   [2/dt^2 M + K_e + K_fix + K_contact] D
//     = F_inertia + F_stress + F_thermal + F_body + F_loads + F_contact.
// Fixed blocks have no unknowns (their contacts only load the free side). The
// per-block diagonal and right-hand side are built once per step; the contact
// part is re-assembled in every open-close iteration. The symbolic analysis
// of the direct solver is reused while the contact pattern stays the same,
// and the solver is told how the contacts changed since the system it last
// factorized (factored_contacts.h), so that it can correct that factor.
#pragma once

#include <memory>
#include <vector>

#include "core/scene/scene.h"
#include "core/state/rock_mass.h"
#include "mechanics/dda/contact_springs.h"
#include "mechanics/dda/dda_contact.h"
#include "mechanics/dda/dda_parameters.h"
#include "mechanics/dda/factored_contacts.h"
#include "mechanics/dda/solver/block_solver.h"
#include "mechanics/dda/thermal_strain.h"
#include "mechanics/dda/viscous_boundary.h"
#include "rockmass/fields/interface_ties.h"

namespace fissure::dda {

/// External actions on blocks: the scene's fixed points and point loads,
/// and the springs that tie block vertices to a continuum interface
/// (rockmass/fields/interface_ties.h), set for each step.
struct BlockLoads {
  std::vector<FixedPoint> fixed_points;
  std::vector<PointLoad> point_loads;
  std::vector<TieSpring> ties;
  /// Dashpots of the viscous boundaries, and the step's reference velocity
  /// of those with free-field input (viscous_boundary.h).
  std::vector<ViscousEdge> dashpots;
  Vec2 free_field_velocity = Vec2::Zero();
  int first_fixed_point = 0;  ///< index of the first fixed point in RockMass::points
  int first_load_point = 0;
};

/// Load factor of a piecewise-linear history at time t (1 when empty).
double load_factor(const PointLoad& load, double t);

class BlockSystem {
 public:
  BlockSystem(const DdaParameters& parameters, const RockMass& state);

  /// Free-block numbering, pattern and per-block terms for a step ending at
  /// t_end, with the step's thermal strain increments (thermal_strain.h).
  void begin_step(const RockMass& state, const BlockLoads& loads,
                  const std::vector<DdaContact>& contacts, const ThermalStrain& thermal,
                  double t_end, double dt);

  /// Assembles the contact terms for the contacts' current states, with the
  /// spring constants `k` (the penalties, or the augmented Lagrangian's
  /// stiffened ones, docs/dda.md section 11), and solves.
  const Eigen::VectorXd& assemble_and_solve(const std::vector<DdaContact>& contacts,
                                            const SpringConstants& k);

  const std::vector<ContactSlots>& slots() const { return slots_; }
  int dof(int block) const { return dof_[block]; }
  int n_free() const { return n_free_; }
  /// Increment of block b in the last solution (zero for fixed blocks).
  Vector6 increment(int block) const;
  /// Increments of the free blocks: the last solution, or the step's first
  /// guess between begin_step and the first solve.
  const Eigen::VectorXd& solution() const { return solution_; }
  /// Takes an earlier solution of this step back (the augmented
  /// Lagrangian's last converged pass).
  void set_solution(const Eigen::VectorXd& x) { solution_ = x; }

  nlohmann::json statistics() const;

  /// What carries over from step to step (core/io/checkpoint.h): the
  /// solver's state, the contacts of its last factorized system and the
  /// analysed pattern.
  void save(CheckpointWriter& out) const;
  void restore(CheckpointReader& in);
  /// Time spent in the linear solver (analysis, factorization, solves).
  double solve_seconds() const { return solve_seconds_; }

 private:
  /// Tells the solver how this solve's system differs from the one it last
  /// factorized.
  void describe_change(const std::vector<DdaContact>& contacts, const SpringConstants& k);
  void add_fixed_point(const FixedPoint& f, const Vec2& current, const Block& b, Matrix6& k,
                       Vector6& rhs) const;
  /// A tie's spring and force at the step's end (interface_ties.h):
  /// p T^T T on the diagonal, T^T (lambda + p (target - current)) loaded.
  static void add_tie(const TieSpring& s, const Vec2& current, const Block& b, Matrix6& k,
                      Vector6& rhs);
  /// What save() writes (Self const) and restore() reads (core/io/checkpoint.h).
  template <class Self, class Archive>
  static void checkpoint(Self& self, Archive& a);

  const DdaParameters& p_;
  std::vector<Eigen::Matrix3d> elastic_;  ///< per material
  std::vector<int> dof_;
  int n_free_ = 0;
  Matrix6List base_matrix_;
  std::vector<Vector6, Eigen::aligned_allocator<Vector6>> base_rhs_;
  std::vector<ContactSlots> slots_;
  std::vector<std::pair<int, int>> pairs_, analysed_pairs_;
  Matrix6List analysed_diagonal_;  ///< the values the pattern was analysed with
  BlockSparseMatrix matrix_;
  Eigen::VectorXd rhs_, solution_;
  std::unique_ptr<BlockSolver> solver_;
  bool analysed_ = false;
  /// The contacts of the solver's last factorized system, and the terms by
  /// which the current system differs from it.
  FactoredContacts factored_;
  SpringConstants factored_springs_;  ///< the spring constants of that factor
  LowRankUpdate update_;
  double solve_seconds_ = 0;
};

}  // namespace fissure::dda
