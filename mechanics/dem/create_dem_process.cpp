#include "mechanics/dem/create_dem_process.h"

#include <fmt/format.h>

#include "core/base/errors.h"
#include "mechanics/dem/dem_process.h"

namespace fissure::dem {

namespace {

/// What the DEM cannot take from a scene, refused before anything runs: a
/// rounding longer than a block's edge (its corners' arcs would meet), and
/// fixed points (the DEM holds whole blocks: blocks[].fixed).
void check_scene(const Scene& scene) {
  const DemControls& c = section_settings(scene, kDemSettings);
  if (c.rounding)
    for (const BlockSpec& b : scene.blocks)
      for (int v = 0; v < b.polygon.n_vertices(); ++v) {
        const double edge = (b.polygon.vertices[b.polygon.next(v)] - b.polygon.vertices[v]).norm();
        const SourceLocation& at = c.rounding_location;
        FISSURE_CHECK(*c.rounding < edge, SceneError,
                      fmt::format("{}:{}:{}: dem.rounding: found {:.4g} m, longer than edge {} of "
                                  "block '{}' ({:.4g} m); expected a rounding shorter than every "
                                  "edge (UDEC: about 1 % of the blocks' size)",
                                  at.file, at.line, at.column, *c.rounding, v, b.name, edge));
      }
  FISSURE_CHECK(scene.fixed_points.empty(), SceneError,
                scene.source.string()
                    << ": fixed_points: found " << scene.fixed_points.size()
                    << "; the DEM holds whole blocks: expected `fixed: true` on the blocks to "
                       "hold (docs/dem.md section 4)");
}

}  // namespace

std::unique_ptr<Process> create_dem_process(const Scene& scene) {
  check_scene(scene);
  return std::make_unique<DemProcess>(scene);
}

}  // namespace fissure::dem
