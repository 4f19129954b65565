// The part of a fracture network that a steady solve needs (theory.md 3.3):
//  * dead ends are removed: a node with one conducting segment, no fixed
//    pressure and no source carries no flow in steady state, so its potential
//    p* equals its neighbour's; trees of such nodes are peeled leaf by leaf
//    and filled back after the solve;
//  * the rest is split into connected components (union-find). A component
//    with a fixed-pressure node gives an SPD block of the system. A component
//    without one is isolated: with no net source it carries no flow and is
//    left out (its pressures are not changed), with a net source it has no
//    steady state, which the caller reports as an error.
// So the assembled matrix is SPD by construction, never singular.
#pragma once

#include <span>
#include <utility>
#include <vector>

#include "flow/network/node_conditions.h"
#include "rockmass/fracture_graph.h"

namespace fissure::flow {

struct NetworkTopology {
  /// Component of each node in the reduced network; -1 for nodes outside it
  /// (dead ends, nodes without a conducting segment).
  std::vector<int> component;
  int n_components = 0;
  std::vector<char> component_fixed;  ///< per component: holds a fixed-pressure or exchanging node
  std::vector<double> component_source;  ///< per component: total injected rate (m^2/s)
  std::vector<int> component_size;       ///< per component: nodes
  /// Dead-end nodes in the order they were removed, each with the neighbour
  /// it hung from (fill back in reverse order).
  std::vector<std::pair<int, int>> dead_ends;
  /// Segments of the reduced network (conducting, both ends in it).
  std::vector<int> segments;

  /// Whether node n takes part in the linear system (in a component with a
  /// fixed-pressure node).
  bool solved(int node) const { return component[node] >= 0 && component_fixed[component[node]]; }
};

/// Reduces `graph` for a solve. Segments with conductance <= 0 do not conduct.
/// `remove_dead_ends` is false for transient solves (dead ends store fluid).
NetworkTopology reduce_network(const FractureGraph& graph, std::span<const double> conductance,
                               const NodeConditions& conditions, bool remove_dead_ends);

}  // namespace fissure::flow
