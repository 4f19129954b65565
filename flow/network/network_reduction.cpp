#include "flow/network/network_reduction.h"

#include <numeric>

#include "core/geometry/union_find.h"

namespace fissure::flow {

NetworkTopology reduce_network(const FractureGraph& graph, std::span<const double> conductance,
                               const NodeConditions& conditions, bool remove_dead_ends) {
  const int n = graph.n_nodes();
  const int m = graph.n_segments();
  NetworkTopology t;

  // 1. Conducting segments and node degrees (a self-loop conducts nothing).
  std::vector<char> conducting(m, 0);
  std::vector<int> degree(n, 0);
  for (int s = 0; s < m; ++s) {
    const FractureSegment& seg = graph.segments[s];
    if (conductance[s] > 0 && seg.node_a != seg.node_b) {
      conducting[s] = 1;
      ++degree[seg.node_a];
      ++degree[seg.node_b];
    }
  }

  // 2. Peel dead ends. Adjacency in CSR form for the neighbour look-up.
  std::vector<char> removed(n, 0);
  if (remove_dead_ends) {
    std::vector<int> start(n + 1, 0), adjacent;
    for (int s = 0; s < m; ++s)
      if (conducting[s]) {
        ++start[graph.segments[s].node_a + 1];
        ++start[graph.segments[s].node_b + 1];
      }
    std::partial_sum(start.begin(), start.end(), start.begin());
    adjacent.resize(start[n]);
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int s = 0; s < m; ++s)
      if (conducting[s]) {
        adjacent[fill[graph.segments[s].node_a]++] = s;
        adjacent[fill[graph.segments[s].node_b]++] = s;
      }
    auto peelable = [&](int v) {
      return !removed[v] && degree[v] == 1 && !conditions.is_fixed(v) &&
             conditions.source[v] == 0 && !conditions.exchanges(v);
    };
    std::vector<int> queue;
    for (int v = 0; v < n; ++v)
      if (peelable(v)) queue.push_back(v);
    while (!queue.empty()) {
      const int v = queue.back();
      queue.pop_back();
      if (!peelable(v)) continue;
      // Its one remaining segment.
      for (int k = start[v]; k < start[v + 1]; ++k) {
        const int s = adjacent[k];
        if (!conducting[s]) continue;
        const int w =
            graph.segments[s].node_a == v ? graph.segments[s].node_b : graph.segments[s].node_a;
        conducting[s] = 0;
        removed[v] = 1;
        --degree[v];
        --degree[w];
        t.dead_ends.emplace_back(v, w);
        if (peelable(w)) queue.push_back(w);
        break;
      }
    }
  }

  // 3. Components of what is left (union-find over conducting segments).
  UnionFind sets(n);
  for (int s = 0; s < m; ++s)
    if (conducting[s]) sets.unite_to_smallest(graph.segments[s].node_a, graph.segments[s].node_b);
  t.component.assign(n, -1);
  std::vector<int> id_of_root(n, -1);
  for (int v = 0; v < n; ++v) {
    // A node without a conducting segment is left out, unless fluid is
    // injected there: it then forms a component of its own, which has no
    // steady state and is reported by the caller.
    if (removed[v] || (degree[v] == 0 && (conditions.is_fixed(v) || conditions.source[v] == 0)))
      continue;
    const int r = sets.find(v);
    if (id_of_root[r] < 0) {
      id_of_root[r] = t.n_components++;
      t.component_fixed.push_back(0);
      t.component_source.push_back(0);
      t.component_size.push_back(0);
    }
    const int c = id_of_root[r];
    t.component[v] = c;
    ++t.component_size[c];
    if (conditions.is_fixed(v) || conditions.exchanges(v))
      t.component_fixed[c] = 1;
    else
      t.component_source[c] += conditions.source[v];
  }
  for (int s = 0; s < m; ++s)
    if (conducting[s]) t.segments.push_back(s);
  return t;
}

}  // namespace fissure::flow
