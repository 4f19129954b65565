#include "tests/support/block_checks.h"

#include <fmt/format.h>

#include "core/geometry/polygon_checks.h"

namespace fissure::testing {

double total_area(const std::vector<Polygon>& blocks) {
  double a = 0;
  for (const Polygon& p : blocks)
    for (int k = 0; k < p.n_loops(); ++k) a += signed_area(p.loop(k));
  return a;
}

std::vector<std::string> block_system_problems(const std::vector<Polygon>& blocks,
                                               double tolerance, size_t max_lines) {
  std::vector<std::string> lines;
  auto add = [&](std::string s) {
    if (lines.size() < max_lines) lines.push_back(std::move(s));
  };
  for (size_t b = 0; b < blocks.size(); ++b) {
    for (const PolygonProblem& p : check_polygon(blocks[b], tolerance))
      add(fmt::format("block {}: {}", b, p.what));
    for (int k = 0; k < blocks[b].n_loops(); ++k) {
      const double a = signed_area(blocks[b].loop(k));
      if ((k == 0) != (a > 0)) add(fmt::format("block {}: loop {} has signed area {}", b, k, a));
    }
  }
  for (const auto& [i, j] : find_overlapping_pairs(blocks, tolerance))
    add(fmt::format("blocks {} and {} overlap", i, j));
  return lines;
}

std::vector<std::string> fracture_graph_problems(const FractureGraph& graph,
                                                 const std::vector<Polygon>& blocks,
                                                 double tolerance, size_t max_lines) {
  std::vector<std::string> lines;
  auto add = [&](std::string s) {
    if (lines.size() < max_lines) lines.push_back(std::move(s));
  };
  const int nb = static_cast<int>(blocks.size());
  for (int s = 0; s < graph.n_segments(); ++s) {
    const FractureSegment& seg = graph.segments[s];
    if (seg.node_a < 0 || seg.node_a >= graph.n_nodes() || seg.node_b < 0 ||
        seg.node_b >= graph.n_nodes()) {
      add(fmt::format("segment {}: node out of range", s));
      continue;
    }
    if (graph.length(s) <= 0) add(fmt::format("segment {}: zero length", s));
    const Vec2 a = graph.nodes[seg.node_a], b = graph.nodes[seg.node_b];
    for (int side = 0; side < 2; ++side) {
      const BlockFace& f = side == 0 ? seg.left : seg.right;
      if (f.block < 0 || f.block >= nb) {
        add(fmt::format("segment {}: {} block {} out of range", s, side == 0 ? "left" : "right",
                        f.block));
        continue;
      }
      if (f.edge < 0) continue;
      const Polygon& p = blocks[f.block];
      if (f.edge >= p.n_vertices()) {
        add(fmt::format("segment {}: edge {} out of range", s, f.edge));
        continue;
      }
      // The left block runs a -> b along its boundary, the right block b -> a.
      const Vec2 from = p.vertices[f.edge], to = p.vertices[p.next(f.edge)];
      const Vec2 want_from = side == 0 ? a : b, want_to = side == 0 ? b : a;
      if ((from - want_from).norm() > tolerance || (to - want_to).norm() > tolerance)
        add(fmt::format("segment {}: {} face edge {} of block {} is not the segment", s,
                        side == 0 ? "left" : "right", f.edge, f.block));
    }
    if ((seg.left.edge < 0) != (seg.right.edge < 0))
      add(fmt::format("segment {}: only one side is a block edge", s));
    if (seg.left.edge < 0 && seg.left.block != seg.right.block)
      add(fmt::format("segment {}: an inner segment with two blocks", s));
  }
  return lines;
}

}  // namespace fissure::testing
