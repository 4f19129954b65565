// check_polygon (each problem kind, and none for valid concave polygons with
// holes), orient_loops, locate_point, and find_overlapping_pairs (touching is
// not overlapping; identical, contained, partial, in-a-hole; equality with an
// exact all-pairs reference on random layouts).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "core/geometry/polygon_checks.h"
#include "core/geometry/polygon_locator.h"

namespace fissure {
namespace {

constexpr double kTol = 1e-9;

Polygon poly(std::vector<Vec2> outer, std::vector<std::vector<Vec2>> holes = {}) {
  Polygon p(std::move(outer));
  for (const auto& h : holes) p.add_loop(h);
  return p;
}

std::vector<Vec2> rect(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}
std::vector<Vec2> rect_cw(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x0, y1}, {x1, y1}, {x1, y0}};
}

/// Star with n spikes (2n vertices), radii r and R, centred at c.
std::vector<Vec2> star(int n, double r, double R, const Vec2& c = Vec2::Zero()) {
  std::vector<Vec2> v;
  for (int i = 0; i < 2 * n; ++i) {
    const double a = std::numbers::pi * i / n;
    v.push_back(c + (i % 2 ? r : R) * Vec2(std::cos(a), std::sin(a)));
  }
  return v;
}

/// A concave block (U shape) with two holes in its base.
Polygon valid_concave_with_holes() {
  return poly({{0, 0}, {10, 0}, {10, 8}, {7, 8}, {7, 3}, {3, 3}, {3, 8}, {0, 8}},
              {rect_cw(1, 1, 2, 2), rect_cw(5, 0.5, 9, 2.5)});
}

/// Problems whose text contains `word`.
std::vector<PolygonProblem> with(const std::vector<PolygonProblem>& ps, const std::string& word) {
  std::vector<PolygonProblem> r;
  for (const auto& p : ps)
    if (p.what.find(word) != std::string::npos) r.push_back(p);
  return r;
}

std::string dump(const std::vector<PolygonProblem>& ps) {
  std::string s;
  for (const auto& p : ps)
    s += "  [" + std::to_string(p.loop) + ":" + std::to_string(p.vertex) + "] " + p.what + "\n";
  return s;
}

// ---------------------------------------------------------------- check_polygon

TEST(polygon_checks, CheckPolygonValidPolygonsHaveNoProblems) {
  const Polygon u = valid_concave_with_holes();
  EXPECT_TRUE(check_polygon(u, kTol).empty()) << dump(check_polygon(u, kTol));
  // Collinear (180-degree) vertices, far from the origin, clockwise input.
  Polygon far =
      poly({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {0, 2}}, {rect_cw(0.5, 0.5, 1.5, 1.5)});
  for (Vec2& v : far.vertices) v += Vec2(1e6, -1e6);
  EXPECT_TRUE(check_polygon(far, kTol).empty()) << dump(check_polygon(far, kTol));
  Polygon cw = poly(rect_cw(0, 0, 1, 1));
  EXPECT_TRUE(check_polygon(cw, kTol).empty());
  // 10,000-vertex star with 100 small holes (grid broad phase).
  Polygon big = poly(star(5000, 50, 60));
  for (int i = 0; i < 100; ++i) {
    const Vec2 c = 30 * Vec2(std::cos(0.0628 * i), std::sin(0.0628 * i));
    big.add_loop(rect_cw(c.x() - 0.2, c.y() - 0.2, c.x() + 0.2, c.y() + 0.2));
  }
  EXPECT_TRUE(check_polygon(big, kTol).empty()) << dump(check_polygon(big, kTol));
}

TEST(polygon_checks, CheckPolygonTooFewVertices) {
  const auto ps = check_polygon(poly({{0, 0}, {1, 0}}, {{{0.2, 0.2}}}), kTol);
  const auto few = with(ps, "at least 3");
  ASSERT_EQ(few.size(), 2u) << dump(ps);
  EXPECT_EQ(few[0].loop, 0);
  EXPECT_EQ(few[1].loop, 1);
  EXPECT_FALSE(check_polygon(Polygon{}, kTol).empty());
}

