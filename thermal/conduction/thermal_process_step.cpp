// One thermal step (ThermalProcess::advance, thermal_process.h): the four
// named steps, close_joints, factor_system, implicit_step and accept_step.
// The inner state s_ changes only in accept_step, once the step is accepted
// (a Retry leaves it).
#include <fmt/format.h>

#include <cmath>

#include "core/base/bdf2.h"
#include "core/base/errors.h"
#include "core/base/same_step.h"
#include "core/base/stopwatch.h"
#include "rockmass/fields/fracture_flow.h"
#include "rockmass/fracture_graph.h"
#include "thermal/conduction/thermal_process.h"

namespace fissure::thermal {

namespace {

double edge_length(const ThermalMesh& mesh, const BoundaryEdge& e) {
  return (mesh.nodes[e.b] - mesh.nodes[e.a]).norm();
}

}  // namespace

struct ThermalProcess::Step {
  std::vector<char> closed;                ///< the joint faces closed in this step
  bool regrouped = false;                  ///< the water's walls regrouped the unknowns
  std::vector<double> start;               ///< node temperatures at the step's start
  double previous_dt = 0;                  ///< of the BDF2 history; 0: backward Euler
  Bdf2Coefficients a;                      ///< backward Euler, or BDF2's
  double dt = 0;                           ///< the step taken (the factor's, see factor_system)
  Eigen::VectorXd t0, tm, t1;              ///< the unknowns at the start, the step before, the end
  std::vector<double> fluid_t0, fluid_tm;  ///< the water per fluid node, at t0 and tm
  std::vector<double> condition_value;     ///< per condition, at t + dt
  Eigen::VectorXd source, load, rhs;       ///< per unknown, W/m
  /// The ties' load lambda + h T_c (per unknown, W/m; empty: no ties), and
  /// what their Robin term took out at the step's end (W/m).
  Eigen::VectorXd tie_load;
  double tie_outflow = 0;
  double change = 0;  ///< the largest nodal change of a free unknown, K
};

StepReport ThermalProcess::advance(RockMass& state, double t, double dt) {
  Stopwatch clock;
  if (counters_.steps == 0 && ties_.empty())
    // The interfaces are published when the continuum initializes: meshes
    // that found none at their own start but one now came first.
    FISSURE_CHECK(ThermalTies::find(mesh_, state).empty(), CouplingOrderError,
                  tied_before_continuum("thermal process", "its blocks lie along"));
  Step step = close_joints(state);
  factor_system(state, dt, step);
  if (!ties_.empty()) {
    step.tie_load = Eigen::VectorXd::Zero(n_unknowns_);
    ties_.add_load(state, node_dof_, step.tie_load);
  }
  implicit_step(t, step);
  if (!step_control_.accepts(step.change)) {
    ++counters_.rejected_steps;
    counters_.step_seconds += clock.seconds();
    return {StepReport::Status::Retry, step_control_.retry_step(step.dt, step.change),
            fmt::format("thermal: the step of {:g} s changed a temperature by {:g} K, more "
                        "than thermal.max_temperature_change = {:g} K",
                        step.dt, step.change, step_control_.max_change)};
  }
  accept_step(state, step);
  ++counters_.steps;
  counters_.smallest_step =
      counters_.steps == 1 ? step.dt : std::min(counters_.smallest_step, step.dt);
  counters_.largest_step = std::max(counters_.largest_step, step.dt);
  counters_.largest_change = std::max(counters_.largest_change, step.change);
  counters_.step_seconds += clock.seconds();
  return {};
}

ThermalProcess::Step ThermalProcess::close_joints(RockMass& state) {
  Step step;
  step.closed = closed_faces(state);
  // The water's grid, once the flow's network exists; in the
  // wall-temperature limit it regroups the unknowns.
  step.regrouped = fluid_ && build_fluid(state) && c_.convection->wall_temperature;
  // (A coordinator's rollback may have taken back the water's first
  // temperatures, set when its grid was built.)
  if (fluid_ && fluid_->built()) start_fluid();
  if (step.closed != built_closed_ || (fluid_ && fluid_->built() && !system_has_fluid_) ||
      step.regrouped)
    build_system(step.closed);
  step.start = s_.temperature;
  step.previous_dt = s_.previous_dt;
  if (step.closed != s_.closed || step.regrouped) {
    // Faces opened or closed: perfect contact regroups the unknowns (energy
    // kept), and BDF2 starts again from this state.
    equalize(step.start);
    step.previous_dt = 0;
  }
  return step;
}

void ThermalProcess::factor_system(const RockMass& state, double dt, Step& step) {
  // Backward Euler, or BDF2 with the step ratio w = dt / dt_previous:
  // a0 T1 - a1 T0 + a2 T-1 = dt (F - K T1).
  if (c_.scheme == ThermalControls::Scheme::Bdf2 && step.previous_dt > 0)
    step.a = bdf2_coefficients(dt / step.previous_dt);
  const double a0 = step.a.a0;
  // The factor is kept when a0 / dt changes by round-off only (a sub-cycled
  // interval summed from shorter steps): the step is then taken with the
  // factor's dt (core/base/same_step.h).
  // With the water: its coefficients from the flow's fluxes and apertures,
  // which change the matrix when they change.
  const bool new_flow =
      fluid_ && fluid_->set_flow(state.fields.get(kFractureGraph), state.fields.get(kFractureFlow));
  // After a restart the solver has no factor: the checkpoint's coefficient
  // stands for the factor the uninterrupted run kept, which is computed
  // again (with the same coefficient, so the same dt) and not counted.
  const double held = matrix_coefficient_ >= 0 ? matrix_coefficient_ : restored_coefficient_;
  const bool same = same_step(held, a0 / dt);
  if (new_flow || !same || matrix_coefficient_ < 0) {
    const double coefficient = same ? held : a0 / dt;
    solver_.set_matrix(step_matrix(coefficient), fixed_dof_, !fluid_, new_flow || !same);
    matrix_coefficient_ = coefficient;
  }
  restored_coefficient_ = -1;
  step.dt = a0 / matrix_coefficient_;
}

void ThermalProcess::implicit_step(double t, Step& step) {
  const double dt = step.dt;
  const double a1 = step.a.a1, a2 = step.a.a2;
  step.t0 = to_dofs(step.start);
  step.tm = a2 != 0 ? to_dofs(s_.previous_temperature) : step.t0;
  Eigen::VectorXd &t0 = step.t0, &tm = step.tm;
  // The water's own unknowns follow the blocks'; at each fluid node its
  // temperature at the step's start (its wall's, where they are one).
  if (fluid_) {
    t0.conservativeResize(n_unknowns_);
    tm.conservativeResize(n_unknowns_);
    for (int i = 0; i < fluid_->n_nodes(); ++i)
      if (const int d = fluid_->dof()[i]; d >= n_dofs_) {
        t0[d] = s_.fluid_temperature[i];
        tm[d] = a2 != 0 ? s_.previous_fluid_temperature[i] : s_.fluid_temperature[i];
      }
    step.fluid_t0 = fluid_->node_values(t0, s_.fluid_temperature);
    step.fluid_tm = fluid_->node_values(tm, s_.previous_fluid_temperature);
  }

  // Sources and conditions at t + dt: the flux and convective loads, the
  // fixed temperatures.
  std::vector<double>& condition_value = step.condition_value;
  condition_value.resize(c_.conditions.size());
  for (std::size_t k = 0; k < c_.conditions.size(); ++k) {
    const ThermalCondition& c = c_.conditions[k];
    condition_value[k] = c.type == ThermalCondition::Type::Convection
                             ? c.value * c.external_temperature_at(t + dt)
                             : c.value_at(t + dt);
  }
  step.source = Eigen::VectorXd::Zero(n_unknowns_);
  step.load = Eigen::VectorXd::Zero(n_unknowns_);
  for (std::size_t k = 0; k < c_.sources.size(); ++k) {
    const double power = c_.sources[k].power * c_.sources[k].factor.at(t + dt);
    for (const auto& [node, w] : source_weights_[k]) step.source[node_dof_[node]] += power * w;
  }
  const std::vector<BoundaryEdge>& edges = mesh_.boundary_edges;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const int k = edge_condition_[e];
    if (k < 0) continue;
    if (c_.conditions[k].type == ThermalCondition::Type::Temperature) continue;
    const double half = edge_length(mesh_, edges[e]) / 2;  // int N ds
    const double q = condition_value[k];                   // W/m^2: the flux, or h T_ext
    step.load[node_dof_[edges[e].a]] += q * half;
    step.load[node_dof_[edges[e].b]] += q * half;
  }
  if (step.tie_load.size() == step.load.size()) step.load += step.tie_load;
  Eigen::VectorXd& rhs = step.rhs;
  if (!fluid_) {
    rhs = matrices_.capacity * (a1 * t0 - a2 * tm) / dt + step.source + step.load;
  } else {
    rhs = step.source + step.load;
    rhs.head(n_dofs_) += matrices_.capacity * (a1 * t0.head(n_dofs_) - a2 * tm.head(n_dofs_)) / dt;
    fluid_->add_rhs(a1 / dt, a2 / dt, step.fluid_t0, step.fluid_tm, rhs);
  }
  step.t1 = t0;
  for (int d = 0; d < n_unknowns_; ++d)
    if (fixed_dof_[d]) step.t1[d] = condition_value[fixed_condition_[d]];
  solver_.solve(rhs, step.t1);
  FISSURE_CHECK(step.t1.allFinite(), DivergenceError,
                "thermal: non-finite temperatures at t = " << t + dt << " s");

