// Bad scene geometry (issue 2, "Bad input"): polygons with fewer than three
// vertices, zero area, self-intersection, duplicate consecutive vertices,
// holes outside their block, overlapping blocks and points outside every
// block, each reported at the offending text with its key path.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "coupling/process_registry.h"
#include "tests/support/bad_scene_checks.h"

namespace fissure::testing {
namespace {

/// The scene with the vertices of block `top` replaced.
std::string with_top_vertices(const std::string& vertices) {
  return replace(kValid, "vertices: [[4, 1], [6, 1], [6, 2], [4, 2]]", "vertices: " + vertices);
}

TEST(bad_scenes, PolygonWithFewerThanThreeVertices) {
  const std::string yaml = with_top_vertices("[[4, 1], [6, 1]]");
  expect_error(errors(yaml), at(yaml, "vertices: [[4, 1], [6"), "blocks[1].vertices",
               {"2 vertices", "expected a simple polygon: at least 3 distinct vertices"});
}

TEST(bad_scenes, PolygonWithZeroArea) {
  const std::string yaml = with_top_vertices("[[4, 1], [5, 1], [6, 1]]");
  expect_error(errors(yaml), at(yaml, "vertices: [[4, 1], [5"), "blocks[1].vertices",
               {"zero area", "expected a simple polygon", "non-zero area"});
}

TEST(bad_scenes, SelfIntersectingBowTie) {
  const std::string yaml = with_top_vertices("[[4, 1], [6, 2], [6, 1], [4, 3]]");
  expect_error(errors(yaml), at(yaml, "vertices: [[4, 1], [6, 2]"), "blocks[1].vertices",
               {"intersect", "expected a simple polygon", "edges that do not cross"});
}

TEST(bad_scenes, DuplicateConsecutiveVertices) {
  const std::string yaml = with_top_vertices("[[4, 1], [6, 1], [6, 1], [6, 2], [4, 2]]");
  expect_error(errors(yaml), at(yaml, "vertices: [[4, 1], [6, 1], [6, 1]"), "blocks[1].vertices",
               {"coincide", "expected a simple polygon: at least 3 distinct vertices"});
}

TEST(bad_scenes, HoleOutsideTheBlock) {
  const std::string yaml =
      replace(kValid, "    fixed: true\n",
              "    holes: [[[20, 0.2], [21, 0.2], [21, 0.8]]]\n    fixed: true\n");
  expect_error(errors(yaml), at(yaml, "holes:"), "blocks[0].holes[0]",
               {"outside", "hole 1 is holes[0]", "strictly inside the outer loop"});
}

TEST(bad_scenes, OverlappingBlocks) {
  const std::string yaml = with_top_vertices("[[4, 0.5], [6, 0.5], [6, 2], [4, 2]]");
  const std::vector<std::string> lines = errors(yaml);
  ASSERT_EQ(lines.size(), 1u);
  expect_error(lines, at(yaml, "vertices: [[4, 0.5]"), "blocks[1].vertices",
               {"found block 'top' overlapping block 'base' (blocks[0], line 12)",
                "expected blocks that touch at most along edges or at vertices"});
}

TEST(bad_scenes, PointOutsideEveryBlock) {
  const std::string yaml = replace(kValid, "point: [5, 1.5]", "point: [50, 50]");
  expect_error(errors(yaml), at(yaml, "[50, 50]"), "monitors[0].point",
               {"found (50, 50), which is outside every block",
                "expected a point inside a block or on its boundary, or `block: none`"});

  const std::string fixed = kValid + "fixed_points:\n  - point: [-1, 0]\n";
  expect_error(errors(fixed), at(fixed, "[-1, 0]"), "fixed_points[0].point",
               {"found (-1, 0), which is outside every block", "expected a point inside"});

  const std::string named = kValid +
                            "point_loads:\n  - point: [5, 0.5]\n    block: top\n"
                            "    force: [0, -1 kN]\n";
  expect_error(errors(named), at(named, "[5, 0.5]"), "point_loads[0].point",
               {"found (5, 0.5), which is outside block 'top'",
                "expected a point inside block 'top' or on its boundary"});
}

TEST(bad_scenes, PointOnTwoBlocksMustNameOne) {
  const std::string yaml = replace(kValid, "point: [5, 1.5]", "point: [5, 1]");
  expect_error(errors(yaml), at(yaml, "[5, 1]\n"), "monitors[0].point",
               {"found (5, 1), which lies on blocks 'base' and 'top'",
                "expected `block:` naming the one it belongs to"});
  const std::string named = replace(kValid, "point: [5, 1.5]", "point: [5, 1]\n    block: top");
  EXPECT_NO_THROW(read_scene_text(named, "bad.yaml"));
}

}  // namespace
}  // namespace fissure::testing
