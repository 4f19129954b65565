#include "continuum/poroelasticity/poroelastic_solver.h"

#include <cmath>
#include <sstream>

#include "core/base/bdf2.h"
#include "core/base/errors.h"
#include "core/base/same_step.h"
#include "core/parallel/mpi_world.h"

namespace fissure::continuum {

namespace {

using Scheme = ContinuumControls::Scheme;

/// [[a, b], [c, d]] of sparse blocks.
SparseMatrix block_matrix(const SparseMatrix& a, const SparseMatrix& b, const SparseMatrix& c,
                          const SparseMatrix& d) {
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(a.nonZeros() + b.nonZeros() + c.nonZeros() + d.nonZeros());
  auto add = [&t](const SparseMatrix& m, int r0, int c0) {
    for (int k = 0; k < m.outerSize(); ++k)
      for (SparseMatrix::InnerIterator it(m, k); it; ++it)
        t.emplace_back(r0 + it.row(), c0 + it.col(), it.value());
  };
  add(a, 0, 0);
  add(b, 0, static_cast<int>(a.cols()));
  add(c, static_cast<int>(a.rows()), 0);
  add(d, static_cast<int>(a.rows()), static_cast<int>(a.cols()));
  SparseMatrix m(a.rows() + c.rows(), a.cols() + b.cols());
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

SparseMatrix reduce(const SparseMatrix& a, const SparseMatrix& p) {
  return SparseMatrix(p.transpose() * a * p);
}

/// `into` := the columns of `a` whose entries the numberings prescribe (in
/// their order: the columns of `first`, then of `second`), the others
/// empty. Its product with x_D is a's, to the bit (the other columns
/// multiplied zeros). Written in place: Eigen 3.4's SparseMatrix has no
/// move, and a returned matrix is copied.
void keep_prescribed_columns(const SparseMatrix& a, const FieldNumbering& first,
                             const FieldNumbering* second, SparseMatrix& into) {
  const auto n_first = static_cast<Eigen::Index>(first.condition.size());
  const auto held = [&](Eigen::Index column) {
    return column < n_first ? first.condition[column] >= 0
                            : second->condition[column - n_first] >= 0;
  };
  Eigen::Index entries = 0;
  for (Eigen::Index j = 0; j < a.outerSize(); ++j)
    if (held(j))
      for (SparseMatrix::InnerIterator it(a, j); it; ++it) ++entries;
  SparseMatrix().swap(into);
  into.resize(a.rows(), a.cols());
  into.reserve(entries);
  for (Eigen::Index j = 0; j < a.outerSize(); ++j) {
    into.startVec(j);
    if (held(j))
      for (SparseMatrix::InnerIterator it(a, j); it; ++it)
        into.insertBack(it.row(), j) = it.value();
  }
  into.finalize();
}

/// A saddle point's analysis carried to a system of other pressure unknowns
/// (the undrained start's, all free, to the steps', without the drained
/// ones): in its column order the first n_u (displacement) unknowns as they
/// were, each pressure unknown that stays free renumbered, the others left
/// out. `old_free` is the old pressure numbering's free_index. Empty unless
/// the order covers every unknown of `now` once.
ContinuumLinearSolver::Analysis carried_analysis(const ContinuumLinearSolver::Analysis& analysis,
                                                 int n_u, const std::vector<int>& old_free,
                                                 const FieldNumbering& now) {
  const std::vector<long>& order = analysis.column_order;
  const auto old_pressures =
      std::count_if(old_free.begin(), old_free.end(), [](int j) { return j >= 0; });
  if (order.empty() || old_free.size() != now.free_index.size() ||
      order.size() != static_cast<std::size_t>(n_u + old_pressures))
    return {};
  // Per old unknown its new one (-1: prescribed now).
  std::vector<long> renumbered(order.size(), -1);
  for (int r = 0; r < n_u; ++r) renumbered[r] = r;
  for (std::size_t e = 0; e < old_free.size(); ++e)
    if (old_free[e] >= 0 && now.free_index[e] >= 0)
      renumbered[n_u + old_free[e]] = n_u + now.free_index[e];
  std::vector<long> next;
  std::vector<char> placed(static_cast<std::size_t>(n_u + now.n_free), 0);
  for (const long r : order) {
    const long k = renumbered[r];
    if (k < 0 || placed[k]) continue;
    placed[k] = 1;
    next.push_back(k);
  }
  if (next.size() != placed.size()) return {};
  return {std::move(next), analysis.memory};
}

/// The change of a pass relative to the field's size, at least `floor` (the
/// largest size the field has had in the run: a field that drains to 0
/// would otherwise make round-off look like a change).
double relative_change(const Eigen::VectorXd& now, const Eigen::VectorXd& before, double floor) {
  const double scale = std::max(now.lpNorm<Eigen::Infinity>(), floor);
  const double change = (now - before).lpNorm<Eigen::Infinity>();
  return scale > 0 ? change / scale : change;
}

/// The free part of x, the first guess of a solver that takes one (an
/// empty vector for a direct solver: no work in its passes).
Eigen::VectorXd first_guess(const ContinuumLinearSolver& solver, const FieldNumbering& f,
                            const Eigen::VectorXd& x) {
  return solver.takes_a_guess() ? f.free_part(x) : Eigen::VectorXd();
}

/// A field of y at the vertices.
template <class OfY>
Eigen::VectorXd at_vertices(const ContinuumMesh& mesh, OfY of_y) {
  Eigen::VectorXd x(mesh.n_vertices);
  for (int v = 0; v < mesh.n_vertices; ++v) x(v) = of_y(mesh.nodes[v].y());
  return x;
}

}  // namespace

Eigen::VectorXd initial_pressure(const ContinuumMesh& mesh, const ContinuumControls& c) {
  return at_vertices(mesh, [&c](double y) { return c.initial_pressure_at(y); });
}

Eigen::VectorXd initial_temperature(const ContinuumMesh& mesh, const ContinuumControls& c) {
  return at_vertices(mesh, [&c](double y) { return c.initial_temperature_at(y); });
}

PoroelasticSolver::PoroelasticSolver(const ContinuumMesh& mesh, const ContinuumControls& c,
                                     const PoroelasticMatrices& m,
                                     const ContinuumConstraints& constraints)
    : mesh_(mesh),
      c_(c),
      m_(m),
      k_(constraints),
      p0_(initial_pressure(mesh, c)),
      t0_(initial_temperature(mesh, c)),
      scheme_(c.scheme),
      steady_load_(m.body_force - m.initial_stress - m.coupling * p0_),
      root_share_(parallel::rank() == 0 ? 1 : 0) {
  for (const ContinuumSource& source : c.sources)
    source_places_.push_back(mesh.locate(source.point));
}

Eigen::VectorXd PoroelasticSolver::point_sources(ContinuumSource::Kind kind, double t) const {
  // A point source is a nodal load: int N_a Q delta = Q N_a(x_s).
  Eigen::VectorXd f = Eigen::VectorXd::Zero(mesh_.n_vertices);
  for (std::size_t k = 0; k < source_places_.size(); ++k) {
    if (c_.sources[k].kind != kind) continue;
    const double q = c_.sources[k].rate * c_.sources[k].time_factor.at(t);
    const ContinuumMesh::Place& place = source_places_[k];
    for (int v = 0; v < 3; ++v) f(mesh_.triangles[place.triangle][v]) += q * place.weights(v);
  }
  // The interfaces' inflows at points (continuum_interface.h), already nodal.
  const Eigen::VectorXd& given =
      kind == ContinuumSource::Kind::Heat ? interface_heat_ : interface_fluid_;
  if (given.size() == f.size()) f += given;
  return f;
}

PoroState PoroelasticSolver::initial_state() const {
  PoroState s;
  s.displacement = Eigen::VectorXd::Zero(2 * mesh_.n_nodes());
  s.pressure = p0_;
  s.temperature = t0_;
  return s;
}

double PoroelasticSolver::factorize_for(double dt) {
  // A step that differs from the factor's by round-off (the step before an
  // output frame) is taken with the factor's dt (core/base/same_step.h); so
  // is, after a restart, the step of the checkpoint's factor.
  const double held = factored_dt_ >= 0 ? factored_dt_ : restored_dt_;
  if (held >= 0 && same_step(held, dt)) dt = held;
  const bool new_dt = dt != factored_dt_;
  if (!new_dt && !flow_changed_) return dt;
  // The first factorization after a restart, for the checkpoint's step size,
  // is the checkpoint's factor computed again (checkpoint_counters); not so
  // with new flow terms, which the uninterrupted run factorizes too.
  const bool restored = factored_dt_ < 0 && dt == restored_dt_ && !flow_changed_;
  flow_changed_ = false;
  factored_dt_ = dt;
  restored_dt_ = -1;
  if (!restored) ++factorizations_;
  const auto make = [this](SystemKind kind, const char* name, const FieldNumbering& first,
                           const FieldNumbering* second = nullptr) {
    return make_linear_solver(kind, name, mesh_, c_.axisymmetric, first, second, c_.solver);
  };
  if (c_.with_temperature() && new_dt) {
    SparseMatrix a = m_.heat_capacity + dt * (m_.conduction + root_share_ * k_.heat_transfer);
    if (!heat_solver_) heat_solver_ = make(SystemKind::Diffusion, "heat", k_.temperature);
    keep_prescribed_columns(a, k_.temperature, nullptr, heat_lifting_);
    heat_solver_->set_matrix(reduce(a, k_.temperature.prolongation));
  }
  if (scheme_ == Scheme::Monolithic) {
    const FieldNumbering& pressure = pressure_numbering();
    // The full matrix and its pieces go before the factorization (only the
    // lifting's columns stay).
    SparseMatrix reduced, schur;
    {
      const SparseMatrix flow = m_.storage + dt * m_.mobility;
      const auto nu = m_.stiffness.rows(), np = flow.rows();
      // [[K, -Q], [-Q^T, d]]: the flow block d = -flow, or none.
      const auto with_flow_block = [this](const SparseMatrix& d) {
        return block_matrix(m_.stiffness, -m_.coupling, -SparseMatrix(m_.coupling.transpose()), d);
      };
      const SparseMatrix p =
          block_matrix(k_.displacement.prolongation,
                       SparseMatrix(k_.displacement.prolongation.rows(), pressure.n_free),
                       SparseMatrix(pressure.prolongation.rows(), k_.displacement.n_free),
                       pressure.prolongation);
      if (c_.stress_dependent_permeability() && !undrained_pressure_) {
        // Every pass of a step factorizes again with new flow terms: the
        // stiffness and coupling blocks, reduced, are kept from the first
        // (their entries and the flow block's are disjoint, so the sum is
        // the whole matrix's reduction to the bit).
        if (mechanical_blocks_.reduced.size() == 0) {
          const SparseMatrix a = with_flow_block(SparseMatrix(np, np));
          reduce(a, p).swap(mechanical_blocks_.reduced);
          keep_prescribed_columns(a, k_.displacement, &pressure, mechanical_blocks_.lifting);
        }
        const SparseMatrix a =
            block_matrix(SparseMatrix(nu, nu), SparseMatrix(nu, np), SparseMatrix(np, nu), -flow);
        SparseMatrix(mechanical_blocks_.reduced + reduce(a, p)).swap(reduced);
        keep_prescribed_columns(a, k_.displacement, &pressure, monolithic_lifting_);
        monolithic_lifting_ += mechanical_blocks_.lifting;
      } else {
        const SparseMatrix a = with_flow_block(-flow);
        reduce(a, p).swap(reduced);
        keep_prescribed_columns(a, k_.displacement, &pressure, monolithic_lifting_);
      }
      // The Krylov solver's Schur preconditioner: the flow block with the
      // fixed-stress term, S + dt H + B_FS ~ S + dt H + Q^T K^-1 Q.
      reduce(flow + m_.fixed_stress, pressure.prolongation).swap(schur);
    }
    if (!monolithic_solver_ ||
        monolithic_solver_->size() != k_.displacement.n_free + pressure.n_free) {
      auto next = make(SystemKind::SaddlePoint, "monolithic", k_.displacement, &pressure);
      // The steps after the undrained start: its factor's analysis, carried
      // over, spares theirs the ordering (continuum_linear_solver.cpp).
      if (monolithic_solver_)
        next->take_analysis(carried_analysis(monolithic_solver_->analysis(), k_.displacement.n_free,
                                             monolithic_pressure_free_, pressure));
      monolithic_solver_ = std::move(next);
      monolithic_pressure_free_ = pressure.free_index;
    }
    monolithic_solver_->set_matrix(std::move(reduced), &schur);
    return dt;
  }
  factorize_flow(dt);
  if (!new_dt && mechanics_solver_) return dt;  // only the flow's matrix changed
  SparseMatrix a =
      scheme_ == Scheme::Undrained ? SparseMatrix(m_.stiffness + m_.undrained) : m_.stiffness;
  if (!mechanics_solver_)
    mechanics_solver_ = make(SystemKind::Elasticity, "mechanics", k_.displacement);
  keep_prescribed_columns(a, k_.displacement, nullptr, mechanics_lifting_);
  mechanics_solver_->set_matrix(reduce(a, k_.displacement.prolongation));
  return dt;
}

void PoroelasticSolver::factorize_flow(double dt) {
  SparseMatrix a = m_.storage + dt * m_.mobility;
  if (scheme_ == Scheme::FixedStress) a += m_.fixed_stress;
  if (!flow_solver_)
    flow_solver_ = make_linear_solver(SystemKind::Diffusion, "flow", mesh_, c_.axisymmetric,
                                      k_.pressure, nullptr, c_.solver);
  keep_prescribed_columns(a, k_.pressure, nullptr, flow_lifting_);
  flow_solver_->set_matrix(reduce(a, k_.pressure.prolongation));
}

void PoroelasticSolver::solve_temperature(PoroState& s, const PoroState& old, double t1,
                                          double dt) {
  if (!c_.with_temperature()) return;
  const Eigen::VectorXd xd = k_.temperature.prescribed(c_.conditions, t1);
  const Eigen::VectorXd rhs =
      m_.heat_capacity * old.temperature +
      dt * root_share_ *
          (k_.heat_inflow(c_.conditions, t1) + point_sources(ContinuumSource::Kind::Heat, t1)) -
      heat_lifting_ * xd;
  const Eigen::VectorXd y =
      heat_solver_->solve(Eigen::VectorXd(k_.temperature.prolongation.transpose() * rhs),
                          first_guess(*heat_solver_, k_.temperature, s.temperature));
  ++solves_;
  s.temperature = k_.temperature.expand(y, xd);
  if (compute_reactions_ && dt > 0) {
    // The heat equation's residual over dt, C (T - T_n) / dt + (L_T + R) T
    // - inflow: the inflow the prescribed temperatures supply (shares).
    heat_reaction_ = m_.heat_capacity * (s.temperature - old.temperature) / dt +
                     (m_.conduction + root_share_ * k_.heat_transfer) * s.temperature -
                     root_share_ * (k_.heat_inflow(c_.conditions, t1) +
                                    point_sources(ContinuumSource::Kind::Heat, t1));
    parallel::all_sum(heat_reaction_);
  }
}

Eigen::VectorXd PoroelasticSolver::mechanical_load(const PoroState& s, double t1) const {
  // K U - Q (P - P0) - K_T (T - T0) = F - int B^T sigma_0, without Q P.
  Eigen::VectorXd load = root_share_ * k_.traction(c_.conditions, t1) + steady_load_;
  if (interface_load_.size() == load.size()) load += root_share_ * interface_load_;
  if (c_.with_temperature()) load += m_.thermal_stress * (s.temperature - t0_);
  return load;
}

Eigen::VectorXd PoroelasticSolver::flow_load(const PoroState& s, const PoroState& old, double t1,
                                             double dt) const {
  return m_.pressurization * (s.temperature - old.temperature) +
         dt * (root_share_ * (k_.fluid_inflow(c_.conditions, t1) +
                              point_sources(ContinuumSource::Kind::Fluid, t1)) +
               m_.gravity_flow);
}

void PoroelasticSolver::monolithic(PoroState& s, const PoroState& old, double t1, double dt) {
  const FieldNumbering &u = k_.displacement, &p = pressure_numbering();
  const int nu = static_cast<int>(u.condition.size()), np = static_cast<int>(p.condition.size());
  Eigen::VectorXd xd(nu + np), rhs(nu + np);
  xd << u.prescribed(c_.conditions, t1), p.prescribed(c_.conditions, t1);
  // -Q^T U - (S + dt H) P = -Q^T U_n - S P_n - W (T - T_n) - dt (inflow + G).
  rhs << mechanical_load(s, t1), -m_.coupling.transpose() * old.displacement -
                                     m_.storage * old.pressure - flow_load(s, old, t1, dt);
  rhs -= monolithic_lifting_ * xd;
  Eigen::VectorXd reduced(u.n_free + p.n_free);
  reduced << Eigen::VectorXd(u.prolongation.transpose() * rhs.head(nu)) +
                 root_share_ * k_.plate_forces(c_.conditions, t1),
      p.prolongation.transpose() * rhs.tail(np);
  Eigen::VectorXd guess;
  if (monolithic_solver_->takes_a_guess()) {
    guess.resize(u.n_free + p.n_free);
    guess << u.free_part(s.displacement), p.free_part(s.pressure);
  }
  const Eigen::VectorXd y = monolithic_solver_->solve(reduced, guess);
  ++solves_;
  s.displacement = u.expand(y.head(u.n_free), xd.head(nu));
  s.pressure = p.expand(y.tail(p.n_free), xd.tail(np));
}

StepStatistics PoroelasticSolver::staggered(PoroState& s, const PoroState& old, double t1,
                                            double dt) {
  // What the passes do not change is lifted once (continuum_constraints.h):
  // P^T (b - A x_D) of the loads, the old state and the prescribed values.
  const FieldNumbering &u = k_.displacement, &p = k_.pressure;
  const Eigen::VectorXd u_d = u.prescribed(c_.conditions, t1),
                        p_d = p.prescribed(c_.conditions, t1);
  const Eigen::VectorXd mechanics_base =
      Eigen::VectorXd(u.prolongation.transpose() *
                      (mechanical_load(s, t1) - mechanics_lifting_ * u_d)) +
      root_share_ * k_.plate_forces(c_.conditions, t1);
  const auto lifted_flow_load = [&] {
    return Eigen::VectorXd(p.prolongation.transpose() *
                           (m_.storage * old.pressure + m_.coupling.transpose() * old.displacement +
                            flow_load(s, old, t1, dt) - flow_lifting_ * p_d));
  };
  Eigen::VectorXd flow_base = lifted_flow_load();
  StepStatistics stats;
  double first_change = 0;
  for (stats.passes = 1; stats.passes <= c_.max_iterations; ++stats.passes) {
    const PoroState before = s;
    auto flow_step = [&] {
      Eigen::VectorXd rhs = -m_.coupling.transpose() * s.displacement;
      if (scheme_ == Scheme::FixedStress) rhs += m_.fixed_stress * s.pressure;
      s.pressure = p.expand(
          flow_solver_->solve(Eigen::VectorXd(flow_base + p.prolongation.transpose() * rhs),
                              first_guess(*flow_solver_, p, s.pressure)),
          p_d);
      ++solves_;
    };
    auto mechanics_step = [&] {
      Eigen::VectorXd rhs = m_.coupling * s.pressure;
      if (scheme_ == Scheme::Undrained) rhs += m_.undrained * s.displacement;
      s.displacement =
          u.expand(mechanics_solver_->solve(
                       Eigen::VectorXd(mechanics_base + u.prolongation.transpose() * rhs),
                       first_guess(*mechanics_solver_, u, s.displacement)),
                   u_d);
      ++solves_;
    };
    if (scheme_ == Scheme::FixedStress) {
      flow_step();
      mechanics_step();
    } else {
      mechanics_step();
      flow_step();
    }
    stats.last_change =
        std::max(relative_change(s.displacement, before.displacement, displacement_scale_),
                 relative_change(s.pressure, before.pressure, pressure_scale_));
    // A permeability that follows the fields: the tensors of this pass's
    // fields, the flow system with them, and their change in the test.
    double tensors_change = 0;
    if (flow_terms_update_) {
      tensors_change = flow_terms_update_(s);
      if (tensors_change > 0) {
        factorize_flow(dt);
        ++factorizations_;
        flow_base = lifted_flow_load();
      }
    }
    if (stats.passes == 1) first_change = stats.last_change;
    // Diverging (growing) or not contracting after 20 passes (a contraction
    // would have shrunk the change by orders of magnitude by then).
    const bool diverging =
        !std::isfinite(stats.last_change) ||
        (stats.passes > 3 && stats.last_change > 1e3 * std::max(first_change, c_.tolerance)) ||
        (stats.passes >= 20 && stats.last_change > 0.5 * first_change);
    if (stats.last_change <= c_.tolerance && tensors_change <= flow_terms_tolerance_) return stats;
    if (diverging || stats.passes == c_.max_iterations) {
      std::ostringstream why;
      why << "the " << ContinuumControls::scheme_name(scheme_) << " split "
          << (diverging ? "diverges" : "did not converge") << " in the step to t = " << t1
          << " s: its relative change per pass went from " << first_change << " to "
          << stats.last_change << " in " << stats.passes << " passes (tolerance " << c_.tolerance
          << ")";
      if (scheme_ == Scheme::Drained)
        why << "; the coupling strength alpha^2 M / K_dr is "
            << largest_coupling_strength(mesh_, c_)
            << ", and the drained split needs it below 1 (Kim et al. 2011); expected "
               "continuum.scheme: fixed_stress, which converges for any coupling";
      else
        why << "; expected a larger continuum.max_iterations, a smaller step, or scheme: "
               "monolithic";
      throw DivergenceError(why.str());
    }
  }
  return stats;
}

void PoroelasticSolver::undrained_response(PoroState& s, double t) {
  // The monolithic system with dt = 0: no flow has taken place yet, so no
  // pressure is held anywhere either. A drained boundary's value applies
  // from the first step on: imposed at 0+ it would put the whole drop
  // across one element, and the pressure next to it overshoots by 10 %
  // (Terzaghi, 0.25 m elements).
  const Scheme scheme = scheme_;
  const FieldNumbering all_free = free_numbering(mesh_.n_vertices);
  scheme_ = Scheme::Monolithic;
  undrained_pressure_ = &all_free;
  factored_dt_ = -1;
  factorize_for(0);
  const PoroState old = s;
  // No heat has been conducted either: the initial temperatures, with the
  // prescribed values of t on their boundaries. (A heat solve with dt = 0
  // is the consistent capacity's L2 projection of that jump: it undershot
  // the initial temperature beside the boundary, and the pressure answered
  // with signs alternating node by node; issue 36, docs/continuum.md 3.)
  if (c_.with_temperature()) {
    const Eigen::VectorXd xd = k_.temperature.prescribed(c_.conditions, t);
    for (std::size_t i = 0; i < k_.temperature.condition.size(); ++i)
      if (k_.temperature.condition[i] >= 0) s.temperature(static_cast<Eigen::Index>(i)) = xd(i);
  }
  monolithic(s, old, t, 0);
  scheme_ = scheme;
  undrained_pressure_ = nullptr;
  factored_dt_ = -1;  // the steps factorize their own matrices
}

StepStatistics PoroelasticSolver::step(PoroState& s, const PoroState& previous, double previous_dt,
                                       double t, double dt) {
  // Variable-step BDF2, a0 X1 - a1 X0 + a2 X-1 = dt f(X1), is backward Euler
  // from X* = (a1 X0 - a2 X-1) / a0 over dt / a0 (the mechanics has no time
  // derivative); its loads are those of t + dt.
  PoroState old = s;
  double step = dt;
  if (c_.time_scheme == ContinuumControls::TimeScheme::Bdf2 && previous_dt > 0) {
    const auto [a0, a1, a2] = bdf2_coefficients(dt / previous_dt);  // core/base/bdf2.h
    old.displacement = (a1 * s.displacement - a2 * previous.displacement) / a0;
    old.pressure = (a1 * s.pressure - a2 * previous.pressure) / a0;
    old.temperature = (a1 * s.temperature - a2 * previous.temperature) / a0;
    step = dt / a0;
  }
  step = factorize_for(step);
  const double t1 = t + dt;
  displacement_scale_ = std::max(displacement_scale_, s.displacement.lpNorm<Eigen::Infinity>());
  pressure_scale_ = std::max(pressure_scale_, s.pressure.lpNorm<Eigen::Infinity>());
  solve_temperature(s, old, t1, step);
  StepStatistics stats{1, 0};
  if (scheme_ == Scheme::Monolithic)
    monolithic(s, old, t1, step);
  else
    stats = staggered(s, old, t1, step);
  if (compute_reactions_) {
    // The flow equation's residual over dt, (S (P - P_n) + Q^T (U - U_n) -
    // W (T - T_n)) / dt + H P - inflow - G: the inflow the prescribed
    // pressures supply (shares; the fixed-stress term vanishes at convergence).
    fluid_reaction_ = (m_.storage * (s.pressure - old.pressure) +
                       m_.coupling.transpose() * (s.displacement - old.displacement) -
                       m_.pressurization * (s.temperature - old.temperature)) /
                          step +
                      m_.mobility * s.pressure -
                      root_share_ * (k_.fluid_inflow(c_.conditions, t1) +
                                     point_sources(ContinuumSource::Kind::Fluid, t1)) -
                      m_.gravity_flow;
    parallel::all_sum(fluid_reaction_);
  }
  return stats;
}

long PoroelasticSolver::linear_iterations() const {
  long n = iterations_before_;
  for (const auto* solver : {&flow_solver_, &mechanics_solver_, &heat_solver_, &monolithic_solver_})
    if (*solver) n += (*solver)->iterations();
  return n;
}

std::string PoroelasticSolver::linear_solver() const {
  for (const auto* solver : {&mechanics_solver_, &monolithic_solver_})
    if (*solver) return (*solver)->describe();
  return "none";
}

nlohmann::json PoroelasticSolver::factor_sizes() const {
  nlohmann::json sizes = nlohmann::json::object();
  const std::pair<const char*, const ContinuumLinearSolver*> systems[] = {
      {"mechanics", mechanics_solver_.get()},
      {"flow", flow_solver_.get()},
      {"heat", heat_solver_.get()},
      {"monolithic", monolithic_solver_.get()}};
  for (const auto& [name, solver] : systems) {
    if (!solver) continue;
    const ContinuumLinearSolver::FactorSize f = solver->factor_size();
    if (f.entries <= 0) continue;
    sizes[name] = {{"entries", f.entries}, {"flops", f.flops}};
    if (f.backward_error > 0)  // an LU factor, checked when it was made
      sizes[name]["backward_error"] = f.backward_error;
    if (f.backward_error > 0 || f.refined) sizes[name]["refined"] = f.refined;
  }
  return sizes;
}

}  // namespace fissure::continuum
