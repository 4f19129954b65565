#include "core/io/point_markers.h"

namespace fissure {

void write_point_markers(FrameWriter& frame, const PointMarkers& markers) {
  if (markers.points.empty()) return;
  Hdf5File& h5 = frame.h5();
  const Hdf5Group all = h5.exists(frame.mesh(), "markers")
                            ? h5.open_group(frame.mesh(), "markers")
                            : h5.create_group(frame.mesh(), "markers");
  const Hdf5Group g = h5.create_group(all, markers.group);
  std::vector<double> xy;
  xy.reserve(2 * markers.points.size());
  for (const Vec2& p : markers.points) xy.insert(xy.end(), {p.x(), p.y()});
  h5.write_strings(g, "names", markers.names);
  h5.write(g, "points", xy, {markers.points.size(), 2});
  h5.write_attribute(g, "kind", markers.kind);
}

MonitorMarkers::MonitorMarkers(const std::vector<Monitor>& monitors) {
  markers_.group = "monitors";
  markers_.kind = "monitor";
  for (const Monitor& m : monitors) {
    markers_.names.push_back(m.name);
    markers_.points.push_back(m.point);
  }
}

void MonitorMarkers::write_mesh(FrameWriter& frame, const RockMass&) {
  write_point_markers(frame, markers_);
}

}  // namespace fissure
