// One backward-Euler step of the poro-thermo-elastic continuum (theory.md
// 5.2-5.4): heat first (its conduction does not depend on u and p), then u
// and p by the scene's scheme:
//   monolithic    [K  -Q; -Q^T  -(S + dt H)] [U; P] = ..., UMFPACK LU;
//   fixed_stress  flow with the mean stress frozen, (S + B_FS + dt H) P^{k+1}
//                 = ... + B_FS P^k, then mechanics K U^{k+1} = F + Q P^{k+1}
//                 (Mikelic and Wheeler 2013: a contraction for any step);
//   drained       mechanics with P^k, then flow (Kim et al. 2011: converges
//                 only for coupling strengths tau = alpha^2 M / K_dr < 1);
//   undrained     mechanics with the fluid mass frozen (K + alpha^2 M m m^T),
//                 then flow.
// Staggered schemes repeat their two solves until the relative change of U
// and P per pass is below the tolerance. The factors (or preconditioners)
// of every matrix are kept while the step size stays. On several ranks the
// matrices are each rank's share (poroelastic_matrices.h), and so are the
// right-hand sides built from them; the loads that are no element integral
// (boundary conditions, sources) are rank 0's share.
#pragma once

#include <algorithm>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>

#include "continuum/poroelasticity/continuum_constraints.h"
#include "continuum/poroelasticity/continuum_linear_solver.h"
#include "continuum/poroelasticity/poroelastic_matrices.h"

namespace fissure::continuum {

/// The full vectors of the fields.
struct PoroState {
  Eigen::VectorXd displacement;  ///< 2 per P2 node, m
  Eigen::VectorXd pressure;      ///< per vertex, Pa
  Eigen::VectorXd temperature;   ///< per vertex, degC
};

struct StepStatistics {
  long passes = 0;         ///< of the staggered scheme (1 for monolithic)
  double last_change = 0;  ///< relative change of the last pass (below the tolerance)
};

class PoroelasticSolver {
 public:
  PoroelasticSolver(const ContinuumMesh& mesh, const ContinuumControls& c,
                    const PoroelasticMatrices& m, const ContinuumConstraints& constraints);

  /// The initial fields (no displacement; the initial pressure and
  /// temperature, the prescribed values where conditions hold them at 0).
  PoroState initial_state() const;
  /// The undrained response at t+ to the loads at t (no time for flow):
  /// the Terzaghi and Mandel start. Nor for conduction: the temperatures
  /// are the initial ones with the prescribed values of t.
  void undrained_response(PoroState& s, double t);
  /// Advances `s` from t to t + dt. Throws DivergenceError when the
  /// staggered scheme diverges or does not converge. With BDF2,
  /// `previous` is the state at t - previous_dt (previous_dt = 0: none yet,
  /// a backward Euler step).
  StepStatistics step(PoroState& s, const PoroState& previous, double previous_dt, double t,
                      double dt);

  /// The interface tractions' nodal loads (full displacement vector, every
  /// rank's whole; empty: none), added to the mechanical load of the steps
  /// as rank 0's share.
  void set_interface_load(Eigen::VectorXd load) { interface_load_ = std::move(load); }
  /// The interfaces' inflows at points as nodal loads (per vertex: m^3/s
  /// per m, W/m; empty: none), added to the point sources as rank 0's share.
  void set_interface_inflows(Eigen::VectorXd fluid, Eigen::VectorXd heat) {
    interface_fluid_ = std::move(fluid);
    interface_heat_ = std::move(heat);
  }
  /// Whether steps compute the reactions below (interfaces only: they cost
  /// a product with each matrix).
  void compute_reactions(bool on) { compute_reactions_ = on; }
  /// After a step: the consistent nodal inflows of the flow (m^3/s per m,
  /// or m^3/s axisymmetric) and heat (W/m, or W) equations, A x - b over
  /// the step divided by dt, summed over the ranks. At a node whose value
  /// is prescribed this is the inflow the condition supplies; at a free
  /// node it is round-off. Empty before a step or without heat.
  const Eigen::VectorXd& fluid_reaction() const { return fluid_reaction_; }
  const Eigen::VectorXd& heat_reaction() const { return heat_reaction_; }

  /// The flow terms H and G of the matrices were assembled again (a
  /// stress-dependent permeability): the next step factorizes the flow (or
  /// monolithic) system again, whatever its step size.
  void flow_terms_changed() { flow_changed_ = true; }
  /// A permeability that follows the fields (stress_permeability.h): after
  /// each pass of a staggered scheme `update` sets the tensors of the pass's
  /// fields, assembles H and G again and returns the tensors' relative
  /// change; the flow system is factorized again, and the passes go on until
  /// that change is at most `tolerance` too (the tensors' iteration and the
  /// split's converge together). Empty: none.
  void set_flow_terms_update(std::function<double(const PoroState&)> update, double tolerance) {
    flow_terms_update_ = std::move(update);
    flow_terms_tolerance_ = tolerance;
  }

