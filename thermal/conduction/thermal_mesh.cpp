#include "thermal/conduction/thermal_mesh.h"

#include <fmt/format.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <unordered_map>

#include "core/base/errors.h"
#include "core/geometry/box_grid.h"
#include "core/geometry/edge_division.h"
#include "core/geometry/interior_point.h"
#include "core/geometry/polygon_mesher.h"
#include "core/geometry/segment_predicates.h"
#include "core/scene/scene_section.h"

namespace fissure::thermal {

namespace {

double distance_to_source(const HeatSource& s, const Vec2& x) {
  switch (s.shape) {
    case HeatSource::Shape::Point:
      return (x - s.points[0]).norm();
    case HeatSource::Shape::Line:
      return point_segment_distance(x, s.points[0], s.points[1]);
    case HeatSource::Shape::Area: {
      double d = std::numeric_limits<double>::infinity();
      bool inside = false;
      const std::size_t n = s.points.size();
      for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        const Vec2 &a = s.points[i], &b = s.points[j];
        d = std::min(d, point_segment_distance(x, a, b));
        if ((a.y() > x.y()) != (b.y() > x.y()) &&
            x.x() < (b.x() - a.x()) * (x.y() - a.y()) / (b.y() - a.y()) + a.x())
          inside = !inside;
      }
      return inside ? 0.0 : d;
    }
  }
  return 0;
}

struct PointHash {
  std::size_t operator()(const std::array<double, 4>& k) const {
    std::size_t h = 1469598103934665603ull;
    for (double v : k) {
      std::uint64_t bits;
      std::memcpy(&bits, &v, sizeof bits);
      h = (h ^ bits) * 1099511628211ull;
    }
    return h;
  }
};

/// Vertices of different blocks closer than tol take the coordinates of the
/// one in the lowest block (so that pieces match to the bit); returns the
/// blocks' loops, snapped.
std::vector<Polygon> snapped_polygons(const std::vector<Block>& blocks,
                                      const std::vector<Box>& boxes, const BoxGrid& grid,
                                      double tol) {
  std::vector<Polygon> polygons;
  polygons.reserve(blocks.size());
  for (const Block& b : blocks) polygons.push_back(b.polygon);
  grid.for_each_pair([&](int i, int j) {
    if (i > j) std::swap(i, j);
    for (Vec2& v : polygons[j].vertices)
      for (const Vec2& u : polygons[i].vertices)
        if ((v - u).norm() <= tol) v = u;
  });
  (void)boxes;
  return polygons;
}

}  // namespace

SizeField::SizeField(const ThermalControls& c, double extent)
    : h_(c.element_size > 0 ? c.element_size : extent / 20),
      h_source_(c.source_element_size > 0 ? std::min(c.source_element_size, h_) : h_ / 4),
      grading_(c.size_grading),
      sources_(c.sources) {
  if (sources_.empty()) h_source_ = h_;
}

double SizeField::operator()(const Vec2& x) const {
  double h = h_;
  for (const HeatSource& s : sources_)
    h = std::min(h, h_source_ + grading_ * distance_to_source(s, x));
  return h;
}

double SizeField::estimate_elements(const std::vector<Block>& blocks) const {
  const double c = kMeshedAreaPerTriangle;
  // Per block: its area at the global size, and a triangle for each
  // boundary node (ceil(length / h) per edge, and the vertices of other
  // blocks that split its edges, about one per vertex): blocks smaller
  // than h are meshed with their boundary nodes only.
  double n = 0;
  for (const Block& b : blocks) {
    double perimeter = 0;
    for (int v = 0; v < b.polygon.n_vertices(); ++v)
      perimeter += (b.polygon.vertices[b.polygon.next(v)] - b.polygon.vertices[v]).norm();
    n += std::abs(b.section.area) / (c * h_ * h_) + perimeter / h_ + 2 * b.polygon.n_vertices();
  }
  if (h_source_ >= h_) return n;
  // The refined zones around the sources (docs/thermal.md 2).
  const double hs = h_source_;
  const double disc = refined_point_triangles(h_, hs, grading_);
  const double strip_per_length = refined_line_triangles_per_length(h_, hs, grading_);
  for (const HeatSource& s : sources_) {
    n += disc;
    double perimeter = 0;
    for (std::size_t i = 0; i + 1 < s.points.size(); ++i)
      perimeter += (s.points[i + 1] - s.points[i]).norm();
    if (s.shape == HeatSource::Shape::Area) {
      perimeter += (s.points.front() - s.points.back()).norm();
      n += std::abs(signed_area(s.points)) / (c * hs * hs);
    }
    n += strip_per_length * perimeter;
  }
  return n;
}

ThermalMesh::Place ThermalMesh::locate(const Vec2& p, int block) const {
  Place place;
  double best = -std::numeric_limits<double>::infinity();
  for (int t = 0; t < n_triangles(); ++t) {
    if (block >= 0 && triangle_block[t] != block) continue;
    const auto& tri = triangles[t];
    const Vec2 &p0 = nodes[tri[0]], &p1 = nodes[tri[1]], &p2 = nodes[tri[2]];
    Eigen::Matrix2d j;
    j << (p1 - p0), (p2 - p0);
    const Vec2 st = j.inverse() * (p - p0);
    const Eigen::Vector3d w(1 - st.x() - st.y(), st.x(), st.y());
    if (w.minCoeff() > best) {
      best = w.minCoeff();
      place = {t, w};
    }
  }
  return place;
}

