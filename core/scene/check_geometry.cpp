// Checks on the block polygons once all blocks are read: each polygon on its
// own (check_polygon), then orientation (orient_loops), then blocks that
// overlap at the start (find_overlapping_pairs).
#include <fmt/format.h>

#include "core/geometry/polygon_checks.h"
#include "core/scene/scene_draft.h"

namespace fissure {

namespace {

/// Vertices of one block: a block's own edges are candidates for each of its
/// vertices in contact detection, so that a polygon of 100,000 vertices
/// took 6 s per DDA step (a circle of 10,000: 0.05 s).
/// Overlapping pairs named in a report; more are counted as "more than".
constexpr std::size_t kMostOverlapsReported = 20;

/// 1e-9 x the largest extent of the bounding box of all blocks that were read.
double geometry_tolerance(const SceneDraft& draft) {
  Box box;
  for (size_t i = 0; i < draft.scene.blocks.size(); ++i)
    if (draft.block_sources[i].geometry_read && draft.scene.blocks[i].polygon.n_vertices() > 0)
      box.extend(bounding_box(draft.scene.blocks[i].polygon));
  if (box.empty()) return 0;
  return kRelativeGeometryTolerance * box.size().maxCoeff();
}

void report_polygon_problem(const BlockSource& source, const PolygonProblem& problem,
                            Diagnostics& diagnostics) {
  if (problem.loop == 0)
    diagnostics.error(source.vertices_at, source.path + ".vertices",
                      problem.what +
                          "; expected a simple polygon: at least 3 distinct vertices, non-zero "
                          "area, edges that do not cross");
  else
    diagnostics.error(
        source.holes_at, fmt::format("{}.holes[{}]", source.path, problem.loop - 1),
        fmt::format("{} (hole {} is holes[{}])", problem.what, problem.loop, problem.loop - 1) +
            "; expected a simple loop with non-zero area, strictly inside the "
            "outer loop and apart from the other holes");
}

}  // namespace

double check_geometry(SceneDraft& draft, Diagnostics& diagnostics) {
  std::vector<BlockSpec>& blocks = draft.scene.blocks;
  const double tolerance = geometry_tolerance(draft);

  std::vector<Polygon> valid;
  std::vector<int> valid_block;  // valid[k] is the polygon of blocks[valid_block[k]]
  for (size_t i = 0; i < blocks.size(); ++i) {
    BlockSource& source = draft.block_sources[i];
    if (!source.geometry_read) continue;
    if (blocks[i].polygon.n_vertices() > kMostVerticesPerBlock) {
      diagnostics.error(source.vertices_at, source.path + ".vertices",
                        fmt::format("found a polygon of {} vertices; expected at most {} per "
                                    "block (the cost of a step grows with them; "
                                    "docs/scene-reference.md, \"Limits\")",
                                    blocks[i].polygon.n_vertices(), kMostVerticesPerBlock));
      continue;
    }
    const std::vector<PolygonProblem> problems = check_polygon(blocks[i].polygon, tolerance);
    for (const PolygonProblem& p : problems) report_polygon_problem(source, p, diagnostics);
    if (!problems.empty()) continue;
    orient_loops(blocks[i].polygon);
    source.polygon_valid = true;
    valid.push_back(blocks[i].polygon);
    valid_block.push_back(static_cast<int>(i));
  }

  // A bounded report: the first kMostOverlapsReported pairs, then a note.
  const auto overlapping = find_overlapping_pairs(valid, tolerance, kMostOverlapsReported + 1);
  for (std::size_t k = 0; k < overlapping.size(); ++k) {
    const auto [a, b] = overlapping[k];
    const int i = valid_block[a], j = valid_block[b];
    if (k == kMostOverlapsReported) {
      diagnostics.error(draft.block_sources[j].vertices_at, "blocks",
                        fmt::format("found more than {} pairs of overlapping blocks (the first {} "
                                    "are listed); expected blocks that touch at most along edges "
                                    "or at vertices",
                                    kMostOverlapsReported, kMostOverlapsReported));
      break;
    }
    const BlockSource& later = draft.block_sources[j];
    diagnostics.error(later.vertices_at, later.path + ".vertices",
                      fmt::format("found block '{}' overlapping block '{}' ({}, line {}); expected "
                                  "blocks that touch at most along edges or at vertices",
                                  blocks[j].name, blocks[i].name, draft.block_sources[i].path,
                                  draft.block_sources[i].vertices_at.line));
  }
  return tolerance;
}

}  // namespace fissure
