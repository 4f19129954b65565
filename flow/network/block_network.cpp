#include "flow/network/block_network.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/geometry/box_grid.h"
#include "core/geometry/segment_predicates.h"
#include "core/geometry/union_find.h"

namespace fissure::flow {

namespace {

/// One overlap of two touching edges, along the edge of `left` (a -> b runs
/// along that edge, so the left block is on the left).
struct Piece {
  Vec2 a, b;
  BlockFace left, right;
  int joint;
};

/// Overlap of edge p0 -> p1 (block i) with edge q0 -> q1 (block j) when they
/// are collinear within tol and run in opposite directions.
bool overlap(const Vec2& p0, const Vec2& p1, const Vec2& q0, const Vec2& q1, double tol, Vec2& a,
             Vec2& b) {
  const Vec2 d = p1 - p0;
  const double len = d.norm();
  if (len <= tol || (q1 - q0).dot(d) >= 0) return false;
  if (std::abs(cross(d, q0 - p0)) > tol * len || std::abs(cross(d, q1 - p0)) > tol * len)
    return false;
  const double s0 = d.dot(q1 - p0) / (len * len), s1 = d.dot(q0 - p0) / (len * len);
  const double lo = std::max(0.0, s0), hi = std::min(1.0, s1);
  if ((hi - lo) * len <= tol) return false;
  a = p0 + lo * d;
  b = p0 + hi * d;
  return true;
}

}  // namespace

double block_tolerance(const std::vector<Block>& blocks) {
  Box box;
  for (const Block& b : blocks) box.extend(bounding_box(b.polygon));
  return box.empty() ? 1e-9 : 1e-9 * std::max(box.size().x(), box.size().y());
}

FractureGraph network_from_blocks(const std::vector<Block>& blocks, double e0, double tol) {
  const int n_blocks = static_cast<int>(blocks.size());
  // 1. Overlapping edge pairs of block pairs whose boxes touch.
  std::vector<Box> boxes(n_blocks);
  Box all;
  for (int i = 0; i < n_blocks; ++i) {
    boxes[i] = bounding_box(blocks[i].polygon);
    all.extend(boxes[i]);
    boxes[i].lo -= Vec2(tol, tol);
    boxes[i].hi += Vec2(tol, tol);
  }
  std::vector<Piece> pieces;
  BoxGrid grid;
  grid.build(boxes);
  grid.for_each_pair([&](int i, int j) {
    const Polygon& pi = blocks[i].polygon;
    const Polygon& pj = blocks[j].polygon;
    for (int e = 0; e < pi.n_vertices(); ++e) {
      const Vec2 p0 = pi.vertices[e], p1 = pi.vertices[pi.next(e)];
      for (int f = 0; f < pj.n_vertices(); ++f) {
        Vec2 a, b;
        if (!overlap(p0, p1, pj.vertices[f], pj.vertices[pj.next(f)], tol, a, b)) continue;
        const int joint = blocks[i].edge_joint.empty() ? -1 : blocks[i].edge_joint[e];
        pieces.push_back({a, b, BlockFace{i, e}, BlockFace{j, f}, joint});
      }
    }
  });

  // 2. Nodes: piece ends, merged within tol (union-find over a sorted sweep).
  std::vector<Vec2> points;
  for (const Piece& p : pieces) points.push_back(p.a), points.push_back(p.b);
  std::vector<int> order(points.size());
  std::iota(order.begin(), order.end(), 0);
  UnionFind sets(static_cast<int>(points.size()));
  std::sort(order.begin(), order.end(),
            [&](int x, int y) { return points[x].x() < points[y].x(); });
  for (std::size_t u = 0; u < order.size(); ++u)
    for (std::size_t w = u + 1;
         w < order.size() && points[order[w]].x() - points[order[u]].x() <= tol; ++w)
      if ((points[order[w]] - points[order[u]]).norm() <= tol)
        sets.unite_to_smallest(order[u], order[w]);  // a node sits at its first point
  FractureGraph g;
  std::vector<int> node_of(points.size(), -1), node_of_root(points.size(), -1);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const int r = sets.find(static_cast<int>(k));
    if (node_of_root[r] < 0) {
      node_of_root[r] = g.n_nodes();
      g.nodes.push_back(points[r]);
    }
    node_of[k] = node_of_root[r];
  }

