#include "flow/network/network_system.h"

namespace fissure::flow {

void number_unknowns(std::span<const char> include, const NodeConditions& conditions,
                     NetworkSystem& system) {
  const int n = static_cast<int>(include.size());
  system.unknown_of_node.assign(n, -1);
  system.node_of_unknown.clear();
  for (int v = 0; v < n; ++v)
    if (include[v] && !conditions.is_fixed(v)) {
      system.unknown_of_node[v] = static_cast<int>(system.node_of_unknown.size());
      system.node_of_unknown.push_back(v);
    }
}

void assemble_network(const FractureGraph& graph, std::span<const double> conductance,
                      std::span<const int> segments, const NodeConditions& conditions,
                      std::span<const double> potential, std::span<const double> offset,
                      NetworkSystem& system) {
  const int n = system.n_unknowns();
  system.rhs.setZero(n);
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(4 * segments.size() + n);
  for (int i = 0; i < n; ++i) {
    const int v = system.node_of_unknown[i];
    system.rhs[i] = conditions.source[v];
    if (const double c = conditions.exchange_conductance[v]; c > 0) {
      triplets.emplace_back(i, i, c);
      system.rhs[i] += c * (conditions.exchange_pressure[v] - (offset.empty() ? 0.0 : offset[v]));
    }
  }
  for (int s : segments) {
    const int a = graph.segments[s].node_a, b = graph.segments[s].node_b;
    const int ia = system.unknown_of_node[a], ib = system.unknown_of_node[b];
    const double c = conductance[s];
    if (ia >= 0) triplets.emplace_back(ia, ia, c);
    if (ib >= 0) triplets.emplace_back(ib, ib, c);
    if (ia >= 0 && ib >= 0) {
      triplets.emplace_back(ia, ib, -c);
      triplets.emplace_back(ib, ia, -c);
    } else if (ia >= 0 && conditions.is_fixed(b)) {
      system.rhs[ia] += c * potential[b];
    } else if (ib >= 0 && conditions.is_fixed(a)) {
      system.rhs[ib] += c * potential[a];
    }
  }
  system.matrix.resize(n, n);
  system.matrix.setFromTriplets(triplets.begin(), triplets.end());
}

}  // namespace fissure::flow