TEST(polygon_checks, CheckPolygonNonFiniteCoordinates) {
  const double nan = std::nan(""), inf = INFINITY;
  const auto ps = check_polygon(poly({{0, 0}, {1, nan}, {1, 1}, {inf, 1}}), kTol);
  const auto bad = with(ps, "non-finite");
  ASSERT_EQ(bad.size(), 2u) << dump(ps);
  EXPECT_EQ(bad[0].vertex, 1);
  EXPECT_EQ(bad[1].vertex, 3);
  EXPECT_NE(bad[1].what.find("inf"), std::string::npos);
}

TEST(polygon_checks, CheckPolygonDuplicateConsecutiveVertices) {
  // Exact repeat of vertex 1, and the last vertex within tol of the first.
  const auto ps = check_polygon(poly({{0, 0}, {2, 0}, {2, 0}, {2, 2}, {0, 2}, {1e-10, 0}}), kTol);
  const auto dup = with(ps, "coincide");
  ASSERT_EQ(dup.size(), 2u) << dump(ps);
  EXPECT_EQ(dup[0].vertex, 1);
  EXPECT_EQ(dup[1].vertex, 5);
  EXPECT_NE(dup[0].what.find("(2, 0)"), std::string::npos) << dup[0].what;
  EXPECT_EQ(ps.size(), 2u) << "duplicates must not also show up as touching edges\n" << dump(ps);
  // Exact duplicates are caught even with zero tolerance.
  EXPECT_EQ(with(check_polygon(poly({{0, 0}, {1, 0}, {1, 0}, {0, 1}}), 0), "coincide").size(), 1u);
}

TEST(polygon_checks, CheckPolygonZeroArea) {
  const auto collinear = check_polygon(poly({{0, 0}, {1, 0}, {2, 0}}), kTol);
  EXPECT_EQ(with(collinear, "zero area").size(), 1u) << dump(collinear);
  const auto sliver = check_polygon(poly({{0, 0}, {1, 0}, {1, 1e-12}, {0, 1e-12}}), kTol);
  EXPECT_FALSE(with(sliver, "zero area").empty()) << dump(sliver);
  // Net area: a hole as large as the outer loop.
  const auto net = check_polygon(poly(rect(0, 0, 1, 1), {rect_cw(0, 0, 1, 1)}), kTol);
  EXPECT_EQ(with(net, "zero net area").size(), 1u) << dump(net);
  EXPECT_TRUE(with(check_polygon(valid_concave_with_holes(), kTol), "area").empty());
}

TEST(polygon_checks, CheckPolygonSelfIntersectionAndTouching) {
  const auto bowtie = check_polygon(poly({{0, 0}, {2, 2}, {2, 0}, {0, 2}}), kTol);
  const auto cross = with(bowtie, "intersect at (1, 1)");
  ASSERT_EQ(cross.size(), 1u) << dump(bowtie);
  EXPECT_EQ(cross[0].loop, 0);
  EXPECT_EQ(cross[0].vertex, 0);

  // Vertex 3 sits on edge 0-1, exactly and within tolerance.
  for (double dy : {0.0, 5e-10}) {
    const auto ps = check_polygon(poly({{0, 0}, {6, 0}, {6, 4}, {3, dy}, {0, 4}}), kTol);
    // Edges 2-3 and 3-4 both meet edge 0-1, at one point: reported once.
    EXPECT_EQ(with(ps, "touch at").size(), 1u) << dump(ps);
  }
  EXPECT_TRUE(check_polygon(poly({{0, 0}, {6, 0}, {6, 4}, {3, 1e-6}, {0, 4}}), kTol).empty());

  // Many crossings in a large polygon: every one found, the list capped.
  std::vector<Vec2> zigzag;
  for (int i = 0; i < 200; ++i) zigzag.push_back({double(i), i % 2 ? 1.0 : -1.0});
  for (int i = 199; i >= 0; --i) zigzag.push_back({i + 0.5, i % 2 ? -1.0 : 1.0});
  const auto zz = check_polygon(poly(zigzag), kTol);
  EXPECT_EQ(with(zz, "intersect").size(), 101u) << "100 listed plus one summary";
  EXPECT_EQ(with(zz, "further intersecting").size(), 1u);
}

