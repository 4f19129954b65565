// Step 3 of block cutting (block_cutter.h): merging to the tolerance.
//
// Faces. The width of a group of faces is w = 2 A / P (area over half the
// perimeter: the width of a long strip, the radius of a disc). A group with
// w < tol is a sliver, from nearly parallel or nearly coincident fractures or
// a crossing at a tiny angle; it is merged into the neighbour group across
// the fracture they share most of. Merging never crosses the rock boundary,
// so the union of the blocks stays exactly the rock. Rounds repeat until no
// sliver is left that has a neighbour.
//
// Vertices. An edge shorter than tol joins its two ends into one node, taking
// the position of one of them (the representative): a vertex where the rock
// boundary bends (a corner, or a point on two boundary segments) never moves;
// a vertex on one boundary segment moves only along it; otherwise the vertex
// with the most edges wins (so a fracture that overshoots a crossing by a
// hair ends exactly at the crossing). Clusters never span more than tol from
// their representative. Edges are taken shortest first.
#include <algorithm>
#include <array>
#include <iterator>
#include <limits>
#include <numeric>

#include "rockmass/cut_state.h"

namespace fissure {

int best_neighbour(CutState& state, int group, const std::vector<int>& group_halfedges) {
  const PlanarSubdivision& sub = state.sub;
  std::vector<std::pair<int, double>> shared;  // (neighbour group, length)
  for (int h : group_halfedges) {
    const int g = state.group(sub.face[h ^ 1]);
    if (g < 0 || g == group) continue;
    shared.emplace_back(g, sub.length(h));
  }
  std::sort(shared.begin(), shared.end());
  int best = -1;
  double best_length = -1;
  for (size_t i = 0; i < shared.size();) {
    double length = 0;
    size_t j = i;
    for (; j < shared.size() && shared[j].first == shared[i].first; ++j) length += shared[j].second;
    if (length > best_length) {
      best_length = length;
      best = shared[i].first;
    }
    i = j;
  }
  return best;
}

void merge_slivers(CutState& state) {
  const PlanarSubdivision& sub = state.sub;
  const int n_faces = sub.n_faces;

  // Face areas (all half-edges: dangling edges cancel, holes count negative).
  std::vector<double> face_area(n_faces, 0.0);
  for (int h = 0; h < sub.n_halfedges(); ++h)
    if (state.rock[sub.face[h]])
      face_area[sub.face[h]] +=
          0.5 * cross(sub.vertices[sub.origin[h]], sub.vertices[sub.target(h)]);

  std::vector<double> area(n_faces), perimeter(n_faces);
  std::vector<int> boundary_start(n_faces + 1), boundary;
  for (;;) {
    // 1. Group areas and perimeters, and each group's boundary half-edges.
    std::fill(area.begin(), area.end(), 0.0);
    std::fill(perimeter.begin(), perimeter.end(), 0.0);
    std::fill(boundary_start.begin(), boundary_start.end(), 0);
    for (int f = 0; f < n_faces; ++f)
      if (state.rock[f]) area[state.groups.find(f)] += face_area[f];
    for (int h = 0; h < sub.n_halfedges(); ++h) {
      const int g = state.group(sub.face[h]);
      if (g < 0 || g == state.group(sub.face[h ^ 1])) continue;
      perimeter[g] += sub.length(h);
      ++boundary_start[g + 1];
    }
    std::vector<std::pair<double, int>> slivers;  // (width, group)
    for (int g = 0; g < n_faces; ++g)
      if (state.rock[g] && state.groups.find(g) == g && perimeter[g] > 0 &&
          2 * area[g] < state.tol * perimeter[g])
        slivers.emplace_back(2 * area[g] / perimeter[g], g);
    if (slivers.empty()) return;
    for (int g = 0; g < n_faces; ++g) boundary_start[g + 1] += boundary_start[g];
    boundary.resize(boundary_start.back());
    std::vector<int> fill(boundary_start.begin(), boundary_start.end() - 1);
    for (int h = 0; h < sub.n_halfedges(); ++h) {
      const int g = state.group(sub.face[h]);
      if (g >= 0 && g != state.group(sub.face[h ^ 1])) boundary[fill[g]++] = h;
    }

    // 2. Thinnest first; a group merged this round waits for the next one
    // (its width has changed).
    std::sort(slivers.begin(), slivers.end());
    std::vector<char> touched(n_faces, 0);
    int merged = 0;
    std::vector<int> halfedges;
    for (const auto& [width, g] : slivers) {
      if (touched[g]) continue;
      halfedges.assign(boundary.begin() + boundary_start[g],
                       boundary.begin() + boundary_start[g + 1]);
      const int n = best_neighbour(state, g, halfedges);
      if (n < 0 || touched[n]) continue;
      touched[g] = touched[n] = 1;
      const int root = state.groups.unite(g, n);
      touched[root] = 1;
      ++merged;
    }
    state.statistics.slivers_merged += merged;
    if (merged == 0) return;
  }
}

namespace {

struct Cluster {
  int fixed = -1;           ///< a vertex that must not move, or -1
  std::vector<int> curves;  ///< boundary segments its vertices lie on, sorted
  int rep = -1;             ///< representative vertex
  Box box;                  ///< of the member vertices
};

}  // namespace

void merge_vertices(CutState& state) {
  const PlanarSubdivision& sub = state.sub;
  const int nv = static_cast<int>(sub.vertices.size());

  // 1. Per vertex: boundary segments through it, and edges next to rock.
  std::vector<std::vector<int>> curves(nv);
  std::vector<int> degree(nv, 0);
  std::vector<int> short_edges;
  for (int e = 0; e < sub.n_edges(); ++e) {
    const int h = 2 * e;
    if (!state.rock[sub.face[h]] && !state.rock[sub.face[h ^ 1]]) continue;
    for (int v : {sub.origin[h], sub.target(h)}) {
      ++degree[v];
      for (int c : sub.edge_curves(e))
        if (c < state.n_boundary &&
            std::find(curves[v].begin(), curves[v].end(), c) == curves[v].end())
          curves[v].push_back(c);
    }
    if (sub.length(h) < state.tol) short_edges.push_back(e);
  }
  std::sort(short_edges.begin(), short_edges.end(),
            [&](int a, int b) { return sub.length(2 * a) < sub.length(2 * b); });

  // 2. Clusters, shortest edges first.
  std::vector<Cluster> clusters(nv);
  for (int v = 0; v < nv; ++v) {
    std::sort(curves[v].begin(), curves[v].end());
    clusters[v].fixed = curves[v].size() >= 2 ? v : -1;
    clusters[v].curves = curves[v];
    clusters[v].rep = v;
    clusters[v].box.extend(sub.vertices[v]);
  }
  UnionFind sets(nv);
  for (int e : short_edges) {
    const int a = sets.find(sub.origin[2 * e]), b = sets.find(sub.target(2 * e));
    if (a == b) continue;
    const Cluster &ca = clusters[a], &cb = clusters[b];
    if (ca.fixed >= 0 && cb.fixed >= 0) continue;
    Cluster merged;
    merged.fixed = ca.fixed >= 0 ? ca.fixed : cb.fixed;
    std::set_union(ca.curves.begin(), ca.curves.end(), cb.curves.begin(), cb.curves.end(),
                   std::back_inserter(merged.curves));
    if (merged.fixed >= 0) {
      // Vertices may slide into a corner only along the corner's own segments.
      const std::vector<int>& allowed = curves[merged.fixed];
      if (!std::includes(allowed.begin(), allowed.end(), merged.curves.begin(),
                         merged.curves.end()))
        continue;
      merged.rep = merged.fixed;
    } else if (merged.curves.size() > 1) {
      continue;  // two boundary segments: merging would move the boundary
    } else if (!merged.curves.empty()) {
      merged.rep = !ca.curves.empty() ? ca.rep : cb.rep;
    } else {
      merged.rep = degree[ca.rep] >= degree[cb.rep] ? ca.rep : cb.rep;
    }
    merged.box = ca.box;
    merged.box.extend(cb.box);
    const Vec2 p = sub.vertices[merged.rep];
    const Vec2 far = (merged.box.lo - p).cwiseAbs().cwiseMax((merged.box.hi - p).cwiseAbs());
    if (far.norm() > state.tol) continue;
    sets.attach(a, b);
    clusters[a] = std::move(merged);
    state.statistics.vertices_merged += 1;
  }
  state.representative.resize(nv);
  for (int v = 0; v < nv; ++v) state.representative[v] = clusters[sets.find(v)].rep;
}

}  // namespace fissure
