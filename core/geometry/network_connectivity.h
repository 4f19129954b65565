// Connectivity of a network of nodes and segments (the fracture graph of
// rockmass/fracture_graph.h, or any other): connected components, which
// named boundaries each component touches, percolation between two
// boundaries, and the dead-end segments that cannot carry steady flow. Lives
// in core so that both the block generator (mechanics/blocks) and the flow
// solver (flow/, which must find components without a Dirichlet node,
// theory.md 3.3) can use it.
//
// Definitions (docs/rock-mass.md, "Connectivity"):
//  * two segments are connected when they share a node; a component is a
//    maximal connected set of segments (nodes without segments belong to no
//    component);
//  * a component touches boundary B when one of its nodes is listed for B;
//  * boundaries A and B percolate when one component touches both;
//  * an isolated component touches no boundary; a dead-end component touches
//    exactly one (it can exchange fluid with one boundary only);
//  * a dead-end segment is one removed by repeatedly pruning nodes of degree 1
//    that lie on no boundary: in a steady state without sources its flow is
//    zero. What remains is the backbone (plus isolated loops).
#pragma once

#include <map>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace fissure {

struct NetworkConnectivity {
  int n_components = 0;
  std::vector<int> segment_component;   ///< per segment
  std::vector<int> node_component;      ///< per node; -1 for a node without segments
  std::vector<int> component_segments;  ///< per component: number of segments
  /// Per component: the names of the boundaries it touches, sorted.
  std::vector<std::vector<std::string>> component_boundaries;
  std::vector<char> dead_end;  ///< per segment: 1 when pruned as a dead end

  bool isolated(int component) const { return component_boundaries[component].empty(); }
  bool dead_end_component(int component) const {
    return component_boundaries[component].size() == 1;
  }
  int n_isolated() const;
  int n_dead_end_components() const;
  int n_dead_end_segments() const;
  /// True when one component touches both boundaries.
  bool percolates(const std::string& a, const std::string& b) const;
};

/// Components are numbered by their lowest segment index. Segments whose two
/// ends are the same node are allowed (they never count as dead ends on their
/// own). Node indices must be in [0, n_nodes). Cost O(nodes + segments).
NetworkConnectivity analyze_connectivity(int n_nodes, std::span<const std::pair<int, int>> segments,
                                         const std::map<std::string, std::vector<int>>& boundaries);

}  // namespace fissure