TEST(polygon_checks, CheckPolygonEdgesFoldingBack) {
  // A zero-width spike (2,1) -> (3,1) -> (2,1) on the right side.
  const auto ps = check_polygon(
      poly({{0, 0}, {2, 0}, {2, 1}, {3, 1}, {2, 1.0000000001}, {2, 2}, {0, 2}}), 1e-6);
  const auto fold = with(ps, "fold back");
  ASSERT_FALSE(fold.empty()) << dump(ps);
  EXPECT_EQ(fold[0].vertex, 3);
  EXPECT_NE(fold[0].what.find("(3, 1)"), std::string::npos) << fold[0].what;
  // An edge running back along its predecessor.
  const auto back = check_polygon(poly({{0, 0}, {4, 0}, {2, 0}, {2, 3}}), kTol);
  EXPECT_FALSE(with(back, "fold back").empty()) << dump(back);
}

TEST(polygon_checks, CheckPolygonHolePlacement) {
  const auto outside = check_polygon(poly(rect(0, 0, 4, 4), {rect_cw(5, 1, 6, 2)}), kTol);
  ASSERT_EQ(outside.size(), 1u) << dump(outside);
  EXPECT_EQ(outside[0].loop, 1);
  EXPECT_NE(outside[0].what.find("outside the outer loop"), std::string::npos);

  const auto crossing = check_polygon(poly(rect(0, 0, 4, 4), {rect_cw(3, 1, 5, 2)}), kTol);
  EXPECT_EQ(with(crossing, "hole 1 and the outer loop intersect").size(), 2u) << dump(crossing);

  const auto touching = check_polygon(poly(rect(0, 0, 4, 4), {rect_cw(2, 1, 4, 2)}), kTol);
  EXPECT_FALSE(with(touching, "hole 1 and the outer loop touch").empty()) << dump(touching);
  EXPECT_TRUE(with(touching, "intersect").empty()) << dump(touching);

  // A hole containing the outer loop.
  const auto around = check_polygon(poly(rect(1, 1, 2, 2), {rect_cw(0, 0, 3, 3)}), kTol);
  EXPECT_EQ(with(around, "outside the outer loop").size(), 1u) << dump(around);
}

TEST(polygon_checks, CheckPolygonHolesOverlappingOrTouching) {
  const auto base = rect(0, 0, 10, 10);
  const auto crossing = check_polygon(poly(base, {rect_cw(1, 1, 4, 4), rect_cw(3, 3, 6, 6)}), kTol);
  EXPECT_EQ(with(crossing, "holes 1 and 2 intersect").size(), 2u) << dump(crossing);
  const auto touching = check_polygon(poly(base, {rect_cw(1, 1, 4, 4), rect_cw(4, 1, 6, 4)}), kTol);
  EXPECT_FALSE(with(touching, "holes 1 and 2 touch").empty()) << dump(touching);
  const auto corner = check_polygon(poly(base, {rect_cw(1, 1, 4, 4), rect_cw(4, 4, 6, 6)}), kTol);
  ASSERT_EQ(with(corner, "holes 1 and 2 touch").size(), 1u) << dump(corner);
  EXPECT_NE(corner[0].what.find("at (4, 4)"), std::string::npos) << dump(corner);
  const auto nested = check_polygon(poly(base, {rect_cw(3, 3, 4, 4), rect_cw(1, 1, 6, 6)}), kTol);
  ASSERT_EQ(nested.size(), 1u) << dump(nested);
  EXPECT_EQ(nested[0].loop, 1);
  EXPECT_NE(nested[0].what.find("hole 1 lies inside hole 2"), std::string::npos);
}

// ----------------------------------------------------------------- orient_loops

TEST(polygon_checks, OrientLoopsOuterCounterClockwiseHolesClockwise) {
  Polygon p = poly(rect_cw(0, 0, 4, 4), {rect(1, 1, 2, 2), rect_cw(2.5, 2.5, 3, 3)});
  orient_loops(p);
  EXPECT_GT(signed_area(p.loop(0)), 0);
  EXPECT_LT(signed_area(p.loop(1)), 0);
  EXPECT_LT(signed_area(p.loop(2)), 0);
  EXPECT_EQ(p.loop(0)[0], Vec2(0, 0));  // first vertex kept
  EXPECT_EQ(p.loop(1)[0], Vec2(1, 1));
  EXPECT_NEAR(section_properties(p).area, 16 - 1 - 0.25, 1e-14);
  const Polygon again = p;
  orient_loops(p);
  EXPECT_EQ(p.vertices, again.vertices);
}