  long factorizations() const { return factorizations_; }
  /// The floors of the relative change (largest |u|, |p| so far), for checkpoints.
  template <class Self, class Archive>
  static void checkpoint_scales(Self& self, Archive& a) {
    a("displacement_scale", self.displacement_scale_);
    a("pressure_scale", self.pressure_scale_);
  }
  /// The counters of summary.json (core/io/checkpoint.h), so that a
  /// restarted run counts as the uninterrupted one. Counts only grow, so the
  /// larger count is kept: the checkpoint's at a restart, this run's own in
  /// a rollback within the run (they count the rolled-back passes' work).
  /// A restart factorizes again for the step size of the checkpoint's
  /// factor: that recomputes the factor the checkpoint stands for and is not
  /// counted. A checkpoint written before the counters were kept leaves them.
  template <class Self, class Archive>
  static void checkpoint_counters(Self& self, Archive& a) {
    if constexpr (Archive::reading)
      if (!a.has("linear_solves")) return;
    long factorizations = self.factorizations_, solves = self.solves_,
         iterations = self.linear_iterations();
    double factored_dt = self.factored_dt_;
    a("factorizations", factorizations);
    a("linear_solves", solves);
    a("linear_iterations", iterations);
    a("factored_dt", factored_dt);
    if constexpr (Archive::reading) {
      self.factorizations_ = std::max(self.factorizations_, factorizations);
      self.solves_ = std::max(self.solves_, solves);
      self.iterations_before_ += std::max(0L, iterations - self.linear_iterations());
      self.restored_dt_ = factored_dt;
    }
  }
  long linear_solves() const { return solves_; }
  /// Krylov iterations of every system so far (0 with direct solvers).
  long linear_iterations() const;
  /// How the systems are solved, e.g. "direct" or "petsc KSP cg + PC hypre on 2 ranks".
  std::string linear_solver() const;
  /// Per system with a factor (mechanics, flow, heat, monolithic): the
  /// entries and flops of its last factorization (an LU factor: also its
  /// measured backward error and whether it refines).
  nlohmann::json factor_sizes() const;

 private:
  /// Factorizes the systems of a step of `dt` unless the factors serve it;
  /// returns the step size they were made for (same_step: dt up to round-off).
  double factorize_for(double dt);
  /// The flow system of a staggered scheme: S + dt H (+ B_FS for fixed stress).
  void factorize_flow(double dt);
  /// The nodal loads at t of the point sources of `kind`: heat (W, or W/m)
  /// or fluid (m^3/s, or m^3/s per m).
  Eigen::VectorXd point_sources(ContinuumSource::Kind kind, double t) const;
  void solve_temperature(PoroState& s, const PoroState& old, double t1, double dt);
  /// The right-hand side of mechanics without the pressure term: loads,
  /// initial stress, and thermal stress of T (full).
  Eigen::VectorXd mechanical_load(const PoroState& s, double t1) const;
  /// The flow equation's right-hand side without the U and P terms:
  /// W (T - T_n) + dt (inflow + gravity flux) (full, times dt).
  Eigen::VectorXd flow_load(const PoroState& s, const PoroState& old, double t1, double dt) const;
  void monolithic(PoroState& s, const PoroState& old, double t1, double dt);
  StepStatistics staggered(PoroState& s, const PoroState& old, double t1, double dt);

  const ContinuumMesh& mesh_;
  const ContinuumControls& c_;
  const PoroelasticMatrices& m_;
  const ContinuumConstraints& k_;
  Eigen::VectorXd p0_, t0_;           ///< the initial fields
  ContinuumControls::Scheme scheme_;  ///< c_.scheme; monolithic for the undrained response
  /// The mechanical load that no step changes: body force, initial stress
  /// and the initial pressure's share (full).
  Eigen::VectorXd steady_load_;
  /// The pressure's numbering: the constraints', or none held (the undrained response).
  const FieldNumbering* undrained_pressure_ = nullptr;
  const FieldNumbering& pressure_numbering() const {
    return undrained_pressure_ ? *undrained_pressure_ : k_.pressure;
  }
  std::vector<ContinuumMesh::Place> source_places_;  ///< per source
  /// 1 on rank 0, 0 on the others: the share of the loads that every rank
  /// computes whole (boundary conditions, sources).
  double root_share_ = 1;
  double factored_dt_ = -1;
  bool flow_changed_ = false;  ///< flow_terms_changed() since the last factorization
  std::function<double(const PoroState&)> flow_terms_update_;
  double flow_terms_tolerance_ = 0;
  /// Of each system's matrix A (full numbering), the columns of its
  /// prescribed entries: all that the lifting b - A x_D reads (x_D is 0 at
  /// the free ones, whose part of A is in the factor). At 256 x 256 Mandel
  /// cells the monolithic one is 1 % of A.
  SparseMatrix flow_lifting_, mechanics_lifting_, heat_lifting_, monolithic_lifting_;
  std::unique_ptr<ContinuumLinearSolver> flow_solver_, mechanics_solver_, heat_solver_,
      monolithic_solver_;
  /// With a stress-dependent permeability: the monolithic matrix's
  /// stiffness and coupling blocks, reduced, and their prescribed columns
  /// (no flow block), which its refactorizations keep.
  struct {
    SparseMatrix reduced, lifting;
  } mechanical_blocks_;
  std::vector<int> monolithic_pressure_free_;  ///< the pressure numbering monolithic_solver_ has
  Eigen::VectorXd interface_load_;             ///< full, whole; empty: none
  Eigen::VectorXd interface_fluid_, interface_heat_;  ///< per vertex, whole; empty: none
  bool compute_reactions_ = false;
  Eigen::VectorXd fluid_reaction_, heat_reaction_;
  long factorizations_ = 0, solves_ = 0;
  long iterations_before_ = 0;  ///< of solvers before a restore (linear_iterations)
  double restored_dt_ = -1;     ///< the restored checkpoint's factored_dt_
  /// The largest |u| and |p| of the states stepped from: the floor of the
  /// staggered schemes' relative change (checkpointed: scales()).
  double displacement_scale_ = 0, pressure_scale_ = 0;
};

/// The initial pressure and temperature fields at the vertices.
Eigen::VectorXd initial_pressure(const ContinuumMesh& mesh, const ContinuumControls& c);
Eigen::VectorXd initial_temperature(const ContinuumMesh& mesh, const ContinuumControls& c);

}  // namespace fissure::continuum
