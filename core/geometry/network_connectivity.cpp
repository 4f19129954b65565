#include "core/geometry/network_connectivity.h"

#include <algorithm>

#include "core/base/errors.h"
#include "core/geometry/union_find.h"

namespace fissure {

int NetworkConnectivity::n_isolated() const {
  int n = 0;
  for (int c = 0; c < n_components; ++c) n += isolated(c) ? 1 : 0;
  return n;
}

int NetworkConnectivity::n_dead_end_components() const {
  int n = 0;
  for (int c = 0; c < n_components; ++c) n += dead_end_component(c) ? 1 : 0;
  return n;
}

int NetworkConnectivity::n_dead_end_segments() const {
  return static_cast<int>(std::count(dead_end.begin(), dead_end.end(), 1));
}

bool NetworkConnectivity::percolates(const std::string& a, const std::string& b) const {
  for (const std::vector<std::string>& names : component_boundaries)
    if (std::binary_search(names.begin(), names.end(), a) &&
        std::binary_search(names.begin(), names.end(), b))
      return true;
  return false;
}

namespace {

/// Marks the segments removed by pruning non-boundary nodes of degree 1.
std::vector<char> prune_dead_ends(int n_nodes, std::span<const std::pair<int, int>> segments,
                                  const std::vector<char>& on_boundary) {
  const int ns = static_cast<int>(segments.size());
  // Node -> incident segments (CSR).
  std::vector<int> start(n_nodes + 1, 0), degree(n_nodes, 0);
  for (const auto& [a, b] : segments) {
    ++start[a + 1];
    if (b != a) ++start[b + 1];
  }
  for (int v = 0; v < n_nodes; ++v) start[v + 1] += start[v];
  std::vector<int> incident(start.back());
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (int s = 0; s < ns; ++s) {
    const auto [a, b] = segments[s];
    incident[fill[a]++] = s;
    ++degree[a];
    if (b != a) {
      incident[fill[b]++] = s;
      ++degree[b];
    }
  }

  std::vector<char> removed(ns, 0);
  std::vector<int> stack;
  for (int v = 0; v < n_nodes; ++v)
    if (degree[v] == 1 && !on_boundary[v]) stack.push_back(v);
  while (!stack.empty()) {
    const int v = stack.back();
    stack.pop_back();
    if (degree[v] != 1) continue;
    for (int k = start[v]; k < start[v + 1]; ++k) {
      const int s = incident[k];
      if (removed[s]) continue;
      removed[s] = 1;
      const int w = segments[s].first == v ? segments[s].second : segments[s].first;
      --degree[v];
      --degree[w];
      if (degree[w] == 1 && !on_boundary[w]) stack.push_back(w);
      break;
    }
  }
  return removed;
}

}  // namespace

NetworkConnectivity analyze_connectivity(
    int n_nodes, std::span<const std::pair<int, int>> segments,
    const std::map<std::string, std::vector<int>>& boundaries) {
  NetworkConnectivity r;
  const int ns = static_cast<int>(segments.size());
  for (const auto& [a, b] : segments)
    FISSURE_CHECK(a >= 0 && a < n_nodes && b >= 0 && b < n_nodes, GeometryError,
                  "analyze_connectivity: segment ("
                      << a << ", " << b << ") names a node outside [0, " << n_nodes << ")");

  // 1. Components: union the two ends of every segment.
  UnionFind sets(n_nodes);
  for (const auto& [a, b] : segments) sets.unite(a, b);
  std::vector<int> root_component(n_nodes, -1);
  r.segment_component.resize(ns);
  for (int s = 0; s < ns; ++s) {
    const int root = sets.find(segments[s].first);
    if (root_component[root] < 0) {
      root_component[root] = r.n_components++;
      r.component_segments.push_back(0);
    }
    r.segment_component[s] = root_component[root];
    ++r.component_segments[r.segment_component[s]];
  }
  r.node_component.assign(n_nodes, -1);
  for (int s = 0; s < ns; ++s) {
    r.node_component[segments[s].first] = r.segment_component[s];
    r.node_component[segments[s].second] = r.segment_component[s];
  }

  // 2. Boundaries touched by each component.
  r.component_boundaries.assign(r.n_components, {});
  std::vector<char> on_boundary(n_nodes, 0);
  for (const auto& [name, nodes] : boundaries) {
    for (int v : nodes) {
      FISSURE_CHECK(v >= 0 && v < n_nodes, GeometryError,
                    "analyze_connectivity: boundary '" << name << "' lists node " << v
                                                       << " outside [0, " << n_nodes << ")");
      on_boundary[v] = 1;
      const int c = r.node_component[v];
      if (c < 0) continue;
      std::vector<std::string>& names = r.component_boundaries[c];
      if (names.empty() || names.back() != name) names.push_back(name);
    }
  }
  for (std::vector<std::string>& names : r.component_boundaries) {
    std::sort(names.begin(), names.end());
    names.erase(std::unique(names.begin(), names.end()), names.end());
  }

  // 3. Dead ends.
  r.dead_end = prune_dead_ends(n_nodes, segments, on_boundary);
  return r;
}

}  // namespace fissure
