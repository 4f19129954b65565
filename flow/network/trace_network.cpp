#include "flow/network/trace_network.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "core/geometry/box_grid.h"
#include "core/geometry/union_find.h"

namespace fissure::flow {

namespace {

struct Crossing {
  double t;  ///< parameter along the trace
  int node;  ///< candidate node
};

/// Merges candidate nodes closer than tol: hash grid of cell 2 tol, 3x3 look-up.
std::vector<int> merge_close(const std::vector<Vec2>& points, double tol, int& merged) {
  const int n = static_cast<int>(points.size());
  UnionFind sets(n);
  const double cell = 2 * tol;
  auto key = [](long long x, long long y) { return (x * 73856093LL) ^ (y * 19349663LL); };
  std::unordered_multimap<long long, int> grid;
  grid.reserve(2 * n);
  merged = 0;
  for (int i = 0; i < n; ++i) {
    const long long cx = static_cast<long long>(std::floor(points[i].x() / cell));
    const long long cy = static_cast<long long>(std::floor(points[i].y() / cell));
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy) {
        const auto range = grid.equal_range(key(cx + dx, cy + dy));
        for (auto it = range.first; it != range.second; ++it) {
          const int j = it->second;
          if ((points[i] - points[j]).norm() > tol) continue;
          if (sets.unite_to_smallest(i, j)) ++merged;
        }
      }
    grid.emplace(key(cx, cy), i);
  }
  std::vector<int> root(n);
  for (int i = 0; i < n; ++i) root[i] = sets.find(i);
  return root;
}

}  // namespace

FractureGraph build_trace_network(std::span<const Trace> traces, const Box& domain, double tol,
                                  TraceNetworkStatistics* statistics) {
  TraceNetworkStatistics stats;
  // 1. Clip.
  std::vector<Trace> clipped;
  clipped.reserve(traces.size());
  for (const Trace& t : traces) {
    Trace c = t;
    if (!clip_to_box(c.a, c.b, domain) || (c.b - c.a).norm() <= tol) {
      ++stats.clipped_away;
      continue;
    }
    clipped.push_back(c);
  }
  const int n_traces = static_cast<int>(clipped.size());

  // 2. Candidate nodes: trace ends, then intersections (broad phase on boxes).
  std::vector<Vec2> points;
  std::vector<std::vector<Crossing>> on_trace(n_traces);
  for (int i = 0; i < n_traces; ++i) {
    on_trace[i].push_back({0.0, static_cast<int>(points.size())});
    points.push_back(clipped[i].a);
    on_trace[i].push_back({1.0, static_cast<int>(points.size())});
    points.push_back(clipped[i].b);
  }
  std::vector<Box> boxes(n_traces);
  for (int i = 0; i < n_traces; ++i) {
    boxes[i].extend(clipped[i].a);
    boxes[i].extend(clipped[i].b);
    boxes[i].lo -= Vec2(tol, tol);
    boxes[i].hi += Vec2(tol, tol);
  }
  BoxGrid grid;
  grid.build(boxes);
  grid.for_each_pair([&](int i, int j) {
    const Vec2 ai = clipped[i].a, di = clipped[i].b - ai;
    const Vec2 aj = clipped[j].a, dj = clipped[j].b - aj;
    const double li = di.norm(), lj = dj.norm();
    const double denom = cross(di, dj);
    if (std::abs(denom) <= 1e-12 * li * lj) {
      // Parallel: collinear overlaps are not joined (rare in a DFN; counted).
      if (std::abs(cross(di, aj - ai)) <= tol * li) {
        const double s0 = di.dot(aj - ai) / (li * li), s1 = di.dot(clipped[j].b - ai) / (li * li);
        if (std::max(s0, s1) > tol / li && std::min(s0, s1) < 1 - tol / li)
          ++stats.collinear_overlaps;
      }
      return;
    }
    const Vec2 r = aj - ai;
    double t = cross(r, dj) / denom, u = cross(r, di) / denom;
    if (t < -tol / li || t > 1 + tol / li || u < -tol / lj || u > 1 + tol / lj) return;
    t = std::clamp(t, 0.0, 1.0);
    u = std::clamp(u, 0.0, 1.0);
    const int node = static_cast<int>(points.size());
    points.push_back(ai + t * di);
    on_trace[i].push_back({t, node});
    on_trace[j].push_back({u, node});
    ++stats.intersections;
  });

  // 3. One node per point (within tol), numbered in order of first use.
  const std::vector<int> root = merge_close(points, tol, stats.merged_nodes);
  FractureGraph g;
  std::vector<int> node_of_root(points.size(), -1);
  auto node_of = [&](int candidate) {
    const int r = root[candidate];
    if (node_of_root[r] < 0) {
      node_of_root[r] = g.n_nodes();
      g.nodes.push_back(points[r]);
    }
    return node_of_root[r];
  };

  // 4. Segments along each trace between consecutive distinct nodes.
  for (int i = 0; i < n_traces; ++i) {
    auto& list = on_trace[i];
    std::sort(list.begin(), list.end(),
              [](const Crossing& x, const Crossing& y) { return x.t < y.t; });
    int previous = -1;
    for (const Crossing& c : list) {
      const int v = node_of(c.node);
      if (previous >= 0 && v != previous) {
        FractureSegment s;
        s.node_a = previous;
        s.node_b = v;
        s.aperture = clipped[i].aperture;
        s.fracture = clipped[i].fracture;
        s.joint_set = clipped[i].joint_set;
        g.segments.push_back(s);
      }
      previous = v;
    }
  }

  // 5. Named boundaries: nodes on the box's sides.
  g.add_box_sides(domain.lo, domain.hi, tol);
  if (statistics) *statistics = stats;
  return g;
}

}  // namespace fissure::flow
