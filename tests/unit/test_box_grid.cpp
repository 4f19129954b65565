// BoxGrid broad phase against a brute-force all-pairs reference: every
// overlapping pair (Box::overlaps, closed boxes) is reported exactly once, for
// random boxes of mixed sizes, a huge box covering all, degenerate zero-width
// boxes, identical boxes, and layouts whose overall extent is degenerate.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "core/geometry/box_grid.h"

namespace fissure {
namespace {

using PairSet = std::set<std::pair<int, int>>;

Box make_box(double x0, double y0, double x1, double y1) {
  Box b;
  b.extend(Vec2(x0, y0));
  b.extend(Vec2(x1, y1));
  return b;
}

PairSet brute_force_pairs(const std::vector<Box>& boxes) {
  PairSet pairs;
  for (int i = 0; i < static_cast<int>(boxes.size()); ++i)
    for (int j = i + 1; j < static_cast<int>(boxes.size()); ++j)
      if (boxes[i].overlaps(boxes[j])) pairs.emplace(i, j);
  return pairs;
}

/// Pairs from the grid; fails the test on a duplicate or on i >= j.
PairSet grid_pairs(const BoxGrid& grid) {
  PairSet pairs;
  grid.for_each_pair([&](int i, int j) {
    EXPECT_LT(i, j);
    EXPECT_TRUE(pairs.emplace(i, j).second) << "pair (" << i << ", " << j << ") reported twice";
  });
  return pairs;
}

void expect_queries_match(const BoxGrid& grid, const std::vector<Box>& boxes,
                          const std::vector<Box>& queries) {
  for (const Box& q : queries) {
    std::vector<int> expected, found;
    for (int i = 0; i < static_cast<int>(boxes.size()); ++i)
      if (boxes[i].overlaps(q)) expected.push_back(i);
    grid.for_each_overlapping(q, [&](int i) { found.push_back(i); });
    std::sort(found.begin(), found.end());
    EXPECT_EQ(std::adjacent_find(found.begin(), found.end()), found.end()) << "duplicate report";
    EXPECT_EQ(found, expected);
  }
}

/// Random boxes: mostly small, some medium, a few long thin ones, some of
/// zero width or zero height, a few points, and exact copies of earlier boxes.
std::vector<Box> mixed_boxes(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> pos(0, 100), small(0.1, 2), medium(2, 15);
  std::uniform_int_distribution<int> kind(0, 9);
  std::vector<Box> boxes;
  while (static_cast<int>(boxes.size()) < n) {
    const double x = pos(rng), y = pos(rng);
    switch (kind(rng)) {
      case 0:
        boxes.push_back(make_box(x, y, x + medium(rng), y + medium(rng)));
        break;
      case 1:
        boxes.push_back(make_box(x, y, x + 40 * small(rng), y + 0.1));
        break;
      case 2:
        boxes.push_back(make_box(x, y, x, y + small(rng)));
        break;  // zero width
      case 3:
        boxes.push_back(make_box(x, y, x + small(rng), y));
        break;  // zero height
      case 4:
        boxes.push_back(make_box(x, y, x, y));
        break;  // point
      case 5:
        if (!boxes.empty()) {
          boxes.push_back(boxes[std::uniform_int_distribution<int>(
              0, static_cast<int>(boxes.size()) - 1)(rng)]);
          break;
        }
        [[fallthrough]];
      default:
        boxes.push_back(make_box(x, y, x + small(rng), y + small(rng)));
    }
  }
  return boxes;
}

TEST(box_grid, EmptyInputReportsNothing) {
  std::vector<Box> boxes;
  BoxGrid grid;
  grid.build(boxes);
  EXPECT_TRUE(grid_pairs(grid).empty());
  int calls = 0;
  grid.for_each_overlapping(make_box(0, 0, 1, 1), [&](int) { ++calls; });
  EXPECT_EQ(calls, 0);
}

TEST(box_grid, SingleBox) {
  std::vector<Box> boxes{make_box(1, 1, 2, 3)};
  BoxGrid grid;
  grid.build(boxes);
  EXPECT_TRUE(grid_pairs(grid).empty());
  expect_queries_match(grid, boxes, {make_box(0, 0, 1, 1), make_box(2.5, 0, 3, 5)});
}

TEST(box_grid, MixedRandomBoxesMatchBruteForce) {
  std::mt19937 rng(20240611);
  for (int n : {2, 10, 100, 600}) {
    const std::vector<Box> boxes = mixed_boxes(n, rng);
    BoxGrid grid;
    grid.build(boxes);
    EXPECT_EQ(grid_pairs(grid), brute_force_pairs(boxes)) << "n = " << n;
  }
}

TEST(box_grid, HugeBoxCoveringAllAndIdenticalBoxes) {
  std::mt19937 rng(7);
  std::vector<Box> boxes = mixed_boxes(300, rng);
  boxes.push_back(make_box(-10, -10, 200, 200));  // covers every other box
  boxes.insert(boxes.begin() + 50, make_box(-10, -10, 200, 200));
  for (int k = 0; k < 5; ++k) boxes.push_back(make_box(3, 3, 4, 4));  // five identical
  BoxGrid grid;
  grid.build(boxes);
  const PairSet pairs = grid_pairs(grid);
  EXPECT_EQ(pairs, brute_force_pairs(boxes));
  EXPECT_TRUE(pairs.count({50, static_cast<int>(boxes.size()) - 6}));
}

TEST(box_grid, TouchingBoxesCountAsOverlapping) {
  // A 20 x 20 lattice of unit squares: closed boxes touch their 8 neighbours.
  std::vector<Box> boxes;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) boxes.push_back(make_box(i, j, i + 1, j + 1));
  BoxGrid grid;
  grid.build(boxes);
  const PairSet pairs = grid_pairs(grid);
  EXPECT_EQ(pairs, brute_force_pairs(boxes));
  EXPECT_EQ(pairs.size(), 2u * 19 * 20 + 2u * 19 * 19);
}

TEST(box_grid, CollinearDegenerateLayouts) {
  // All boxes are points or segments on one horizontal line: the overall
  // extent has zero height and the median box extent is zero.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> pos(0, 1000);
  std::vector<Box> on_line;
  for (int i = 0; i < 200; ++i) {
    const double x = pos(rng);
    on_line.push_back(i % 3 == 0 ? make_box(x, 5, x + 3, 5) : make_box(x, 5, x, 5));
  }
  on_line.push_back(on_line[10]);
  BoxGrid grid;
  grid.build(on_line);
  EXPECT_EQ(grid_pairs(grid), brute_force_pairs(on_line));
  // The grid stays small: at most ~4 cells per box along the line (a cell
  // size derived from the zero median extent would give ~1e12 cells).
  Box all;
  for (const Box& b : on_line) all.extend(b);
  EXPECT_GE(grid.cell_size() * 4.0 * on_line.size(), all.size().x() * (1 - 1e-12));

  // Same on a vertical line, and a long thin strip of tiny boxes.
  std::vector<Box> vertical, strip;
  for (const Box& b : on_line) vertical.push_back(make_box(5, b.lo.x(), 5, b.hi.x()));
  for (int i = 0; i < 300; ++i) {
    const double x = pos(rng) * 1e3;
    strip.push_back(make_box(x, 0, x + 1e-3, 1e-3));
  }
  strip.push_back(make_box(0, 0, 1e6, 1e-3));
  for (const auto* boxes : {&vertical, &strip}) {
    BoxGrid g;
    g.build(*boxes);
    EXPECT_EQ(grid_pairs(g), brute_force_pairs(*boxes));
  }
}

TEST(box_grid, AllBoxesAtOnePoint) {
  std::vector<Box> boxes(10, make_box(2, 2, 2, 2));
  BoxGrid grid;
  grid.build(boxes);
  EXPECT_EQ(grid_pairs(grid).size(), 45u);
}

TEST(box_grid, ForEachOverlappingMatchesBruteForce) {
  std::mt19937 rng(11);
  std::vector<Box> boxes = mixed_boxes(500, rng);
  boxes.push_back(make_box(-5, -5, 150, 150));
  BoxGrid grid;
  grid.build(boxes);
  std::vector<Box> queries = mixed_boxes(200, rng);
  queries.push_back(make_box(-1e9, -1e9, 1e9, 1e9));    // covers everything
  queries.push_back(make_box(500, 500, 600, 600));      // outside the grid
  queries.push_back(make_box(-600, -600, -500, -500));  // outside the grid
  queries.push_back(make_box(-1e300, 50, 1e300, 50));   // extreme coordinates
  queries.push_back(Box{});                             // empty box
  expect_queries_match(grid, boxes, queries);
}

TEST(box_grid, ExtremeAspectQueriesOnDegenerateGrid) {
  std::vector<Box> boxes;
  for (int i = 0; i < 100; ++i) boxes.push_back(make_box(i, 0, i, 0));
  BoxGrid grid;
  grid.build(boxes);
  expect_queries_match(grid, boxes,
                       {make_box(10, 0, 20, 0), make_box(-1, -1, 0.5, 1), make_box(99, 0, 1e12, 0),
                        make_box(10.5, 0, 10.7, 0)});
}

}  // namespace
}  // namespace fissure
