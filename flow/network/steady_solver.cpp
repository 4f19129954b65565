#include "flow/network/steady_solver.h"

#include <algorithm>
#include <cmath>

#include "core/base/errors.h"
#include "core/base/stopwatch.h"

namespace fissure::flow {

void segment_fluxes(const FractureGraph& graph, std::span<const double> conductance,
                    std::span<const double> potential, std::vector<double>& flux) {
  flux.assign(graph.n_segments(), 0.0);
  for (int s = 0; s < graph.n_segments(); ++s) {
    const FractureSegment& seg = graph.segments[s];
    if (conductance[s] > 0)
      flux[s] = conductance[s] * (potential[seg.node_a] - potential[seg.node_b]);
  }
}

void node_inflows(const FractureGraph& graph, std::span<const double> flux,
                  std::vector<double>& inflow) {
  // Inflow from outside = what leaves the node through its segments.
  inflow.assign(graph.n_nodes(), 0.0);
  for (int s = 0; s < graph.n_segments(); ++s) {
    inflow[graph.segments[s].node_a] += flux[s];
    inflow[graph.segments[s].node_b] -= flux[s];
  }
}

NetworkSolution SteadySolver::solve(const FractureGraph& graph, std::span<const double> conductance,
                                    const NodeConditions& conditions, const FluidProperties& fluid,
                                    const Vec2& gravity, std::span<const double> previous) {
  const Stopwatch clock;
  const int n = graph.n_nodes();
  FISSURE_CHECK(
      static_cast<int>(conductance.size()) == graph.n_segments() && conditions.n_nodes() == n,
      SolverError, "flow: conductances or conditions do not match the network");
  NetworkSolution sol;
  Stopwatch phase;

  // 1. Reduce: dead ends, isolated clusters.
  sol.topology = reduce_network(graph, conductance, conditions, true);
  const NetworkTopology& topo = sol.topology;
  for (int c = 0; c < topo.n_components; ++c) {
    if (topo.component_fixed[c]) {
      ++sol.n_components;
      continue;
    }
    sol.n_isolated_nodes += topo.component_size[c];
    if (std::abs(topo.component_source[c]) > 0) {
      int at = 0;
      while (topo.component[at] != c) ++at;
      FISSURE_CHECK(false, SolverError,
                    "flow: no steady state: "
                        << topo.component_source[c] << " m^2/s is injected into a cluster of "
                        << topo.component_size[c] << " fracture nodes (one at ("
                        << graph.nodes[at].x() << ", " << graph.nodes[at].y()
                        << ")) that no fixed-pressure boundary reaches");
    }
  }
  sol.n_dead_end_nodes = static_cast<int>(topo.dead_ends.size());
  sol.seconds.reduction = phase.seconds();
  phase.restart();

  // 2. Potentials at fixed nodes: p* = p - rho g.x.
  std::vector<double> potential(n, 0.0), offset(n);
  for (int v = 0; v < n; ++v) {
    offset[v] = hydrostatic_offset(fluid, gravity, graph.nodes[v]);
    const double p = conditions.is_fixed(v) ? conditions.fixed_pressure[v]
                     : previous.empty()     ? 0.0
                                            : previous[v];
    potential[v] = p - offset[v];
  }

  // 3. Assemble and solve over the solved components.
  std::vector<char> include(n, 0);
  for (int v = 0; v < n; ++v) include[v] = topo.solved(v);
  NetworkSystem system;
  number_unknowns(include, conditions, system);
  assemble_network(graph, conductance, topo.segments, conditions, potential, offset, system);
  sol.n_unknowns = system.n_unknowns();
  sol.seconds.assembly = phase.seconds();
  phase.restart();
  if (sol.n_unknowns > 0) {
    std::vector<int> pattern = system.node_of_unknown;
    pattern.push_back(-1);
    pattern.insert(pattern.end(), topo.segments.begin(), topo.segments.end());
    if (!solver_ || pattern != pattern_) {
      if (!solver_) solver_ = make_spd_solver(controls_, sol.n_unknowns, allow_petsc_);
      solver_->analyze(system.matrix);
      pattern_ = std::move(pattern);
    }
    solver_->factorize(system.matrix);
    Eigen::VectorXd x;
    solver_->solve(system.rhs, x);
    FISSURE_CHECK(x.allFinite(), SolverError, "flow: the network solve gave non-finite pressures");
    for (int i = 0; i < sol.n_unknowns; ++i) potential[system.node_of_unknown[i]] = x[i];
  }

  sol.seconds.solve = phase.seconds();
  phase.restart();

  // 4. Dead ends take the potential of the node they hang from.
  for (auto it = topo.dead_ends.rbegin(); it != topo.dead_ends.rend(); ++it)
    potential[it->first] = potential[it->second];

  // 5. Pressures, fluxes, inflows, balance.
  sol.pressure.resize(n);
  for (int v = 0; v < n; ++v) sol.pressure[v] = potential[v] + offset[v];
  std::vector<double> flux_potential = potential;
  // Segments of isolated clusters carry nothing (their potentials are not solved).
  std::vector<double> active_conductance(conductance.begin(), conductance.end());
  for (int s = 0; s < graph.n_segments(); ++s) {
    const int a = graph.segments[s].node_a;
    const bool solved = topo.solved(a) || (topo.component[a] < 0 && conditions.is_fixed(a));
    const int b = graph.segments[s].node_b;
    const bool solved_b = topo.solved(b) || (topo.component[b] < 0 && conditions.is_fixed(b));
    if (!(solved || solved_b)) active_conductance[s] = 0;
  }
  segment_fluxes(graph, active_conductance, flux_potential, sol.flux);
  node_inflows(graph, sol.flux, sol.inflow);
  double max_flux = 0, max_residual = 0;
  for (double q : sol.flux) max_flux = std::max(max_flux, std::abs(q));
  for (int v = 0; v < n; ++v) {
    if (conditions.is_fixed(v)) continue;
    // What the conditions bring in (an isolated node's exchange is not solved).
    const double given =
        topo.solved(v) ? conditions.inflow(v, sol.pressure[v]) : conditions.source[v];
    max_residual = std::max(max_residual, std::abs(sol.inflow[v] - given));
    sol.inflow[v] = given;
  }
  sol.balance_error = max_flux > 0 ? max_residual / max_flux : 0;
  sol.seconds.post = phase.seconds();
  ++solves_;
  seconds_ += clock.seconds();
  return sol;
}

nlohmann::json SteadySolver::linear_solver_statistics() const {
  nlohmann::json s = solver_ ? solver_->statistics() : nlohmann::json::object();
  for (const auto& [name, before] : linear_solver_before_.items())
    s[name] = before.get<long>() + s.value(name, 0L);
  return s;
}

void SteadySolver::linear_solver_counts(std::vector<std::string>& names,
                                        std::vector<double>& counts) const {
  const nlohmann::json statistics = linear_solver_statistics();
  for (const auto& [name, value] : statistics.items())
    if (value.is_number()) {
      names.push_back(name);
      counts.push_back(value.get<double>());
    }
}

void SteadySolver::restore_linear_solver_counts(const std::vector<std::string>& names,
                                                const std::vector<double>& counts) {
  // Counts only grow: the larger total is kept, the checkpoint's at a
  // restart, this run's own in a rollback within the run (they count the
  // rolled-back passes' work). The solver's own counts go on from theirs.
  const nlohmann::json totals = linear_solver_statistics();
  for (std::size_t k = 0; k < names.size() && k < counts.size(); ++k) {
    const long more = static_cast<long>(counts[k]) - totals.value(names[k], 0L);
    if (more > 0)
      linear_solver_before_[names[k]] = linear_solver_before_.value(names[k], 0L) + more;
  }
}

nlohmann::json SteadySolver::statistics() const {
  nlohmann::json s = {{"solves", solves_}, {"seconds", seconds_}};
  if (solver_ || !linear_solver_before_.empty()) {
    s["linear_solver"] = linear_solver_statistics();
    if (solver_) s["linear_solver"]["name"] = solver_->name();
  }
  return s;
}

}  // namespace fissure::flow
