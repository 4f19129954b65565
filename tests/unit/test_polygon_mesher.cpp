// mesh_polygon on polygons large enough for the lattice seeds
// (core/geometry/lattice_seeds.h): the triangles cover the region exactly
// (area to 1e-12), keep the given boundary nodes first and exactly, have
// every required point as a node and every constrained segment as an edge,
// meet the size bound at each centroid, and keep CGAL's angle bound away from
// the boundary; the lattice's near-equilateral triangles make most of the
// mesh; the same input gives the same mesh. The seeds themselves: inside the
// region, clear of the edges by the margin, never in a hole.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <utility>
#include <vector>

#include "core/geometry/edge_division.h"
#include "core/geometry/lattice_seeds.h"
#include "core/geometry/polygon.h"
#include "core/geometry/polygon_mesher.h"
#include "core/geometry/segment_predicates.h"

namespace fissure {
namespace {

/// A closed loop through `corners`, its sides divided as the processes
/// divide them (divide_edge).
std::vector<Vec2> divided_loop(const std::vector<Vec2>& corners, const SizeFunction& size) {
  std::vector<Vec2> loop;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    loop.push_back(corners[i]);
    for (const Vec2& p : divide_edge(corners[i], corners[(i + 1) % corners.size()], size))
      loop.push_back(p);
  }
  return loop;
}

/// The unit square with a square hole, a constrained line and a required
/// point (the inputs a heated block has: a drift, a line source, a monitor).
MesherInput holed_square(const SizeFunction& size) {
  MesherInput in;
  in.loops.push_back(divided_loop({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, size));
  in.loops.push_back(divided_loop({{0.6, 0.6}, {0.6, 0.8}, {0.8, 0.8}, {0.8, 0.6}}, size));
  in.hole_seeds.push_back({0.7, 0.7});
  std::vector<Vec2> line{{0.2, 0.3}};
  for (const Vec2& p : divide_edge({0.2, 0.3}, {0.5, 0.3}, size)) line.push_back(p);
  line.push_back({0.5, 0.3});
  in.polylines.push_back(line);
  in.points.push_back({0.31234, 0.71234});
  return in;
}

double smallest_angle_degrees(const Vec2& a, const Vec2& b, const Vec2& c) {
  auto angle = [](const Vec2& p, const Vec2& q, const Vec2& r) {
    return std::acos(std::clamp((q - p).normalized().dot((r - p).normalized()), -1.0, 1.0));
  };
  return std::min({angle(a, b, c), angle(b, c, a), angle(c, a, b)}) * 180 / std::numbers::pi;
}

struct MeshCheck {
  double area = 0;
  int equilateral = 0;  ///< triangles whose smallest angle is above 55 degrees
};

/// The checks every mesh passes; returns its area and shape count. The size
/// bound is checked where `sized` (the refinement alone leaves a few
/// triangles near the boundary up to 16 % longer: it does not split the
/// given boundary, and skips points that would crowd it).
MeshCheck check_mesh(const MesherInput& in, const TriangleMesh& m, const SizeFunction& size,
                     bool sized = true) {
  MeshCheck r;
  std::size_t n_loop_points = 0;
  for (const auto& loop : in.loops)
    for (const Vec2& p : loop) EXPECT_EQ(m.nodes[n_loop_points++], p);
  // Nodes on a loop edge or constrained line (the angle bound does not hold
  // at them: the mesher does not split the given boundary).
  auto on_constraint = [&](const Vec2& p) {
    for (const auto& loop : in.loops)
      for (std::size_t i = 0; i < loop.size(); ++i)
        if (point_segment_distance(p, loop[i], loop[(i + 1) % loop.size()]) < 1e-12) return true;
    for (const auto& line : in.polylines)
      for (std::size_t i = 0; i + 1 < line.size(); ++i)
        if (point_segment_distance(p, line[i], line[i + 1]) < 1e-12) return true;
    for (const Vec2& q : in.points)
      if ((p - q).norm() < 1e-12) return true;
    return false;
  };
  std::vector<char> constrained(m.nodes.size());
  for (std::size_t i = 0; i < m.nodes.size(); ++i) constrained[i] = on_constraint(m.nodes[i]);
  std::set<std::pair<int, int>> edges;
  for (const auto& t : m.triangles) {
    const Vec2 &a = m.nodes[t[0]], &b = m.nodes[t[1]], &c = m.nodes[t[2]];
    const double twice = orient(a, b, c);
    EXPECT_GT(twice, 0);
    r.area += twice / 2;
    const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    const double angle = smallest_angle_degrees(a, b, c);
    if (!constrained[t[0]] && !constrained[t[1]] && !constrained[t[2]]) {
      if (sized) {
        EXPECT_LE(longest, size((a + b + c) / 3) * (1 + 1e-12));
      }
      EXPECT_GE(angle, 20.6);
    }
    if (angle > 55) ++r.equilateral;
    for (int k = 0; k < 3; ++k)
      edges.emplace(std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]));
  }
  // Every constrained segment is a mesh edge; every required point a node.
  auto node_of = [&](const Vec2& p) {
    for (std::size_t i = 0; i < m.nodes.size(); ++i)
      if (m.nodes[i] == p) return static_cast<int>(i);
    return -1;
  };
  for (const auto& line : in.polylines)
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
      const int u = node_of(line[i]), v = node_of(line[i + 1]);
      EXPECT_TRUE(u >= 0 && v >= 0 && edges.count({std::min(u, v), std::max(u, v)}))
          << line[i].transpose() << " - " << line[i + 1].transpose();
    }
  for (const Vec2& p : in.points) EXPECT_GE(node_of(p), 0);
  return r;
}

