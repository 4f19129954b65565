// Named points of a model that the pictures mark (docs/output.md, "/mesh"):
// the scene's monitors, and the points each process marks as its own. Each
// writes its own into results.h5:/mesh/markers/<group> with the first frame:
// `names`, `points` (n x 2, m, where they are at the start) and the attribute
// `kind`.
#pragma once

#include <string>
#include <vector>

#include "core/geometry/vec2.h"
#include "core/io/results_part.h"
#include "core/scene/scene.h"

namespace fissure {

struct PointMarkers {
  std::string group;  ///< its group in /mesh/markers, named by its writer
  std::string kind;   ///< what one point is, as its writer names it
  std::vector<std::string> names;
  std::vector<Vec2> points;
};

/// Writes `markers` into /mesh/markers/<group> (from a part's write_mesh);
/// nothing when there are none.
void write_point_markers(FrameWriter& frame, const PointMarkers& markers);

/// The scene's monitors (they belong to no process) as a results part of
/// their own: /mesh/markers/monitors.
class MonitorMarkers final : public ResultsPart {
 public:
  explicit MonitorMarkers(const std::vector<Monitor>& monitors);
  void write_mesh(FrameWriter& frame, const RockMass& state) override;
  std::size_t frame_bytes(const RockMass&) const override { return 0; }
  void write_frame(FrameWriter&, const RockMass&) override {}

 private:
  PointMarkers markers_;
};

}  // namespace fissure
