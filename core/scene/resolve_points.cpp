// Attaches fixed points, load points and monitors to blocks: to the block
// they name (the point must be inside it or on its boundary), or else to the
// one block that contains them (locate_point; the boundary counts).
#include <fmt/format.h>

#include "core/geometry/polygon_checks.h"
#include "core/scene/scene_draft.h"

namespace fissure {

namespace {

using Owner = PointToResolve::Owner;

int& target_block(Scene& scene, const PointToResolve& p) {
  switch (p.owner) {
    case Owner::FixedPoint:
      return scene.fixed_points[p.index].block;
    case Owner::PointLoad:
      return scene.point_loads[p.index].block;
    case Owner::Monitor:
      break;
  }
  return scene.monitors[p.index].block;
}

std::string format_point(const Vec2& p) {
  return fmt::format("({}, {})", p.x(), p.y());
}

/// The point names its block.
void resolve_named(SceneDraft& draft, const PointToResolve& p, double tolerance,
                   Diagnostics& diagnostics) {
  if (!p.block) return;  // an unreadable name, already reported
  int& block = target_block(draft.scene, p);
  if (p.owner == Owner::Monitor && *p.block == "none") {
    block = -1;  // fixed in space
    return;
  }
  const std::optional<int> i = draft.blocks.resolve(*p.block_node);
  if (!i || *i >= static_cast<int>(draft.scene.blocks.size())) return;
  block = *i;
  // Without a point or a valid polygon there is nothing more to check (both
  // are reported already).
  if (!p.point || !draft.block_sources[*i].polygon_valid) return;
  const BlockSpec& spec = draft.scene.blocks[*i];
  if (locate_point(spec.polygon, *p.point, tolerance) < 0)
    diagnostics.error(p.point_at, p.path + ".point",
                      fmt::format("found {}, which is outside block '{}'; expected a point "
                                  "inside block '{}' or on its boundary",
                                  format_point(*p.point), spec.name, spec.name));
}

/// The point names no block: the one block that contains it.
void resolve_by_location(SceneDraft& draft, const PointToResolve& p, double tolerance,
                         Diagnostics& diagnostics) {
  const std::vector<BlockSpec>& blocks = draft.scene.blocks;
  std::vector<int> hits;
  bool all_checked = !blocks.empty();
  for (size_t i = 0; i < blocks.size(); ++i) {
    if (!draft.block_sources[i].polygon_valid) {
      all_checked = false;
      continue;
    }
    if (locate_point(blocks[i].polygon, *p.point, tolerance) >= 0)
      hits.push_back(static_cast<int>(i));
  }
  if (hits.size() == 1) {
    target_block(draft.scene, p) = hits.front();
    return;
  }
  const std::string where = p.path + ".point";
  if (hits.empty()) {
    // With a block left unchecked the point might be on it: no guess.
    if (!all_checked) return;
    diagnostics.error(
        p.point_at, where,
        fmt::format(
            "found {}, which is outside every block; expected a point "
            "inside a block or on its boundary{}",
            format_point(*p.point),
            p.owner == Owner::Monitor ? ", or `block: none` for a monitor fixed in space" : ""));
    return;
  }
  std::string names;
  for (size_t k = 0; k < hits.size(); ++k)
    names += (k == 0 ? "'" : k + 1 == hits.size() ? " and '" : ", '") + blocks[hits[k]].name + "'";
  diagnostics.error(p.point_at, where,
                    fmt::format("found {}, which lies on blocks {}; expected `block:` naming "
                                "the one it belongs to",
                                format_point(*p.point), names));
}

}  // namespace

void resolve_points(SceneDraft& draft, double tolerance, Diagnostics& diagnostics) {
  for (const PointToResolve& p : draft.points) {
    if (p.block_node)
      resolve_named(draft, p, tolerance, diagnostics);
    else if (p.point)
      resolve_by_location(draft, p, tolerance, diagnostics);
  }
}

}  // namespace fissure
