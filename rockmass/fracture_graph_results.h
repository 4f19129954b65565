// The fracture graph in results.h5 and results.xdmf (docs/output.md,
// "/mesh/fractures" and "fractures/" of a frame): written whenever the
// shared state has a graph (generated with the rock mass, or built by the
// flow process), whichever processes run. The graph is written once, with
// the block mesh; a frame whose graph is not that one (rebuilt, or moved)
// gets its own nodes and segments instead of a wrong picture. Each frame's
// "fractures" grid shows the network as two-node polylines; the flow
// process adds its fields to that grid.
#pragma once

#include <vector>

#include "core/io/results_part.h"

namespace fissure {

class FractureGraphResults final : public ResultsPart {
 public:
  void write_mesh(FrameWriter& frame, const RockMass& state) override;
  void restore_mesh(const RockMass& state) override;
  std::size_t frame_bytes(const RockMass& state) const override;
  void write_frame(FrameWriter& frame, const RockMass& state) override;

 private:
  /// The graph in /mesh/fractures (empty: none).
  std::vector<double> mesh_nodes_;
  std::vector<int> mesh_segments_;
};

}  // namespace fissure