  // The change the step caused: the fixed temperatures' is prescribed,
  // whatever the step, and takes no part.
  step.change = 0;
  for (int d = 0; d < n_dofs_; ++d)
    if (!fixed_dof_[d]) step.change = std::max(step.change, std::abs(step.t1[d] - t0[d]));
}

void ThermalProcess::account_energy(const Step& step) {
  // Energy (J/m): summing every row of the step's equations, conduction and
  // joints cancel (K 1 = 0 without the convective part), so the stored
  // change is what the sources, the boundary loads, the convective
  // exchange and the fixed temperatures' reactions bring in.
  const Eigen::VectorXd &t0 = step.t0, &t1 = step.t1;
  const std::vector<BoundaryEdge>& edges = mesh_.boundary_edges;
  double boundary = step.load.sum() + solver_.fixed_reaction(step.rhs, t1) - step.tie_outflow;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const int k = edge_condition_[e];
    if (k >= 0 && c_.conditions[k].type == ThermalCondition::Type::Convection)
      boundary -= c_.conditions[k].value * edge_length(mesh_, edges[e]) / 2 *
                  (t1[node_dof_[edges[e].a]] + t1[node_dof_[edges[e].b]]);
  }
  // With BDF2 the rows balance the difference a0 T1 - a1 T0 + a2 T-1, not
  // T1 - T0: summed, a0 dE1 - a2 dE0 (a0 - a1 + a2 = 0), that is the stored
  // change dE1 and the correction (a0 - 1) dE1 - a2 dE0 (docs/thermal.md 5),
  // which the step before's change dE0 = sum C (T0 - T-1) gives.
  const Eigen::VectorXd& tm = step.tm;
  const double a0 = step.a.a0, a2 = step.a.a2;
  EnergyBalance& b = s_.balance;
  b.last_step_stored = 0;
  double stored_before = 0;
  for (int i = 0; i < mesh_.n_nodes(); ++i) {
    const double c = matrices_.node_capacity[i];
    const int d = node_dof_[i];
    b.last_step_stored += c * (t1[d] - t0[d]);
    if (a2 != 0) stored_before += c * (t0[d] - tm[d]);
  }
  b.last_step_bdf2_correction = (a0 - 1) * b.last_step_stored - a2 * stored_before;
  b.last_step_supplied = step.dt * step.source.sum();
  b.last_step_boundary = step.dt * boundary;
  b.stored += b.last_step_stored;
  b.bdf2_correction += b.last_step_bdf2_correction;
  b.supplied += b.last_step_supplied;
  b.boundary += b.last_step_boundary;
}

