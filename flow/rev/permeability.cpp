#include "flow/rev/permeability.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/base/errors.h"

#include "flow/network/apertures.h"
#include "flow/network/network_reduction.h"
#include "flow/network/network_system.h"
#include "flow/network/spd_solver.h"
#include "flow/network/steady_solver.h"

namespace fissure::flow {

namespace {

/// Why a domain's factorization can fail where every conductance is
/// positive: their spread, set by the cubic law (a^3) from the apertures,
/// beyond what a Cholesky factorization in double precision resolves (a
/// contrast of about 1e15 and more leaves pivots that round-off makes <= 0).
std::string conductance_spread(const FractureGraph& g, const std::vector<double>& conductance,
                               const std::vector<double>& aperture_a,
                               const std::vector<double>& aperture_b) {
  double c_min = std::numeric_limits<double>::infinity(), c_max = 0;
  double a_min = std::numeric_limits<double>::infinity(), a_max = 0;
  for (int s = 0; s < g.n_segments(); ++s) {
    c_min = std::min(c_min, conductance[s]), c_max = std::max(c_max, conductance[s]);
    a_min = std::min({a_min, aperture_a[s], aperture_b[s]});
    a_max = std::max({a_max, aperture_a[s], aperture_b[s]});
  }
  return fmt::format(
      "its segment conductances span {:.3g} to {:.3g} m^3/(Pa s) ({:.0f} orders of magnitude, from "
      "apertures of {:.3g} to {:.3g} m), more than a double-precision factorization resolves "
      "(about 15 orders); expected apertures (the network's aperture values or distributions) "
      "with a smaller spread",
      c_min, c_max, std::log10(c_max / c_min), a_min, a_max);
}

}  // namespace

DomainPermeability domain_permeability(const FractureGraph& g, double size, double viscosity,
                                       double pressure_drop) {
  std::vector<double> aperture(g.n_segments());
  for (int s = 0; s < g.n_segments(); ++s) aperture[s] = g.segments[s].aperture;
  return domain_permeability(g, size, viscosity, pressure_drop, aperture, aperture);
}

DomainPermeability domain_permeability(const FractureGraph& g, double size, double viscosity,
                                       double pressure_drop, const std::vector<double>& aperture_a,
                                       const std::vector<double>& aperture_b) {
  DomainPermeability result;
  result.n_nodes = g.n_nodes();
  result.n_segments = g.n_segments();
  const int n = g.n_nodes();

  // 1. All boundary nodes are fixed (both load cases).
  std::vector<char> on_boundary(n, 0);
  for (const auto& [name, nodes] : g.boundary_nodes)
    for (int v : nodes) on_boundary[v] = 1;
  NodeConditions conditions(n);
  for (int v = 0; v < n; ++v)
    if (on_boundary[v]) conditions.fixed_pressure[v] = 0;
  std::vector<double> conductance(g.n_segments());
  for (int s = 0; s < g.n_segments(); ++s)
    conductance[s] = segment_conductance(aperture_a[s], aperture_b[s], g.length(s), viscosity);
  const NetworkTopology topo = reduce_network(g, conductance, conditions, true);

  // 2. Does any component join two different sides?
  std::vector<int> side_mask(topo.n_components, 0);
  int bit = 0;
  for (const auto& [name, nodes] : g.boundary_nodes) {
    for (int v : nodes)
      if (topo.component[v] >= 0) side_mask[topo.component[v]] |= 1 << bit;
    ++bit;
  }
  for (int mask : side_mask)
    if (mask & (mask - 1)) result.connected = true;

  std::vector<char> include(n, 0);
  for (int v = 0; v < n; ++v) include[v] = topo.solved(v);
  NetworkSystem system;
  number_unknowns(include, conditions, system);
  result.n_unknowns = system.n_unknowns();

  // 3. Two load cases on one factorization.
  const double gradient = pressure_drop / size;
  std::unique_ptr<SpdSolver> solver;
  std::vector<double> potential(n), flux, inflow;
  const double area = size * size;
  for (int axis = 0; axis < 2; ++axis) {
    for (int v = 0; v < n; ++v) potential[v] = -gradient * g.nodes[v][axis];
    assemble_network(g, conductance, topo.segments, conditions, potential, {}, system);
    if (system.n_unknowns() > 0) {
      if (!solver) {
        solver = make_direct_spd_solver();
        solver->analyze(system.matrix);
        try {
          solver->factorize(system.matrix);
        } catch (const SolverError&) {
          throw SolverError("the flow network matrix is not positive definite: " +
                            conductance_spread(g, conductance, aperture_a, aperture_b));
        }
      }
      Eigen::VectorXd x;
      solver->solve(system.rhs, x);
      for (int i = 0; i < system.n_unknowns(); ++i) potential[system.node_of_unknown[i]] = x[i];
    }
    // Dead ends, isolated clusters: no flow (conductance of unsolved segments is cut).
    std::vector<double> c = conductance;
    for (int s = 0; s < g.n_segments(); ++s) {
      const int a = g.segments[s].node_a, b = g.segments[s].node_b;
      const bool solved_a = topo.solved(a), solved_b = topo.solved(b);
      if (!solved_a || !solved_b) c[s] = 0;
    }
    segment_fluxes(g, c, potential, flux);
    node_inflows(g, flux, inflow);
    // q_bar = (1/A) sum_b x_b Q_b with Q_b = -inflow (outward).
    Eigen::Vector2d q = Eigen::Vector2d::Zero();
    for (int v = 0; v < n; ++v)
      if (on_boundary[v]) q -= inflow[v] * g.nodes[v];
    q /= area;
    // dp/dx_axis = -gradient: k(:, axis) = -mu q / (-gradient).
    result.k.col(axis) = viscosity * q / gradient;
  }
  return result;
}

}  // namespace fissure::flow
