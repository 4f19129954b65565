// Contacts of rigid blocks with rounded corners (mechanics/dem/
// contact_geometry.h) on configurations whose gaps, normals and lengths
// follow by hand:
//  * a square corner rounded with d has an arc of radius d centred d
//    inside both edges;
//  * a brick on a wider base, lifted by g: its two bottom corners on the
//    base's top edge, gap g, normal down, half its width each (its weight
//    carried over its whole width);
//  * two squares meeting corner to corner across a diagonal gap: one
//    contact, along the diagonal, gap sqrt(2) (2 d + delta) - 2 d;
//  * a square in the concave corner of an L: its corner touches both edges;
//  * a wedge's tip on a face: alone on its interface, the rounding length;
//  * nothing beyond the margin.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "mechanics/dem/contact_geometry.h"

namespace fissure::dem {
namespace {

Polygon rectangle(double x0, double y0, double x1, double y1) {
  return Polygon({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
}

TEST(DemContactGeometry, ASquareCornerIsRoundedByAQuarterCircle) {
  const std::vector<RoundedCorner> c = rounded_corners(rectangle(0, 0, 2, 1), 0.1);
  ASSERT_EQ(c.size(), 4u);
  for (const RoundedCorner& r : c) {
    EXPECT_TRUE(r.convex);
    EXPECT_NEAR(r.radius, 0.1, 1e-15);
  }
  EXPECT_NEAR((c[0].centre - Vec2(0.1, 0.1)).norm(), 0, 1e-15);
  EXPECT_NEAR((c[2].centre - Vec2(1.9, 0.9)).norm(), 0, 1e-15);
  // An edge shorter than 2 d leaves each end half of it.
  const std::vector<RoundedCorner> thin = rounded_corners(rectangle(0, 0, 2, 0.1), 0.1);
  EXPECT_NEAR(thin[0].tangent_length, 0.05, 1e-15);
}

TEST(DemContactGeometry, ABrickOnABaseRestsOnItsTwoBottomCorners) {
  const double g = 1e-3, d = 0.05;
  const std::vector<Polygon> blocks = {rectangle(0, -1, 10, 0), rectangle(2, g, 4, g + 1)};
  const std::vector<ContactGeometry> c = find_contacts(blocks, d, 0.01);
  ASSERT_EQ(c.size(), 2u);
  for (int k = 0; k < 2; ++k) {
    EXPECT_EQ(c[k].key.block_i, 1);
    EXPECT_EQ(c[k].key.corner, k);  // the bottom corners (2, g) and (4, g)
    EXPECT_EQ(c[k].key.block_j, 0);
    EXPECT_EQ(c[k].key.feature, 2);  // the base's top edge (10, 0) -> (0, 0)
    EXPECT_NEAR(c[k].gap, g, 1e-14);
    EXPECT_NEAR((c[k].normal - Vec2(0, -1)).norm(), 0, 1e-15);
    EXPECT_NEAR(c[k].point.y(), 0.5 * g, 1e-14);
    EXPECT_NEAR(c[k].length, 1.0, 1e-12);  // half of the 2 m width
  }
}

TEST(DemContactGeometry, CornersAcrossADiagonalMeetOnceAlongIt) {
  const double d = 0.05, delta = 2e-3;
  const std::vector<Polygon> blocks = {rectangle(0, 0, 1, 1),
                                       rectangle(1 + delta, 1 + delta, 2 + delta, 2 + delta)};
  const std::vector<ContactGeometry> c = find_contacts(blocks, d, 0.1);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_TRUE(c[0].key.corner_corner());
  EXPECT_EQ(c[0].key.block_i, 0);
  EXPECT_EQ(c[0].key.corner, 2);
  EXPECT_EQ(c[0].key.feature, -1);  // corner 0 of block 1
  EXPECT_NEAR(c[0].gap, std::sqrt(2.0) * (2 * d + delta) - 2 * d, 1e-14);
  EXPECT_NEAR((c[0].normal - Vec2(1, 1).normalized()).norm(), 0, 1e-14);
  EXPECT_NEAR(c[0].length, d, 1e-15);  // alone on its interface
}

TEST(DemContactGeometry, ACornerInAConcaveCornerTouchesBothEdges) {
  // An L (its reflex corner at (1, 1)) and a 60-degree wedge whose tip
  // points into that corner along the diagonal, e = 1 mm off it: by
  // symmetry its rounded tip is the same distance from both faces,
  // e + (d / cos 30) / sqrt 2 - d tan 30.
  const Polygon l({{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}});
  const double e = 1e-3, d = 0.05, pi = std::acos(-1.0);
  const Vec2 tip(1 + e, 1 + e);
  auto ray = [&](double degrees) -> Vec2 {
    return tip + 2.0 * Vec2(std::cos(degrees * pi / 180), std::sin(degrees * pi / 180));
  };
  const Polygon wedge({tip, ray(15), ray(75)});
  const double gap = e + d / std::cos(pi / 6) / std::sqrt(2.0) - d * std::tan(pi / 6);
  const std::vector<ContactGeometry> c = find_contacts({l, wedge}, d, 0.05);
  int at_tip = 0;
  for (const ContactGeometry& k : c)
    if (k.key.block_i == 1 && k.key.corner == 0) {
      ++at_tip;
      EXPECT_NEAR(k.gap, gap, 1e-14);
    }
  EXPECT_EQ(at_tip, 2);
}

TEST(DemContactGeometry, AWedgesTipOnAFaceHasTheRoundingLength) {
  const std::vector<Polygon> blocks = {rectangle(0, -1, 4, 0),
                                       Polygon({{2, 0.002}, {3, 1.002}, {1, 1.002}})};
  // The tip's arc: 90 degrees between its edges, radius d, centre d sqrt(2)
  // above the tip: gap = 0.002 + d sqrt(2) - d = 0.0227 (the rounding lifts
  // the tip's surface by d (sqrt 2 - 1)).
  const std::vector<ContactGeometry> c = find_contacts(blocks, 0.05, 0.05);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].key.block_i, 1);
  EXPECT_EQ(c[0].key.corner, 0);
  EXPECT_NEAR(c[0].length, 0.05, 1e-15);
  EXPECT_NEAR(c[0].gap, 0.002 + 0.05 * std::sqrt(2.0) - 0.05, 1e-14);
}

TEST(DemContactGeometry, KnownContactsFollowAMoveAsASearchWouldFindThem) {
  // A brick on a base and a second brick corner to corner with it; the
  // first is moved and turned slightly: update_contacts gives the gaps,
  // normals and points a new search gives, with the keys and lengths kept.
  std::vector<Polygon> blocks = {rectangle(0, -1, 10, 0), rectangle(2, 1e-3, 4, 1.001),
                                 rectangle(4.002, 1.003, 5.002, 2.003)};
  std::vector<ContactGeometry> known = find_contacts(blocks, 0.05, 0.05);
  ASSERT_EQ(known.size(), 3u);
  const Eigen::Rotation2Dd turn(2e-4);
  const Vec2 centre(3, 0.501);
  for (Vec2& v : blocks[1].vertices) v = centre + Vec2(1e-4, -2e-4) + turn * (v - centre);
  update_contacts(known, blocks, 0.05);
  const std::vector<ContactGeometry> found = find_contacts(blocks, 0.05, 0.05);
  ASSERT_EQ(found.size(), known.size());
  for (std::size_t k = 0; k < known.size(); ++k) {
    EXPECT_EQ(known[k].key, found[k].key);
    EXPECT_NEAR(known[k].gap, found[k].gap, 1e-15);
    EXPECT_NEAR((known[k].normal - found[k].normal).norm(), 0, 1e-15);
    EXPECT_NEAR((known[k].point - found[k].point).norm(), 0, 1e-15);
  }
}

TEST(DemContactGeometry, NothingBeyondTheMargin) {
  const std::vector<Polygon> blocks = {rectangle(0, -1, 10, 0), rectangle(2, 0.02, 4, 1)};
  EXPECT_TRUE(find_contacts(blocks, 0.05, 0.01).empty());
  EXPECT_EQ(find_contacts(blocks, 0.05, 0.03).size(), 2u);
}

}  // namespace
}  // namespace fissure::dem
