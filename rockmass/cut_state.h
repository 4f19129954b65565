// Internal to the block cutter (block_cutter.h): the state that its steps
// share, and the steps after the arrangement.
#pragma once

#include <string>
#include <vector>

#include "core/geometry/union_find.h"
#include "rockmass/block_cutter.h"
#include "rockmass/fracture_graph.h"
#include "rockmass/planar_subdivision.h"

namespace fissure {

struct CutState {
  PlanarSubdivision sub;
  /// Input segments [0, n_boundary) are boundary segments, the others traces
  /// (segment n_boundary + t is trace traces[t] of the cut input).
  int n_boundary = 0;
  std::vector<int> trace_of_segment;  ///< per trace segment: index into the input traces
  double tol = 0;                     ///< merge tolerance
  double check_tol = 0;               ///< check_polygon tolerance

  std::vector<char> rock;  ///< per face
  /// Half-edges of each face: face f has face_halfedges[face_start[f] ..
  /// face_start[f + 1]).
  std::vector<int> face_start, face_halfedges;
  UnionFind groups;  ///< faces merged into one block
  /// Per vertex: the vertex whose position it takes after merging (itself
  /// when not merged).
  std::vector<int> representative;

  CutStatistics statistics;

  int group(int face) { return rock[face] ? groups.find(face) : -1; }
  bool boundary_edge(int e) const {
    const std::span<const int> c = sub.edge_curves(e);
    return !c.empty() && c.front() < n_boundary;  // curves are sorted
  }
  /// Smallest trace on edge e, or -1.
  int trace_of_edge(int e) const {
    for (int c : sub.edge_curves(e))
      if (c >= n_boundary) return trace_of_segment[c - n_boundary];
    return -1;
  }
  /// Block edge source (CutBlock::edge_source) of edge e.
  int edge_source(int e) const {
    const std::span<const int> c = sub.edge_curves(e);
    if (!c.empty() && c.front() < n_boundary) return -1 - c.front();
    return trace_of_edge(e);
  }
  int node_of(int v) const { return representative[v]; }
};

/// A block as extracted: its polygon and, per polygon vertex, the half-edge
/// that leaves it along the block's boundary.
struct ExtractedBlock {
  Polygon polygon;
  std::vector<int> halfedge;
  int group = -1;
  Vec2 centroid = Vec2::Zero();
};

// Steps, in order (block_cutter.cpp runs them).
void merge_slivers(CutState& state);                          ///< subdivision_merging.cpp
void merge_vertices(CutState& state);                         ///< subdivision_merging.cpp
std::vector<ExtractedBlock> extract_blocks(CutState& state);  ///< block_extraction.cpp
/// `block_of_group` maps a face group to its block index (-1: none).
FractureGraph build_fracture_graph(CutState& state, const std::vector<ExtractedBlock>& blocks,
                                   const std::vector<int>& block_of_group,
                                   const std::vector<FractureTrace>& traces,
                                   const std::vector<std::vector<std::string>>& boundary_names);

/// The neighbour group with which `group` shares the longest fracture (edges
/// between two rock faces), or -1 (subdivision_merging.cpp).
int best_neighbour(CutState& state, int group, const std::vector<int>& group_halfedges);

}  // namespace fissure