// ----------------------------------------------------------------- locate_point

TEST(polygon_checks, LocatePointInsideBoundaryOutsideHole) {
  const Polygon u = valid_concave_with_holes();
  EXPECT_EQ(locate_point(u, {1, 5}, kTol), 1);
  EXPECT_EQ(locate_point(u, {5, 5}, kTol), -1);      // in the notch of the U
  EXPECT_EQ(locate_point(u, {1.5, 1.5}, kTol), -1);  // in a hole
  EXPECT_EQ(locate_point(u, {11, 1}, kTol), -1);
  EXPECT_EQ(locate_point(u, {0, 4}, kTol), 0);    // outer edge
  EXPECT_EQ(locate_point(u, {7, 8}, kTol), 0);    // vertex
  EXPECT_EQ(locate_point(u, {1.5, 2}, kTol), 0);  // hole edge
  EXPECT_EQ(locate_point(u, {1.5, 2 + 5e-10}, kTol), 0);
  EXPECT_EQ(locate_point(u, {1.5, 2 + 2e-9}, kTol), 1);
  EXPECT_EQ(locate_point(u, {1.5, 2 - 2e-9}, kTol), -1);
  // Rays through vertices: points level with vertices of a diamond.
  const Polygon diamond = poly({{0, -1}, {1, 0}, {0, 1}, {-1, 0}});
  EXPECT_EQ(locate_point(diamond, {0, 0}, kTol), 1);
  EXPECT_EQ(locate_point(diamond, {-2, 0}, kTol), -1);
  EXPECT_EQ(locate_point(diamond, {-0.5, -1}, kTol), -1);
  EXPECT_EQ(locate_point(diamond, {0, 1}, kTol), 0);
}

TEST(polygon_checks, LocatePointLargePolygonMatchesWindingNumber) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-70, 70);
  Polygon p = poly(star(400, 40, 60), {star(30, 5, 15, {5, 0})});
  std::reverse(p.vertices.begin() + p.loop_offsets[1], p.vertices.end());
  for (int k = 0; k < 2000; ++k) {
    const Vec2 q(u(rng), u(rng));
    double winding = 0;  // sum of signed angles over all loops
    for (int v = 0; v < p.n_vertices(); ++v) {
      const Vec2 a = p.vertices[v] - q, b = p.vertices[p.next(v)] - q;
      winding += std::atan2(cross(a, b), a.dot(b));
    }
    const int expected = std::abs(winding) > std::numbers::pi ? 1 : -1;
    EXPECT_EQ(locate_point(p, q, 1e-12), expected) << q.transpose();
  }
}

// A small polygon is located without an index (locate_point's own loop); a
// locator answers the same everywhere, near edges and vertices included.
TEST(polygon_checks, LocatePointSmallPolygonAnswersAsALocator) {
  const Polygon u = valid_concave_with_holes();
  ASSERT_LT(u.n_vertices(), 32);
  const PolygonLocator locator(u);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> x(-1, 11), near(-2e-9, 2e-9);
  std::uniform_int_distribution<int> vertex(0, u.n_vertices() - 1);
  int on_boundary = 0;
  for (int k = 0; k < 4000; ++k) {
    // Every other point within a few tolerances of a vertex or an edge's middle.
    Vec2 q(x(rng), x(rng));
    if (k % 2 == 1) {
      const int v = vertex(rng);
      const Vec2 at = k % 4 == 1 ? u.vertices[v] : 0.5 * (u.vertices[v] + u.vertices[u.next(v)]);
      q = at + Vec2(near(rng), near(rng));
    }
    const int located = locate_point(u, q, kTol);
    EXPECT_EQ(located, locator.locate(q, kTol)) << q.transpose();
    on_boundary += located == 0;
  }
  EXPECT_GT(on_boundary, 500);  // the near points did test the boundary rule
}

