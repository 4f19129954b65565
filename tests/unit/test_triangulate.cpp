// triangulate: the triangles cover exactly the polygon (area sum to 1e-12
// relative, Euler count n + 2h - 2 so no vertex is left out), are
// counter-clockwise with positive area, use valid vertex indices only, and
// contain every polygon edge; for convex, concave, holed, collinear-vertex,
// clockwise, far-from-origin and 1000-vertex polygons.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <utility>
#include <vector>

#include "core/base/errors.h"
#include "core/geometry/triangulate.h"

namespace fissure {
namespace {

Polygon poly(std::vector<Vec2> outer, std::vector<std::vector<Vec2>> holes = {}) {
  Polygon p(std::move(outer));
  for (const auto& h : holes) p.add_loop(h);
  return p;
}

std::vector<Vec2> rect_cw(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x0, y1}, {x1, y1}, {x1, y0}};
}

/// Net area with the loops taken as outer minus holes, whatever their orientation.
double net_area(const Polygon& p) {
  double a = std::abs(signed_area(p.loop(0)));
  for (int k = 1; k < p.n_loops(); ++k) a -= std::abs(signed_area(p.loop(k)));
  return a;
}

void expect_valid_triangulation(const Polygon& p) {
  const std::vector<std::array<int, 3>> tris = triangulate(p);
  const int n = p.n_vertices();
  EXPECT_EQ(static_cast<int>(tris.size()), n + 2 * (p.n_loops() - 1) - 2);

  double area = 0;
  std::set<std::pair<int, int>> tri_edges;
  for (const auto& t : tris) {
    for (int i : t) ASSERT_TRUE(i >= 0 && i < n) << "index " << i;
    ASSERT_TRUE(t[0] != t[1] && t[1] != t[2] && t[0] != t[2]);
    const Vec2 &a = p.vertices[t[0]], &b = p.vertices[t[1]], &c = p.vertices[t[2]];
    const double twice = orient(a, b, c);
    EXPECT_GT(twice, 0) << "triangle " << t[0] << " " << t[1] << " " << t[2] << " not CCW";
    area += twice / 2;
    for (int k = 0; k < 3; ++k)
      tri_edges.emplace(std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]));
  }
  const double exact = net_area(p);
  EXPECT_NEAR(area, exact, 1e-12 * exact);
  for (int v = 0; v < n; ++v) {
    const int w = p.next(v);
    EXPECT_TRUE(tri_edges.count({std::min(v, w), std::max(v, w)}))
        << "polygon edge " << v << "-" << w << " is not a triangle edge";
  }
}

TEST(triangulate, Convex) {
  std::vector<Vec2> hexagon;
  for (int i = 0; i < 6; ++i)
    hexagon.push_back({std::cos(std::numbers::pi * i / 3), std::sin(std::numbers::pi * i / 3)});
  expect_valid_triangulation(poly(hexagon));
  expect_valid_triangulation(poly({{0, 0}, {1, 0}, {0, 1}}));
}

TEST(triangulate, Concave) {
  // A comb: concave vertices whose Delaunay triangulation would cut outside.
  std::vector<Vec2> comb{{0, 0}, {10, 0}};
  for (int i = 10; i > 0; --i) {
    comb.push_back({double(i), 5});
    comb.push_back({i - 0.5, 1});
  }
  comb.push_back({0, 5});
  expect_valid_triangulation(poly(comb));
  expect_valid_triangulation(poly({{0, 0}, {6, 0}, {6, 2}, {2, 2}, {2, 5}, {0, 5}}));
}

TEST(triangulate, WithHoles) {
  const Polygon u = poly({{0, 0}, {10, 0}, {10, 8}, {7, 8}, {7, 3}, {3, 3}, {3, 8}, {0, 8}},
                         {rect_cw(1, 1, 2, 2), rect_cw(5, 0.5, 9, 2.5), rect_cw(0.5, 4, 2.5, 7)});
  expect_valid_triangulation(u);
  // Holes given counter-clockwise, the outer loop clockwise: same cover.
  Polygon flipped;
  for (int k = 0; k < u.n_loops(); ++k) {
    std::vector<Vec2> loop(u.loop(k).rbegin(), u.loop(k).rend());
    flipped.add_loop(loop);
  }
  expect_valid_triangulation(flipped);
}

TEST(triangulate, CollinearVertices) {
  // Square with 180-degree vertices along every edge, and a hole with them.
  std::vector<Vec2> outer, hole;
  for (int i = 0; i < 8; ++i) outer.push_back({double(i), 0});
  for (int i = 0; i < 8; ++i) outer.push_back({8, double(i)});
  for (int i = 8; i > 0; --i) outer.push_back({double(i), 8});
  for (int i = 8; i > 0; --i) outer.push_back({0, double(i)});
  for (int i = 0; i < 4; ++i) hole.push_back({2, 2 + i * 0.5});
  for (int i = 0; i < 4; ++i) hole.push_back({2 + i * 0.5, 4});
  hole.push_back({4, 4});
  hole.push_back({4, 3});
  hole.push_back({4, 2});
  hole.push_back({3, 2});
  expect_valid_triangulation(poly(outer, {hole}));
}

TEST(triangulate, ThousandVertexStar) {
  std::vector<Vec2> star;
  for (int i = 0; i < 1000; ++i) {
    const double a = 2 * std::numbers::pi * i / 1000;
    star.push_back((i % 2 ? 3.0 : 10.0) * Vec2(std::cos(a), std::sin(a)));
  }
  const Polygon p = poly(star);
  expect_valid_triangulation(p);
  std::vector<Vec2> holes[2] = {rect_cw(-1, -1, 0, 0), rect_cw(0.5, 0.5, 1.5, 1.5)};
  expect_valid_triangulation(poly(star, {holes[0], holes[1]}));
}

TEST(triangulate, FarFromOrigin) {
  Polygon p = poly({{0, 0}, {6, 0}, {6, 2}, {2, 2}, {2, 5}, {0, 5}}, {rect_cw(3, 0.5, 5, 1.5)});
  for (Vec2& v : p.vertices) v += Vec2(1e6, -2e6);
  expect_valid_triangulation(p);
}

TEST(triangulate, DegenerateInput) {
  EXPECT_TRUE(triangulate(Polygon{}).empty());
  EXPECT_TRUE(triangulate(poly({{0, 0}, {1, 0}})).empty());
  EXPECT_THROW(triangulate(poly({{0, 0}, {1, std::nan("")}, {0, 1}})), GeometryError);
  EXPECT_THROW(triangulate(poly({{0, 0}, {2, 2}, {2, 0}, {0, 2}})), GeometryError);  // bow-tie
}

}  // namespace
}  // namespace fissure
