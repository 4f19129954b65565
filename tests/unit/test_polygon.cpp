// Polygon storage and simplex integration (theory.md 1.2): area moments and
// section properties against exact values from rectangle and triangle
// formulas, the same shapes 1e6 m from the origin, the orientation rules, and
// loop navigation (next / prev / loop_of).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/geometry/polygon.h"

namespace fissure {
namespace {

/// Exact moments of the rectangle [x0, x1] x [y0, y1] about the origin.
AreaMoments rect_moments(double x0, double y0, double x1, double y1) {
  const double w = x1 - x0, h = y1 - y0;
  const double ix = (x1 * x1 - x0 * x0) / 2, iy = (y1 * y1 - y0 * y0) / 2;
  return {w * h,
          ix * h,
          iy * w,
          (x1 * x1 * x1 - x0 * x0 * x0) / 3 * h,
          (y1 * y1 * y1 - y0 * y0 * y0) / 3 * w,
          ix * iy};
}

AreaMoments operator+(AreaMoments a, const AreaMoments& b) {
  return {a.S + b.S, a.Sx + b.Sx, a.Sy + b.Sy, a.Sxx + b.Sxx, a.Syy + b.Syy, a.Sxy + b.Sxy};
}
AreaMoments operator-(const AreaMoments& a, const AreaMoments& b) {
  return a + AreaMoments{-b.S, -b.Sx, -b.Sy, -b.Sxx, -b.Syy, -b.Sxy};
}

/// Central properties from exact moments about the origin.
SectionProperties central(const AreaMoments& m) {
  SectionProperties s;
  s.area = m.S;
  s.centroid = Vec2(m.Sx / m.S, m.Sy / m.S);
  s.Ixx = m.Sxx - m.Sx * m.Sx / m.S;
  s.Iyy = m.Syy - m.Sy * m.Sy / m.S;
  s.Ixy = m.Sxy - m.Sx * m.Sy / m.S;
  return s;
}

void expect_rel(double actual, double expected, double rel, double scale, const char* what) {
  EXPECT_NEAR(actual, expected, rel * std::max(std::abs(expected), scale)) << what;
}

void expect_moments(const AreaMoments& a, const AreaMoments& e, double rel) {
  // Scale: a vanishing moment is compared with the magnitude of its siblings.
  const double s1 = std::max(std::abs(e.Sx), std::abs(e.Sy));
  const double s2 = std::max({std::abs(e.Sxx), std::abs(e.Syy), std::abs(e.Sxy)});
  expect_rel(a.S, e.S, rel, 0, "S");
  expect_rel(a.Sx, e.Sx, rel, s1, "Sx");
  expect_rel(a.Sy, e.Sy, rel, s1, "Sy");
  expect_rel(a.Sxx, e.Sxx, rel, s2, "Sxx");
  expect_rel(a.Syy, e.Syy, rel, s2, "Syy");
  expect_rel(a.Sxy, e.Sxy, rel, s2, "Sxy");
}

void expect_section(const SectionProperties& a, const SectionProperties& e, const Vec2& shift,
                    double rel, double size) {
  expect_rel(a.area, e.area, rel, 0, "area");
  EXPECT_NEAR(a.centroid.x() - shift.x(), e.centroid.x(), rel * size) << "centroid x";
  EXPECT_NEAR(a.centroid.y() - shift.y(), e.centroid.y(), rel * size) << "centroid y";
  const double scale = std::max({std::abs(e.Ixx), std::abs(e.Iyy), std::abs(e.Ixy)});
  expect_rel(a.Ixx, e.Ixx, rel, scale, "Ixx");
  expect_rel(a.Iyy, e.Iyy, rel, scale, "Iyy");
  expect_rel(a.Ixy, e.Ixy, rel, scale, "Ixy");
}

Polygon translated(Polygon p, const Vec2& shift) {
  for (Vec2& v : p.vertices) v += shift;
  return p;
}

Polygon rectangle() {
  return Polygon({{0, 0}, {3, 0}, {3, 2}, {0, 2}});
}
Polygon right_triangle() {
  return Polygon({{0, 0}, {4, 0}, {0, 3}});
}

/// L-shaped block [0,6]x[0,2] + [0,2]x[2,5] with the rectangular hole
/// [3,5]x[0.5,1.5] (clockwise).
Polygon l_block_with_hole() {
  Polygon p({{0, 0}, {6, 0}, {6, 2}, {2, 2}, {2, 5}, {0, 5}});
  const std::vector<Vec2> hole{{3, 0.5}, {3, 1.5}, {5, 1.5}, {5, 0.5}};
  p.add_loop(hole);
  return p;
}

const Vec2 kFar(1e6, 1e6);
const Vec2 kFar2(-3e6, 2e6);

TEST(polygon, AreaMomentsRectangleExact) {
  const AreaMoments m = area_moments(rectangle(), Vec2::Zero());
  expect_moments(m, {6, 9, 6, 18, 8, 9}, 1e-14);
  expect_moments(m, rect_moments(0, 0, 3, 2), 1e-14);
}

TEST(polygon, AreaMomentsRightTriangleExact) {
  // Legs a = 4 along x, b = 3 along y: S = ab/2, Sx = a^2 b/6, Sy = a b^2/6,
  // Sxx = a^3 b/12, Syy = a b^3/12, Sxy = a^2 b^2/24.
  expect_moments(area_moments(right_triangle(), Vec2::Zero()), {6, 8, 6, 16, 9, 6}, 1e-14);
}

TEST(polygon, AreaMomentsLBlockWithHoleExact) {
  // By hand: [0,6]x[0,2] -> {12, 36, 12, 144, 16, 36}; [0,2]x[2,5] -> {6, 6,
  // 21, 8, 78, 21}; hole [3,5]x[0.5,1.5] -> {2, 8, 2, 98/3, 13/6, 8}.
  const AreaMoments exact{16, 34, 31, 358.0 / 3, 551.0 / 6, 49};
  expect_moments(rect_moments(0, 0, 6, 2) + rect_moments(0, 2, 2, 5) - rect_moments(3, 0.5, 5, 1.5),
                 exact, 1e-14);
  expect_moments(area_moments(l_block_with_hole(), Vec2::Zero()), exact, 1e-14);
}

TEST(polygon, AreaMomentsAboutAnotherOrigin) {
  // Moments about o equal the moments of the shape shifted by -o.
  const Vec2 o(1.5, -2);
  expect_moments(area_moments(l_block_with_hole(), o),
                 area_moments(translated(l_block_with_hole(), -o), Vec2::Zero()), 1e-13);
}

TEST(polygon, AreaMomentsFarFromOriginAboutLocalOrigin) {
  for (const Vec2& far : {kFar, kFar2}) {
    expect_moments(area_moments(translated(rectangle(), far), far), rect_moments(0, 0, 3, 2),
                   1e-10);
    expect_moments(area_moments(translated(right_triangle(), far), far), {6, 8, 6, 16, 9, 6},
                   1e-10);
    expect_moments(area_moments(translated(l_block_with_hole(), far), far),
                   {16, 34, 31, 358.0 / 3, 551.0 / 6, 49}, 1e-10);
  }
}

TEST(polygon, SectionPropertiesExactShapes) {
  SectionProperties rect = section_properties(rectangle());
  EXPECT_NEAR(rect.area, 6, 1e-14);
  EXPECT_NEAR(rect.centroid.x(), 1.5, 1e-14);
  EXPECT_NEAR(rect.centroid.y(), 1.0, 1e-14);
  EXPECT_NEAR(rect.Ixx, 27.0 * 2 / 12, 1e-13);  // b h^3/12 with the roles of x, y
  EXPECT_NEAR(rect.Iyy, 3.0 * 8 / 12, 1e-13);
  EXPECT_NEAR(rect.Ixy, 0, 1e-13);

  SectionProperties tri = section_properties(right_triangle());
  EXPECT_NEAR(tri.centroid.x(), 4.0 / 3, 1e-14);
  EXPECT_NEAR(tri.centroid.y(), 1.0, 1e-14);
  EXPECT_NEAR(tri.Ixx, 64.0 * 3 / 36, 1e-13);   // a^3 b/36
  EXPECT_NEAR(tri.Iyy, 4.0 * 27 / 36, 1e-13);   // a b^3/36
  EXPECT_NEAR(tri.Ixy, -16.0 * 9 / 72, 1e-13);  // -a^2 b^2/72

  const SectionProperties l = section_properties(l_block_with_hole());
  const SectionProperties exact = central({16, 34, 31, 358.0 / 3, 551.0 / 6, 49});
  expect_section(l, exact, Vec2::Zero(), 1e-13, 6);
  EXPECT_NEAR(exact.centroid.x(), 2.125, 1e-15);
  EXPECT_NEAR(exact.centroid.y(), 1.9375, 1e-15);
}

TEST(polygon, SectionPropertiesFarFromOriginRelativeError) {
  const std::vector<std::pair<Polygon, AreaMoments>> shapes{
      {rectangle(), rect_moments(0, 0, 3, 2)},
      {right_triangle(), {6, 8, 6, 16, 9, 6}},
      {l_block_with_hole(), {16, 34, 31, 358.0 / 3, 551.0 / 6, 49}}};
  for (const auto& [shape, exact] : shapes)
    for (const Vec2& far : {kFar, kFar2})
      expect_section(section_properties(translated(shape, far)), central(exact), far, 1e-10, 6);
}

TEST(polygon, OrientationHoleClockwiseContributesNegatively) {
  const Polygon l = l_block_with_hole();
  Polygon hole_only(std::vector<Vec2>(l.loop(1).begin(), l.loop(1).end()));
  expect_moments(area_moments(hole_only, Vec2::Zero()),
                 AreaMoments{} - rect_moments(3, 0.5, 5, 1.5), 1e-14);
  EXPECT_NEAR(signed_area(l.loop(0)), 18, 1e-14);
  EXPECT_NEAR(signed_area(l.loop(1)), -2, 1e-14);

  // A hole given counter-clockwise adds instead of subtracting: the loops'
  // orientation, not their index, carries the sign (orient_loops fixes it).
  Polygon wrong({l.loop(0).begin(), l.loop(0).end()});
  std::vector<Vec2> ccw_hole(l.loop(1).rbegin(), l.loop(1).rend());
  wrong.add_loop(ccw_hole);
  EXPECT_NEAR(area_moments(wrong, Vec2::Zero()).S, 20, 1e-14);
}

TEST(polygon, OrientationReversingEveryLoopNegatesAllMoments) {
  const Polygon l = l_block_with_hole();
  Polygon reversed;
  for (int k = 0; k < l.n_loops(); ++k) {
    std::vector<Vec2> loop(l.loop(k).rbegin(), l.loop(k).rend());
    reversed.add_loop(loop);
  }
  const AreaMoments m = area_moments(l, Vec2::Zero());
  expect_moments(area_moments(reversed, Vec2::Zero()), AreaMoments{} - m, 1e-14);
  // Central properties of a consistently reversed polygon: area negative,
  // centroid and central moments per unit area unchanged.
  const SectionProperties s = section_properties(l), r = section_properties(reversed);
  EXPECT_NEAR(r.area, -s.area, 1e-13);
  EXPECT_NEAR((r.centroid - s.centroid).norm(), 0, 1e-13);
}

TEST(polygon, OrientationStartingVertexDoesNotMatter) {
  const Polygon l = l_block_with_hole();
  Polygon rotated;
  for (int k = 0; k < l.n_loops(); ++k) {
    std::vector<Vec2> loop(l.loop(k).begin(), l.loop(k).end());
    std::rotate(loop.begin(), loop.begin() + 2, loop.end());
    rotated.add_loop(loop);
  }
  expect_moments(area_moments(rotated, Vec2::Zero()), area_moments(l, Vec2::Zero()), 1e-14);
  expect_section(section_properties(rotated), section_properties(l), Vec2::Zero(), 1e-13, 6);
}

TEST(polygon, NextPrevLoopOf) {
  const Polygon l = l_block_with_hole();
  ASSERT_EQ(l.n_loops(), 2);
  ASSERT_EQ(l.n_vertices(), 10);
  EXPECT_EQ(l.loop_offsets, (std::vector<int>{0, 6, 10}));
  EXPECT_EQ(l.loop(0).size(), 6u);
  EXPECT_EQ(l.loop(1).size(), 4u);
  EXPECT_EQ(l.loop(1)[0], Vec2(3, 0.5));
  for (int v = 0; v < 6; ++v) EXPECT_EQ(l.loop_of(v), 0) << v;
  for (int v = 6; v < 10; ++v) EXPECT_EQ(l.loop_of(v), 1) << v;
  EXPECT_EQ(l.next(0), 1);
  EXPECT_EQ(l.next(4), 5);
  EXPECT_EQ(l.next(5), 0);
  EXPECT_EQ(l.prev(0), 5);
  EXPECT_EQ(l.prev(3), 2);
  EXPECT_EQ(l.next(6), 7);
  EXPECT_EQ(l.next(9), 6);
  EXPECT_EQ(l.prev(6), 9);
  for (int v = 0; v < l.n_vertices(); ++v) {
    EXPECT_EQ(l.prev(l.next(v)), v);
    EXPECT_EQ(l.loop_of(l.next(v)), l.loop_of(v));
  }
}

TEST(polygon, EmptyLoopIsSkippedByLoopOf) {
  Polygon p({{0, 0}, {1, 0}, {0, 1}});
  p.add_loop(std::vector<Vec2>{});
  const std::vector<Vec2> hole{{0.1, 0.1}, {0.1, 0.2}, {0.2, 0.1}};
  p.add_loop(hole);
  EXPECT_EQ(p.n_loops(), 3);
  EXPECT_EQ(p.loop(1).size(), 0u);
  EXPECT_EQ(p.loop_of(3), 2);
  EXPECT_EQ(p.next(5), 3);
  EXPECT_EQ(p.prev(3), 5);
}

TEST(polygon, BoundingBox) {
  const Box b = bounding_box(l_block_with_hole());
  EXPECT_EQ(b.lo, Vec2(0, 0));
  EXPECT_EQ(b.hi, Vec2(6, 5));
  EXPECT_TRUE(Box{}.empty());
  EXPECT_FALSE(b.empty());
  EXPECT_TRUE(bounding_box(Polygon{}).empty());
}

}  // namespace
}  // namespace fissure
