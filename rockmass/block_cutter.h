// Block cutting (Shi's DC step; docs/rock-mass.md section 4): the
// rock domain minus its excavations, cut by every fracture trace, becomes a
// set of closed blocks plus the fracture graph that flow will use.
//
// Steps (each in its own file):
//  1. input (block_cutter.cpp): traces are cut off one domain extent beyond
//     its bounding box, those shorter than the merge tolerance or missing the
//     domain are dropped; a trace end that stops short of another
//     trace or of the boundary by at most the tolerance is extended across it
//     (a T-junction made exact);
//  2. the exact arrangement of boundary edges and traces (CGAL, exact
//     constructions; segment_arrangement.cpp), exported as a planar
//     subdivision; its faces inside the domain and outside every excavation
//     are rock (block_cutter.cpp);
//  3. merging to the tolerance tol (subdivision_merging.cpp): faces thinner
//     than tol (2 area / perimeter < tol) are merged into the neighbour with
//     which they share the longest fracture; then vertices joined by an edge
//     shorter than tol are merged into one, never moving the rock boundary;
//  4. blocks (block_extraction.cpp): each group of merged faces becomes a
//     polygon whose boundary skips the fracture pieces inside it; a group
//     that is not a valid simple polygon (check_polygon at the geometry
//     tolerance) or is thinner than tol / 2 is merged into a neighbour too;
//  5. the fracture graph (fracture_graph_builder.cpp).
// Merging joins faces across fractures only, so the blocks always cover the
// rock exactly; the fracture pieces between merged faces stay in the graph as
// segments inside a block. Cost: O((n + k) log n) for n traces with k
// crossings (a sweep line and grids; no all-pairs loop).
#pragma once

#include <string>
#include <vector>

#include "core/geometry/polygon.h"
#include "rockmass/fracture_graph.h"
#include "rockmass/fracture_trace.h"
#include "rockmass/rock_mass_spec.h"

namespace fissure {

struct CutInput {
  std::vector<Vec2> domain;  ///< simple loop, either orientation
  std::vector<ExcavationSpec> excavations;
  std::vector<FractureTrace> traces;
  double merge_tolerance = 0;  ///< m, > 0
  /// Tolerance of check_polygon for the blocks (m); 0: 1e-9 x domain extent,
  /// the scene's geometry tolerance.
  double check_tolerance = 0;
};

struct CutBlock {
  Polygon polygon;  ///< outer loop counter-clockwise, holes clockwise
  /// Per vertex v, where the edge v -> next(v) comes from: a trace index
  /// (>= 0), or -1 - b for boundary segment b (CutResult::boundary_names).
  std::vector<int> edge_source;
};

struct CutStatistics {
  int traces_used = 0;      ///< traces that contribute at least one graph segment or block edge
  int traces_dropped = 0;   ///< shorter than the tolerance, or missing the domain
  int traces_extended = 0;  ///< ends extended onto a trace or the boundary
  int slivers_merged = 0;   ///< faces merged for being thinner than tol
  int vertices_merged = 0;  ///< vertices merged into a neighbour
  int invalid_merged = 0;   ///< groups merged for not being valid polygons
  /// Wall time of each step (s): 1 input, 2 arrangement and rock faces, 3
  /// merging, 4 blocks, 5 fracture graph and block edges (the block_cutting
  /// benchmark reports them).
  double prepare_seconds = 0, arrange_seconds = 0, merge_seconds = 0, extract_seconds = 0,
         graph_seconds = 0;
};

struct CutResult {
  std::vector<CutBlock> blocks;  ///< ordered by centroid (y, then x)
  FractureGraph graph;           ///< block indices into `blocks`
  /// Boundary segments: the domain's edges (edge i runs from domain vertex i,
  /// counter-clockwise), then each excavation's edges. Each has its boundary
  /// names: "left", "right", "bottom", "top" for domain sides
  /// (domain_sides.h), the excavation's name for its edges.
  std::vector<std::vector<std::string>> boundary_names;
  CutStatistics statistics;
};

/// Cuts the rock. Throws GeometryError when the rock is empty or a group of
/// faces cannot be made a valid polygon (which merging prevents for valid
/// input).
CutResult cut_blocks(const CutInput& input);

}  // namespace fissure