void ThermalProcess::accept_step(RockMass& state, Step& step) {
  if (!ties_.empty()) step.tie_outflow = ties_.robin_outflow(state, node_dof_, step.t1);
  account_energy(step);
  ThermalState& s = s_;
  s.closed = std::move(step.closed);
  s.previous_temperature = std::move(step.start);
  for (int i = 0; i < mesh_.n_nodes(); ++i) s.temperature[i] = step.t1[node_dof_[i]];
  if (fluid_) {
    // The water: its stored change, what the flow carried in and out, and
    // what it gave the walls (in the rock's rows above: the fixed
    // temperatures' reactions hold what it gave to fixed walls).
    std::vector<double> fluid_t1 = fluid_->node_values(step.t1, step.fluid_t0);
    const FluidStepEnergy e =
        fluid_->energy(step.dt, step.a, step.fluid_tm, step.fluid_t0, fluid_t1, s.temperature);
    EnergyBalance& b = s.balance;
    b.last_step_fluid = {e.stored, e.bdf2_correction, e.advected_in, e.advected_out, e.exchanged};
    b.fluid.stored += e.stored;
    b.fluid.bdf2_correction += e.bdf2_correction;
    b.fluid.advected_in += e.advected_in;
    b.fluid.advected_out += e.advected_out;
    b.fluid.exchanged += e.exchanged;
    s.previous_fluid_temperature = std::move(step.fluid_t0);
    s.fluid_temperature = std::move(fluid_t1);
  }
  s.previous_dt = step.dt;
  s.last_max_change = step.change;
  if (step_control_.enabled()) s.next_dt = step_control_.next_step(step.dt, step.change);
  publish(state);
  if (!ties_.empty()) ties_.give(state, node_dof_, step.t1);
}

}  // namespace fissure::thermal