// ------------------------------------------------------- find_overlapping_pairs

using Pairs = std::vector<std::pair<int, int>>;

TEST(polygon_checks, OverlappingPairsTouchingIsNotOverlapping) {
  // Running-bond brick wall: bricks touch along edges and at T-junctions.
  std::vector<Polygon> wall;
  for (int row = 0; row < 30; ++row)
    for (int i = 0; i < 30; ++i) {
      const double x = 2.0 * i + (row % 2);
      wall.push_back(poly(rect(x, row, x + 2, row + 1)));
    }
  EXPECT_TRUE(find_overlapping_pairs(wall, kTol).empty());

  // Diamonds tiling the plane (boxes overlap, so the narrow phase decides),
  // and a rotated square grid (touching only up to rounding).
  std::vector<Polygon> diamonds, rotated;
  const double c = std::cos(0.3), s = std::sin(0.3);
  auto rot = [&](double x, double y) -> Vec2 {
    return Vec2(c * x - s * y, s * x + c * y) + Vec2(1e5, 0);
  };
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) {
      if ((i + j) % 2 == 0)
        diamonds.push_back(
            poly({{i - 1.0, j + 0.0}, {i + 0.0, j - 1.0}, {i + 1.0, j + 0.0}, {i + 0.0, j + 1.0}}));
      rotated.push_back(poly({rot(i, j), rot(i + 1, j), rot(i + 1, j + 1), rot(i, j + 1)}));
    }
  EXPECT_TRUE(find_overlapping_pairs(diamonds, kTol).empty());
  EXPECT_TRUE(find_overlapping_pairs(rotated, 1e-9 * 20).empty());
  // Corner to corner, and a vertex touching an edge.
  std::vector<Polygon> corners{poly(rect(0, 0, 1, 1)), poly(rect(1, 1, 2, 2)),
                               poly({{0.5, 1}, {1, 2}, {-0.5, 2}})};
  EXPECT_TRUE(find_overlapping_pairs(corners, kTol).empty());
}

TEST(polygon_checks, OverlappingPairsJigsawOfNonConvexBlocks) {
  // Cells of a jittered lattice with a jittered vertex on every side, shared
  // exactly with the neighbour: non-convex blocks touching along zig-zags,
  // 1e6 m from the origin. Moving one block by 1e-3 makes it overlap its
  // right neighbour (and possibly others), never a pair without it.
  const int n = 30;
  auto corner = [&](int i, int j) {
    std::mt19937 r(i * 1000 + j);  // same point for every cell sharing it
    std::uniform_real_distribution<double> d(-0.3, 0.3);
    const double dx = d(r), dy = d(r);
    return Vec2(1e6 + i + (i % n ? dx : 0), 1e6 + j + (j % n ? dy : 0));
  };
  auto side = [&](int i, int j, bool horizontal) {  // midpoint of the side from corner (i, j)
    const Vec2 a = corner(i, j), b = horizontal ? corner(i + 1, j) : corner(i, j + 1);
    std::mt19937 r(i * 1000 + j + (horizontal ? 500000 : 700000));
    const double d = std::uniform_real_distribution<double>(-0.2, 0.2)(r);
    const bool border = horizontal ? j % n == 0 : i % n == 0;
    return Vec2(0.5 * (a + b) + (border ? 0 : d) * (horizontal ? Vec2(0, 1) : Vec2(1, 0)));
  };
  std::vector<Polygon> cells;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      cells.push_back(
          poly({corner(i, j), side(i, j, true), corner(i + 1, j), side(i + 1, j, false),
                corner(i + 1, j + 1), side(i, j + 1, true), corner(i, j + 1), side(i, j, false)}));
  for (const Polygon& c : cells) ASSERT_TRUE(check_polygon(c, kTol).empty());
  EXPECT_TRUE(find_overlapping_pairs(cells, 1e-9 * n).empty());
  const int moved = 10 * n + 10;
  for (Vec2& v : cells[moved].vertices) v.x() += 1e-3;
  const Pairs pairs = find_overlapping_pairs(cells, 1e-9 * n);
  EXPECT_TRUE(std::count(pairs.begin(), pairs.end(), std::pair{moved, moved + n}));
  for (const auto& [i, j] : pairs) EXPECT_TRUE(i == moved || j == moved) << i << " " << j;
}

