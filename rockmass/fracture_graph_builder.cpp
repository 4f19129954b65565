// Step 5 of block cutting (block_cutter.h): the fracture graph
// (rockmass/fracture_graph.h) from the cut subdivision.
//
// A graph segment is an edge of the subdivision that lies on a trace and has
// rock on both sides, between two distinct merged nodes. Edges on the rock
// boundary are not fractures, and neither is a fracture piece that merging
// has laid onto the boundary (same two nodes as a boundary edge). Two pieces
// between the same nodes (nearly coincident fractures merged) become one
// segment whose aperture carries both flows under the cubic law:
// e = (e1^3 + e2^3)^(1/3) (theory.md 3.1). Nodes are numbered in order of
// first use; a named boundary lists the nodes at the ends of its rock
// boundary edges.
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "rockmass/cut_state.h"

namespace fissure {

namespace {

/// Values keyed by an unordered pair of vertices, chained from the smaller
/// vertex: vertices have few edges, so a look-up walks a handful of entries
/// in flat arrays (linear in the subdivision, unlike a hash table of node
/// allocations whose cost grows with cache misses).
class VertexPairIndex {
 public:
  explicit VertexPairIndex(int n_vertices) : head_(n_vertices, -1) {}
  /// The value stored for {a, b}, or -1.
  int find(int a, int b) const {
    if (a > b) std::swap(a, b);
    for (int k = head_[a]; k >= 0; k = entries_[k].next)
      if (entries_[k].other == b) return entries_[k].value;
    return -1;
  }
  /// Stores {a, b} -> value (value >= 0), when {a, b} is not yet there.
  void insert(int a, int b, int value) {
    if (a > b) std::swap(a, b);
    if (find(a, b) >= 0) return;
    entries_.push_back(Entry{b, value, head_[a]});
    head_[a] = static_cast<int>(entries_.size()) - 1;
  }

 private:
  struct Entry {
    int other, value, next;
  };
  std::vector<int> head_;
  std::vector<Entry> entries_;
};

}  // namespace

FractureGraph build_fracture_graph(CutState& state, const std::vector<ExtractedBlock>& blocks,
                                   const std::vector<int>& block_of_group,
                                   const std::vector<FractureTrace>& traces,
                                   const std::vector<std::vector<std::string>>& boundary_names) {
  const PlanarSubdivision& sub = state.sub;
  FractureGraph graph;

  // Which block edge each retained boundary half-edge is.
  std::vector<int> corner_block(sub.n_halfedges(), -1), corner_index(sub.n_halfedges(), -1);
  for (size_t b = 0; b < blocks.size(); ++b)
    for (size_t i = 0; i < blocks[b].halfedge.size(); ++i) {
      corner_block[blocks[b].halfedge[i]] = static_cast<int>(b);
      corner_index[blocks[b].halfedge[i]] = static_cast<int>(i);
    }

  // Node pairs of the rock boundary.
  const int n_vertices = static_cast<int>(sub.vertices.size());
  VertexPairIndex boundary_pairs(n_vertices);
  auto rock_boundary = [&](int e) {
    return (state.rock[sub.face[2 * e]] != 0) != (state.rock[sub.face[2 * e + 1]] != 0);
  };
  for (int e = 0; e < sub.n_edges(); ++e)
    if (rock_boundary(e))
      boundary_pairs.insert(state.node_of(sub.origin[2 * e]), state.node_of(sub.target(2 * e)), 0);

  std::vector<int> node_index(sub.vertices.size(), -1);
  auto node = [&](int v) {
    if (node_index[v] < 0) {
      node_index[v] = graph.n_nodes();
      graph.nodes.push_back(sub.vertices[v]);
    }
    return node_index[v];
  };
  auto face_of = [&](int h) {
    BlockFace f;
    const int g = state.group(sub.face[h]);
    f.block = g >= 0 ? block_of_group[g] : -1;
    if (g != state.group(sub.face[h ^ 1]) && corner_block[h] == f.block) f.edge = corner_index[h];
    return f;
  };

  VertexPairIndex segment_of_pair(n_vertices);
  for (int e = 0; e < sub.n_edges(); ++e) {
    const int h = 2 * e;
    if (!state.rock[sub.face[h]] || !state.rock[sub.face[h ^ 1]] || state.boundary_edge(e))
      continue;
    const int trace = state.trace_of_edge(e);
    if (trace < 0) continue;
    const int a = state.node_of(sub.origin[h]), b = state.node_of(sub.target(h));
    if (a == b) continue;
    if (boundary_pairs.find(a, b) >= 0) continue;
    const double aperture = traces[trace].aperture;
    if (const int existing = segment_of_pair.find(a, b); existing >= 0) {
      double& e0 = graph.segments[existing].aperture;
      e0 = std::cbrt(e0 * e0 * e0 + aperture * aperture * aperture);
      continue;
    }
    FractureSegment s;
    s.node_a = node(a);
    s.node_b = node(b);
    s.fracture = trace;
    s.joint_set = traces[trace].set;
    s.aperture = aperture;
    s.left = face_of(h);
    s.right = face_of(h ^ 1);
    segment_of_pair.insert(a, b, graph.n_segments());
    graph.segments.push_back(s);
  }

  // Named boundaries.
  for (int e = 0; e < sub.n_edges(); ++e) {
    if (!rock_boundary(e)) continue;
    for (int c : sub.edge_curves(e)) {
      if (c >= state.n_boundary) break;
      for (const std::string& name : boundary_names[c]) {
        std::vector<int>& nodes = graph.boundary_nodes[name];
        for (int v : {sub.origin[2 * e], sub.target(2 * e)}) {
          const int n = node_index[state.node_of(v)];
          if (n >= 0) nodes.push_back(n);
        }
      }
    }
  }
  for (auto& [name, nodes] : graph.boundary_nodes) {
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  }
  return graph;
}

}  // namespace fissure