const std::vector<int>* ThermalMesh::boundary(const std::string& name) const {
  for (const auto& [n, edges] : boundaries)
    if (n == name) return &edges;
  return nullptr;
}

ThermalMesh build_thermal_mesh(const std::vector<Block>& blocks, const SizeField& size,
                               const std::vector<HeatSource>& sources,
                               const std::vector<int>& source_block,
                               const std::vector<NamedWall>& walls) {
  const int n_blocks = static_cast<int>(blocks.size());
  Box all;
  std::vector<Box> boxes;
  for (const Block& b : blocks) {
    boxes.push_back(bounding_box(b.polygon));
    all.extend(boxes.back());
  }
  const double tol = kRelativeGeometryTolerance * std::max(all.size().maxCoeff(), 1e-300);
  for (Box& b : boxes) b.lo -= Vec2(tol, tol), b.hi += Vec2(tol, tol);
  BoxGrid grid;
  grid.build(boxes);
  const std::vector<Polygon> polygons = snapped_polygons(blocks, boxes, grid, tol);

  // 1. T-junctions: vertices of other blocks inside an edge split it.
  std::vector<std::vector<std::vector<std::pair<double, Vec2>>>> splits(n_blocks);
  for (int b = 0; b < n_blocks; ++b) splits[b].resize(polygons[b].n_vertices());
  auto add_splits = [&](int b, int other) {
    const Polygon& p = polygons[b];
    for (int e = 0; e < p.n_vertices(); ++e) {
      const Vec2 a = p.vertices[e], c = p.vertices[p.next(e)];
      const Vec2 before = p.vertices[p.prev(e)], after = p.vertices[p.next(p.next(e))];
      const Vec2 d = c - a;
      for (const Vec2& v : polygons[other].vertices) {
        if (v == a || v == c || point_segment_distance(v, a, c) > tol) continue;
        // Near the edge and the one before or after: at the corner, not a
        // T-junction (blocks that moved leave a neighbour's corner a
        // round-off from ours; split into both edges it would make a
        // zig-zag the mesher sees as crossing constraints).
        if (point_segment_distance(v, before, a) <= tol ||
            point_segment_distance(v, c, after) <= tol)
          continue;
        splits[b][e].emplace_back(d.dot(v - a) / d.squaredNorm(), v);
      }
    }
  };
  grid.for_each_pair([&](int i, int j) {
    add_splits(i, j);
    add_splits(j, i);
  });

  // 2. Mesh each block with its split boundary.
  const SizeFunction size_of = std::cref(size);
  ThermalMesh mesh;
  mesh.block_first_node.push_back(0);
  mesh.edge_nodes.resize(n_blocks);
  for (int b = 0; b < n_blocks; ++b) {
    const Polygon& poly = polygons[b];
    MesherInput input;
    std::vector<int> edge_start(poly.n_vertices());  // local index of each vertex's point
    for (int l = 0; l < poly.n_loops(); ++l) {
      std::vector<Vec2> loop;
      int counted = 0;
      for (int k = 0; k < l; ++k) counted += static_cast<int>(input.loops[k].size());
      for (int e = poly.loop_offsets[l]; e < poly.loop_offsets[l + 1]; ++e) {
        edge_start[e] = counted + static_cast<int>(loop.size());
        std::vector<std::pair<double, Vec2>> cuts = splits[b][e];
        std::sort(cuts.begin(), cuts.end(),
                  [](const auto& x, const auto& y) { return x.first < y.first; });
        Vec2 from = poly.vertices[e];
        loop.push_back(from);
        cuts.emplace_back(1.0, poly.vertices[poly.next(e)]);
        for (std::size_t k = 0; k < cuts.size(); ++k) {
          const Vec2 to = cuts[k].second;
          if (to == from) continue;
          for (const Vec2& p : divide_edge(from, to, size_of)) loop.push_back(p);
          if (k + 1 < cuts.size()) loop.push_back(to);
          from = to;
        }
      }
      if (l > 0) {
        Polygon hole(std::vector<Vec2>(poly.loop(l).rbegin(), poly.loop(l).rend()));
        input.hole_seeds.push_back(interior_point(hole).point);
      }
      input.loops.push_back(std::move(loop));
    }
    for (std::size_t s = 0; s < sources.size(); ++s) {
      if (source_block[s] != b) continue;
      const HeatSource& src = sources[s];
      if (src.shape == HeatSource::Shape::Point) {
        input.points.push_back(src.points[0]);
        continue;
      }
      std::vector<Vec2> line;
      const std::size_t n = src.points.size();
      const std::size_t pieces = src.shape == HeatSource::Shape::Line ? 1 : n;
      for (std::size_t i = 0; i < pieces; ++i) {
        line.push_back(src.points[i]);
        for (const Vec2& p : divide_edge(src.points[i], src.points[(i + 1) % n], size_of))
          line.push_back(p);
      }
      line.push_back(src.shape == HeatSource::Shape::Line ? src.points[1] : src.points[0]);
      input.polylines.push_back(std::move(line));
    }
    TriangleMesh m;
    try {
      m = mesh_polygon(input, size);
    } catch (const Error& e) {
      throw Error(fmt::format("block '{}': {}", blocks[b].name, e.what()));
    }
    const int first = mesh.block_first_node.back();
    for (const Vec2& x : m.nodes) {
      mesh.nodes.push_back(x);
      mesh.node_block.push_back(b);
    }
    for (const auto& t : m.triangles) {
      mesh.triangles.push_back({first + t[0], first + t[1], first + t[2]});
      mesh.triangle_block.push_back(b);
      const Vec2 &p0 = m.nodes[t[0]], &p1 = m.nodes[t[1]], &p2 = m.nodes[t[2]];
      mesh.triangle_area.push_back(((p1 - p0).x() * (p2 - p0).y() - (p2 - p0).x() * (p1 - p0).y()) /
                                   2);
    }
    mesh.block_first_node.push_back(first + static_cast<int>(m.nodes.size()));
    // Boundary nodes along each polygon edge.
    auto& edges = mesh.edge_nodes[b];
    edges.resize(poly.n_vertices());
    for (int e = 0; e < poly.n_vertices(); ++e) {
      const int l = poly.loop_of(e);
      const int loop_first = edge_start[poly.loop_offsets[l]];
      const int loop_size = static_cast<int>(input.loops[l].size());
      const int start = edge_start[e];
      const int end =
          poly.next(e) == poly.loop_offsets[l] ? loop_first + loop_size : edge_start[poly.next(e)];
      for (int k = start; k <= end; ++k)
        edges[e].push_back(first + (k == loop_first + loop_size ? loop_first : k));
    }
  }

  // 3. Boundary edges and their partners (the same two points, reversed).
  std::unordered_map<std::array<double, 4>, int, PointHash> by_points;
  for (int b = 0; b < n_blocks; ++b)
    for (int e = 0; e < static_cast<int>(mesh.edge_nodes[b].size()); ++e) {
      const std::vector<int>& nodes = mesh.edge_nodes[b][e];
      for (std::size_t k = 0; k + 1 < nodes.size(); ++k) {
        BoundaryEdge edge{nodes[k], nodes[k + 1], b, e, -1};
        const Vec2 &pa = mesh.nodes[edge.a], &pb = mesh.nodes[edge.b];
        const int index = static_cast<int>(mesh.boundary_edges.size());
        auto it = by_points.find({pb.x(), pb.y(), pa.x(), pa.y()});
        if (it != by_points.end() && mesh.boundary_edges[it->second].partner < 0 &&
            mesh.boundary_edges[it->second].block != b) {
          edge.partner = it->second;
          mesh.boundary_edges[it->second].partner = index;
        }
        by_points.emplace(std::array<double, 4>{pa.x(), pa.y(), pb.x(), pb.y()}, index);
        mesh.boundary_edges.push_back(edge);
      }
    }

  // 4. Named boundaries: the sides of the bounding box, the exterior, and
  // the walls (excavations), whose outlines the blocks were cut along. The
  // blocks are those as cut (ThermalProcess::initialize), so the sides and
  // the walls are where the cutting put them.
  std::vector<std::pair<std::string, std::vector<int>>> named;
  for (std::string_view side : kNamedSides) named.emplace_back(side, std::vector<int>{});
  for (const NamedWall& w : walls) named.emplace_back(w.name, std::vector<int>{});
  for (int i = 0; i < static_cast<int>(mesh.boundary_edges.size()); ++i) {
    const BoundaryEdge& e = mesh.boundary_edges[i];
    if (e.partner >= 0) continue;
    const Vec2 &a = mesh.nodes[e.a], &b = mesh.nodes[e.b];
    if (std::abs(a.x() - all.lo.x()) <= tol && std::abs(b.x() - all.lo.x()) <= tol)
      named[0].second.push_back(i);
    if (std::abs(a.x() - all.hi.x()) <= tol && std::abs(b.x() - all.hi.x()) <= tol)
      named[1].second.push_back(i);
    if (std::abs(a.y() - all.lo.y()) <= tol && std::abs(b.y() - all.lo.y()) <= tol)
      named[2].second.push_back(i);
    if (std::abs(a.y() - all.hi.y()) <= tol && std::abs(b.y() - all.hi.y()) <= tol)
      named[3].second.push_back(i);
    named[4].second.push_back(i);
    const Vec2 mid = 0.5 * (a + b);
    for (std::size_t w = 0; w < walls.size(); ++w) {
      const std::vector<Vec2>& o = walls[w].outline;
      for (std::size_t k = 0; k < o.size(); ++k)
        if (point_segment_distance(mid, o[k], o[(k + 1) % o.size()]) <= 1e3 * tol) {
          named[5 + w].second.push_back(i);
          break;
        }
    }
  }
  mesh.boundaries = std::move(named);
  return mesh;
}

}  // namespace fissure::thermal