TEST(polygon_checks, OverlappingPairsOverlapKinds) {
  const Polygon square = poly(rect(0, 0, 4, 4));
  const Pairs one{{0, 1}};
  auto pair_of = [](const Polygon& a, const Polygon& b) {
    return find_overlapping_pairs(std::vector<Polygon>{a, b}, kTol);
  };
  EXPECT_EQ(pair_of(square, square), one) << "identical";
  EXPECT_EQ(pair_of(square, poly(rect_cw(0, 0, 4, 4))), one) << "identical, reversed";
  EXPECT_EQ(pair_of(square, poly(rect(1, 1, 2, 2))), one) << "strictly inside";
  EXPECT_EQ(pair_of(poly(rect(0, 0, 2, 2)), square), one) << "inside, sharing a corner";
  EXPECT_EQ(pair_of(square, poly(rect(2, 0, 6, 4))), one) << "partial, boundaries along each other";
  EXPECT_EQ(pair_of(poly(rect(0, 1, 4, 2)), poly(rect(1, 0, 2, 4))), one)
      << "cross, no vertex inside";
  EXPECT_EQ(pair_of(square, poly({{2, 2}, {6, 3}, {6, 1}})), one) << "vertex poking in";
  EXPECT_EQ(pair_of(square, poly(rect(4 - 2e-9, 1, 6, 2))), one) << "penetration 2 tol";
  EXPECT_TRUE(pair_of(square, poly(rect(4 - 5e-10, 1, 6, 2))).empty()) << "penetration tol/2";
  EXPECT_TRUE(pair_of(square, poly({{4 - 5e-10, 2}, {6, 3}, {6, 1}})).empty()) << "tip within tol";

  // Blocks in a hole: not overlapping; filling the hole exactly: touching;
  // larger than the hole: overlapping.
  const Polygon frame = poly(rect(0, 0, 10, 10), {rect_cw(3, 3, 7, 7)});
  EXPECT_TRUE(pair_of(frame, poly(rect(4, 4, 6, 6))).empty());
  EXPECT_TRUE(pair_of(frame, poly(rect(3, 3, 7, 7))).empty());
  EXPECT_TRUE(pair_of(frame, poly(rect(3, 4, 5, 6))).empty());
  EXPECT_EQ(pair_of(frame, poly(rect(2, 4, 5, 6))), one);
  EXPECT_EQ(pair_of(frame, poly(rect(1, 1, 9, 9))), one) << "covers the hole, edges inside frame";
  EXPECT_EQ(pair_of(frame, poly(rect(0, 0, 10, 10))), one) << "frame without its hole";
  // Invalid polygons are skipped, not crashed on.
  EXPECT_TRUE(pair_of(square, poly({{1, 1}, {2, 2}})).empty());
}

TEST(polygon_checks, OverlappingPairsLargePolygons) {
  const Polygon a = poly(star(300, 40, 50));
  Polygon b = poly(star(300, 40, 50, {95, 0}));  // spikes interleave near x = 47.5
  std::vector<Polygon> ps{a, b, poly(star(300, 40, 50, {100, 0}))};
  EXPECT_EQ(find_overlapping_pairs(ps, kTol), (Pairs{{0, 1}, {1, 2}}));
}

// Exact reference for convex loops: Sutherland-Hodgman clipping.
double clipped_area(std::vector<Vec2> subject, const std::vector<Vec2>& clip) {
  const double orientation = signed_area(clip) > 0 ? 1 : -1;
  for (std::size_t i = 0; i < clip.size() && !subject.empty(); ++i) {
    const Vec2 a = clip[i], b = clip[(i + 1) % clip.size()];
    std::vector<Vec2> out;
    for (std::size_t j = 0; j < subject.size(); ++j) {
      const Vec2 p = subject[j], q = subject[(j + 1) % subject.size()];
      const double sp = orientation * orient(a, b, p), sq = orientation * orient(a, b, q);
      if (sp >= 0) out.push_back(p);
      if ((sp >= 0) != (sq >= 0)) out.push_back(p + sp / (sp - sq) * (q - p));
    }
    subject = std::move(out);
  }
  return subject.size() < 3 ? 0 : std::abs(signed_area(subject));
}

