// What the flow process writes (docs/output.md): per frame its state on the
// fracture network, in "fractures/" of the frame and as fields of the
// "fractures" grid (node pressures and, with gravity, hydraulic heads;
// segment apertures and fluxes), and the monitor column m.p, the pressure at
// a monitor read off the network (fracture_pressure.h).
#pragma once

#include "core/io/monitor_source.h"
#include "core/io/point_markers.h"
#include "core/io/results_part.h"
#include "flow/cubic_law/hydraulic_head.h"

namespace fissure::flow {

class FlowResults final : public ResultsPart {
 public:
  /// `wells` are marked on the pictures (/mesh/markers/flow_wells).
  explicit FlowResults(HeadDefinition head, PointMarkers wells = {})
      : head_(head), wells_(std::move(wells)) {}
  void write_mesh(FrameWriter& frame, const RockMass& state) override;
  std::size_t frame_bytes(const RockMass& state) const override;
  void write_frame(FrameWriter& frame, const RockMass& state) override;

 private:
  HeadDefinition head_;
  PointMarkers wells_;
};

class PressureMonitors final : public MonitorSource {
 public:
  std::vector<MonitorColumn> columns() const override { return {{"p", 1, true}}; }
  void values(const RockMass& state, int point, std::span<double> out) const override;
  std::string why_missing(const RockMass& state, int point, std::string_view column) const override;
};

}  // namespace fissure::flow
