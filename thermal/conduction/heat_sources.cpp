#include "thermal/conduction/heat_sources.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "core/base/errors.h"
#include "core/geometry/polygon_checks.h"
#include "core/geometry/segment_predicates.h"

namespace fissure {

namespace thermal {

namespace {

/// The block strictly containing p, or -1.
int block_containing(const std::vector<Block>& blocks, const Vec2& p, double tol) {
  for (std::size_t b = 0; b < blocks.size(); ++b)
    if (locate_point(blocks[b].polygon, p, tol) > 0) return static_cast<int>(b);
  return -1;
}

/// Whether the segment a-b crosses an edge of the polygon.
bool crosses_boundary(const Polygon& poly, const Vec2& a, const Vec2& b, double tol) {
  for (int e = 0; e < poly.n_vertices(); ++e)
    if (segments_cross(a, b, poly.vertices[e], poly.vertices[poly.next(e)], tol)) return true;
  return false;
}

int nearest_node(const ThermalMesh& mesh, int block, const Vec2& p) {
  int best = -1;
  double d = std::numeric_limits<double>::infinity();
  for (int i = mesh.block_first_node[block]; i < mesh.block_first_node[block + 1]; ++i) {
    const double di = (mesh.nodes[i] - p).squaredNorm();
    if (di < d) d = di, best = i;
  }
  return best;
}

}  // namespace

std::vector<int> source_blocks(const std::vector<HeatSource>& sources,
                               const std::vector<Block>& blocks) {
  Box all;
  for (const Block& b : blocks) all.extend(bounding_box(b.polygon));
  const double tol = 1e-9 * std::max(all.size().maxCoeff(), 1e-300);
  std::vector<int> result;
  for (const HeatSource& s : sources) {
    int block = -1;
    for (const Vec2& p : s.points) {
      const int b = block_containing(blocks, p, tol);
      if (b < 0)
        throw SceneError(
            fmt::format("{}: found the point ({:g}, {:g}) outside the rock (in no block, "
                        "or in a hole, or on a block boundary); expected a source inside "
                        "one block",
                        s.path, p.x(), p.y()));
      if (block >= 0 && b != block)
        throw SceneError(
            fmt::format("{}: found points in blocks '{}' and '{}'; expected a source "
                        "inside one block",
                        s.path, blocks[block].name, blocks[b].name));
      block = b;
    }
    const std::size_t n = s.points.size();
    const std::size_t pieces = s.shape == HeatSource::Shape::Line ? 1 : n > 2 ? n : 0;
    for (std::size_t i = 0; i < pieces; ++i)
      if (crosses_boundary(blocks[block].polygon, s.points[i], s.points[(i + 1) % n], tol))
        throw SceneError(
            fmt::format("{}: found a source that crosses the boundary of block '{}'; "
                        "expected a source inside one block",
                        s.path, blocks[block].name));
    result.push_back(block);
  }
  return result;
}

std::vector<NodalWeights> source_weights(const std::vector<HeatSource>& sources,
                                         const std::vector<int>& source_block,
                                         const ThermalMesh& mesh) {
  std::vector<NodalWeights> weights(sources.size());
  for (std::size_t s = 0; s < sources.size(); ++s) {
    const HeatSource& src = sources[s];
    const int b = source_block[s];
    NodalWeights& w = weights[s];
    if (src.shape == HeatSource::Shape::Point) {
      w.emplace_back(nearest_node(mesh, b, src.points[0]), 1.0);
    } else if (src.shape == HeatSource::Shape::Line) {
      // The mesh edges along the line: its nodes sorted along it.
      const Vec2 a = src.points[0], d = src.points[1] - a;
      const double tol = 1e-9 * d.norm();
      std::vector<std::pair<double, int>> on;
      for (int i = mesh.block_first_node[b]; i < mesh.block_first_node[b + 1]; ++i)
        if (point_segment_distance(mesh.nodes[i], a, src.points[1]) <= tol)
          on.emplace_back(d.dot(mesh.nodes[i] - a) / d.squaredNorm(), i);
      std::sort(on.begin(), on.end());
      for (std::size_t k = 0; k + 1 < on.size(); ++k) {
        const double half = (on[k + 1].first - on[k].first) / 2;
        w.emplace_back(on[k].second, half);
        w.emplace_back(on[k + 1].second, half);
      }
    } else {
      // Triangles inside the outline (their centroid is): A_t / 3 per node.
      Polygon outline(src.points);
      double total = 0;
      for (int t = 0; t < mesh.n_triangles(); ++t) {
        if (mesh.triangle_block[t] != b) continue;
        const auto& tri = mesh.triangles[t];
        const Vec2 &p0 = mesh.nodes[tri[0]], &p1 = mesh.nodes[tri[1]], &p2 = mesh.nodes[tri[2]];
        if (locate_point(outline, (p0 + p1 + p2) / 3, 0) <= 0) continue;
        const double area = mesh.triangle_area[t];
        for (int k = 0; k < 3; ++k) w.emplace_back(tri[k], area / 3);
        total += area;
      }
      for (auto& [node, weight] : w) weight /= total;
    }
  }
  return weights;
}

}  // namespace thermal
}  // namespace fissure
