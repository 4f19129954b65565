// Boundary conditions as the network solvers see them (theory.md 3.3): per
// node either a fixed pressure (Dirichlet; moves to the right-hand side) or a
// free pressure with an injected volume rate (fixed flux, well, sink) and,
// where the node is tied to a continuum (flow/cubic_law/flow_ties.h), an
// exchange c (p_e - p) with an outside pressure p_e through a conductance c
// (Robin: c joins the matrix's diagonal, c p_e the right-hand side). A free
// node with zero rate and no exchange is a no-flow node: no-flow is the
// default everywhere.
#pragma once

#include <cmath>
#include <limits>
#include <vector>

namespace fissure::flow {

struct NodeConditions {
  /// Fixed pressure p (Pa), NaN where the pressure is free.
  std::vector<double> fixed_pressure;
  /// Volume rate injected at the node (m^2/s per unit thickness; > 0 into
  /// the network, < 0 a sink). Ignored at fixed-pressure nodes.
  std::vector<double> source;
  /// Exchange conductance c (m^2/(s Pa) per unit thickness; 0: none) and
  /// outside pressure p_e (Pa): c (p_e - p) flows into the node.
  std::vector<double> exchange_conductance;
  std::vector<double> exchange_pressure;

  explicit NodeConditions(int n_nodes = 0)
      : fixed_pressure(n_nodes, std::numeric_limits<double>::quiet_NaN()),
        source(n_nodes, 0.0),
        exchange_conductance(n_nodes, 0.0),
        exchange_pressure(n_nodes, 0.0) {}
  int n_nodes() const { return static_cast<int>(fixed_pressure.size()); }
  bool is_fixed(int node) const { return !std::isnan(fixed_pressure[node]); }
  /// A free node that exchanges with an outside pressure: it anchors its
  /// cluster's pressure as a fixed one does.
  bool exchanges(int node) const { return !is_fixed(node) && exchange_conductance[node] > 0; }
  /// What flows into a free node from outside at its pressure p (m^2/s).
  double inflow(int node, double p) const {
    return source[node] + exchange_conductance[node] * (exchange_pressure[node] - p);
  }
  bool any_fixed() const {
    for (double p : fixed_pressure)
      if (!std::isnan(p)) return true;
    return false;
  }
};

}  // namespace fissure::flow