/// Area of A intersect B for polygons of one convex outer loop and at most
/// one convex hole (inclusion-exclusion over the loops).
double overlap_area(const Polygon& a, const Polygon& b) {
  double area = 0;
  for (int i = 0; i < a.n_loops(); ++i)
    for (int j = 0; j < b.n_loops(); ++j) {
      const std::vector<Vec2> la(a.loop(i).begin(), a.loop(i).end());
      const std::vector<Vec2> lb(b.loop(j).begin(), b.loop(j).end());
      area += ((i + j) % 2 ? -1 : 1) * clipped_area(la, lb);
    }
  return area;
}

TEST(polygon_checks, OverlappingPairsRandomLayoutsMatchAllPairsReference) {
  std::mt19937 rng(42);
  // (1) Integer boxes: many touching, identical and overlapping pairs.
  std::uniform_int_distribution<int> pos(0, 30), size(1, 4);
  std::vector<Polygon> boxes;
  std::vector<std::array<int, 4>> b;
  for (int i = 0; i < 400; ++i) {
    const int x = pos(rng), y = pos(rng);
    b.push_back({x, y, x + size(rng), y + size(rng)});
    boxes.push_back(poly(rect(b[i][0], b[i][1], b[i][2], b[i][3])));
  }
  Pairs expected;
  for (int i = 0; i < 400; ++i)
    for (int j = i + 1; j < 400; ++j)
      if (std::min(b[i][2], b[j][2]) > std::max(b[i][0], b[j][0]) &&
          std::min(b[i][3], b[j][3]) > std::max(b[i][1], b[j][1]))
        expected.emplace_back(i, j);
  EXPECT_GT(expected.size(), 100u);
  EXPECT_EQ(find_overlapping_pairs(boxes, kTol), expected);

  // (2) Random convex polygons and frames (a square with a square hole).
  std::uniform_real_distribution<double> xy(0, 40), radius(0.3, 3), angle(0, 6.3);
  std::uniform_int_distribution<int> sides(3, 9);
  std::vector<Polygon> shapes;
  for (int i = 0; i < 300; ++i) {
    const Vec2 c(xy(rng), xy(rng));
    const double r = radius(rng), a0 = angle(rng);
    if (i % 5 == 0) {
      shapes.push_back(poly(rect(c.x() - r, c.y() - r, c.x() + r, c.y() + r),
                            {rect_cw(c.x() - r / 2, c.y() - r / 2, c.x() + r / 2, c.y() + r / 2)}));
      continue;
    }
    std::vector<Vec2> v;
    const int n = sides(rng);
    for (int k = 0; k < n; ++k)
      v.push_back(c + r * Vec2(std::cos(a0 + 2 * std::numbers::pi * k / n),
                               std::sin(a0 + 2 * std::numbers::pi * k / n)));
    shapes.push_back(poly(v));
  }
  expected.clear();
  for (int i = 0; i < 300; ++i)
    for (int j = i + 1; j < 300; ++j)
      if (overlap_area(shapes[i], shapes[j]) > 1e-12) expected.emplace_back(i, j);
  EXPECT_GT(expected.size(), 100u);
  EXPECT_EQ(find_overlapping_pairs(shapes, kTol), expected);
}

TEST(polygon_checks, OverlappingPairsTenThousandTouchingRectangles) {
  std::vector<Polygon> grid;
  for (int i = 0; i < 100; ++i)
    for (int j = 0; j < 100; ++j) grid.push_back(poly(rect(i, j, i + 1, j + 1)));
  EXPECT_TRUE(find_overlapping_pairs(grid, kTol).empty());
  grid.push_back(poly(rect(10.5, 10.5, 11.5, 11.5)));  // overlaps four cells
  EXPECT_EQ(find_overlapping_pairs(grid, kTol),
            (Pairs{{1010, 10000}, {1011, 10000}, {1110, 10000}, {1111, 10000}}));
}

}  // namespace
}  // namespace fissure
