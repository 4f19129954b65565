// Boundary conditions as the network solvers see them (theory.md 3.3): per
// node either a fixed pressure (Dirichlet; moves to the right-hand side) or a
// free pressure with an injected volume rate (fixed flux, well, sink). A free
// node with zero rate is a no-flow node: no-flow is the default everywhere.
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

  explicit NodeConditions(int n_nodes = 0)
      : fixed_pressure(n_nodes, std::numeric_limits<double>::quiet_NaN()), source(n_nodes, 0.0) {}
  int n_nodes() const { return static_cast<int>(fixed_pressure.size()); }
  bool is_fixed(int node) const { return !std::isnan(fixed_pressure[node]); }
  bool any_fixed() const {
    for (double p : fixed_pressure)
      if (!std::isnan(p)) return true;
    return false;
  }
};

}  // namespace fissure::flow