TEST(PolygonMesher, ALargeHoledPolygonIsSeededAndMeetsTheBounds) {
  const SizeFunction size = [](const Vec2&) { return 0.006; };
  const MesherInput in = holed_square(size);
  const TriangleMesh m = mesh_polygon(in, size);
  const MeshCheck r = check_mesh(in, m, size);
  EXPECT_NEAR(r.area, 1 - 0.04, 1e-10);
  // The lattice (about 5e4 points) makes most triangles near-equilateral;
  // the refinement alone makes few (its triangles spread over 20-90 degrees).
  EXPECT_GT(r.equilateral, 0.8 * static_cast<double>(m.triangles.size()));
  // About the node density of the refinement alone: mean triangle area
  // 0.19-0.21 h^2 (polygon_mesher.h).
  const double mean_area = r.area / static_cast<double>(m.triangles.size());
  EXPECT_GT(mean_area, 0.17 * 0.006 * 0.006);
  EXPECT_LT(mean_area, 0.23 * 0.006 * 0.006);
  const TriangleMesh again = mesh_polygon(in, size);
  EXPECT_EQ(again.nodes, m.nodes);
  EXPECT_EQ(again.triangles, m.triangles);
}

TEST(PolygonMesher, AGradedSizeIsSeededLevelByLevel) {
  // h from 0.004 m at x = 0 to 0.036 m at x = 1: lattices of four spacings.
  const SizeFunction size = [](const Vec2& p) { return 0.004 * (1 + 8 * p.x()); };
  const MesherInput in = holed_square(size);
  const TriangleMesh m = mesh_polygon(in, size);
  const MeshCheck r = check_mesh(in, m, size);
  EXPECT_NEAR(r.area, 1 - 0.04, 1e-10);
  EXPECT_GT(r.equilateral, 0.6 * static_cast<double>(m.triangles.size()));
}

TEST(PolygonMesher, LatticeSeedsStayInsideAndClearOfTheConstraints) {
  const SizeFunction size = [](const Vec2&) { return 0.01; };
  const MesherInput in = holed_square(size);
  const std::vector<Vec2> seeds = lattice_seeds(in, size);
  const double s = kLatticeSpacing * 0.01, margin = kLatticeMargin * s;
  // The lattice of spacing s over the region (area 0.96 m^2) less the margin band.
  EXPECT_GT(static_cast<double>(seeds.size()), 0.9 * 0.96 / (std::sqrt(3.0) / 2 * s * s));
  for (const Vec2& p : seeds) {
    ASSERT_TRUE(p.x() > margin && p.x() < 1 - margin && p.y() > margin && p.y() < 1 - margin);
    ASSERT_FALSE(p.x() > 0.6 - margin && p.x() < 0.8 + margin && p.y() > 0.6 - margin &&
                 p.y() < 0.8 + margin)
        << p.transpose();
    ASSERT_GE(point_segment_distance(p, {0.2, 0.3}, {0.5, 0.3}), margin);
    ASSERT_GE((p - Vec2(0.31234, 0.71234)).norm(), margin);
  }
  // Sorted and unique: no point twice.
  std::vector<std::pair<double, double>> xy;
  for (const Vec2& p : seeds) xy.emplace_back(p.x(), p.y());
  std::sort(xy.begin(), xy.end());
  EXPECT_EQ(std::adjacent_find(xy.begin(), xy.end()), xy.end());
}

TEST(PolygonMesher, ASmallPolygonIsNotSeeded) {
  // Below kMinLatticeSeeds lattice points the refinement alone meshes it:
  // its triangles are not mostly equilateral.
  const SizeFunction size = [](const Vec2&) { return 0.05; };
  const MesherInput in = holed_square(size);
  const TriangleMesh m = mesh_polygon(in, size);
  const MeshCheck r = check_mesh(in, m, size, false);
  EXPECT_NEAR(r.area, 1 - 0.04, 1e-10);
  EXPECT_LT(r.equilateral, 0.5 * static_cast<double>(m.triangles.size()));
}

}  // namespace
}  // namespace fissure