  // 3. Segments, split at nodes that lie inside a piece (T-junctions).
  std::vector<Box> node_boxes(g.n_nodes());
  for (int v = 0; v < g.n_nodes(); ++v) {
    node_boxes[v].extend(g.nodes[v]);
    node_boxes[v].lo -= Vec2(tol, tol);
    node_boxes[v].hi += Vec2(tol, tol);
  }
  BoxGrid node_grid;
  node_grid.build(node_boxes);
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const Piece& p = pieces[k];
    const int na = node_of[2 * k], nb = node_of[2 * k + 1];
    Box query;
    query.extend(p.a);
    query.extend(p.b);
    std::vector<std::pair<double, int>> inside;
    const Vec2 d = p.b - p.a;
    node_grid.for_each_overlapping(query, [&](int v) {
      if (v == na || v == nb) return;
      if (point_segment_distance(g.nodes[v], p.a, p.b) > tol) return;
      inside.emplace_back(d.dot(g.nodes[v] - p.a) / d.squaredNorm(), v);
    });
    std::sort(inside.begin(), inside.end());
    int previous = na;
    inside.emplace_back(1.0, nb);
    for (const auto& [t, v] : inside) {
      FractureSegment s;
      s.node_a = previous;
      s.node_b = v;
      s.aperture = e0;
      s.joint_set = p.joint;
      s.left = p.left;
      s.right = p.right;
      g.segments.push_back(s);
      previous = v;
    }
  }

  // 4. Named boundaries.
  g.add_box_sides(all.lo, all.hi, tol);
  auto& exterior = g.boundary_nodes["exterior"];
  // Exterior: a node is on the outer surface when some block edge through it
  // is not covered by pieces right next to it. Test points tol * 10 to either
  // side of the node along each edge through it.
  std::vector<std::vector<std::pair<double, double>>> covered;  // per (block, edge): [s0, s1]
  std::vector<int> first_edge(n_blocks + 1, 0);
  for (int b = 0; b < n_blocks; ++b)
    first_edge[b + 1] = first_edge[b] + blocks[b].polygon.n_vertices();
  covered.resize(first_edge[n_blocks]);
  auto add_cover = [&](const BlockFace& f, const Vec2& a, const Vec2& b) {
    const Polygon& poly = blocks[f.block].polygon;
    const Vec2 p0 = poly.vertices[f.edge], d = poly.vertices[poly.next(f.edge)] - p0;
    double s0 = d.dot(a - p0) / d.squaredNorm(), s1 = d.dot(b - p0) / d.squaredNorm();
    if (s0 > s1) std::swap(s0, s1);
    covered[first_edge[f.block] + f.edge].emplace_back(s0, s1);
  };
  for (const Piece& p : pieces) add_cover(p.left, p.a, p.b), add_cover(p.right, p.a, p.b);
  for (int v = 0; v < g.n_nodes(); ++v) {
    bool outside = false;
    for (int b = 0; b < n_blocks && !outside; ++b) {
      if (!boxes[b].overlaps(Box{g.nodes[v], g.nodes[v]})) continue;
      const Polygon& poly = blocks[b].polygon;
      for (int e = 0; e < poly.n_vertices() && !outside; ++e) {
        const Vec2 p0 = poly.vertices[e], d = poly.vertices[poly.next(e)] - p0;
        if (point_segment_distance(g.nodes[v], p0, p0 + d) > tol) continue;
        const double s = d.dot(g.nodes[v] - p0) / d.squaredNorm();
        const double eps = 10 * tol / d.norm();
        for (const double probe : {s - eps, s + eps}) {
          if (probe < 0 || probe > 1) continue;
          bool hit = false;
          for (const auto& [s0, s1] : covered[first_edge[b] + e])
            hit = hit || (probe >= s0 && probe <= s1);
          if (!hit) outside = true;
        }
      }
    }
    if (outside) exterior.push_back(v);
  }
  return g;
}

}  // namespace fissure::flow
