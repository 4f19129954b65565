// The blocks in results.h5 / results.xdmf (docs/output.md "/mesh" and
// "/frames"; private to core/io): the block topology once, in /mesh, and per
// frame the current vertices, displacements, velocities and block stresses,
// as the "blocks" grid (triangles). Always the first part of a frame.
#pragma once

#include <optional>

#include "core/io/output_mesh.h"
#include "core/io/results_part.h"

namespace fissure {

class BlockResults final : public ResultsPart {
 public:
  void write_mesh(FrameWriter& frame, const RockMass& state) override;
  void restore_mesh(const RockMass& state) override;
  std::size_t frame_bytes(const RockMass& state) const override;
  void write_frame(FrameWriter& frame, const RockMass& state) override;

 private:
  std::optional<OutputMesh> mesh_;  ///< the block topology, fixed at the first frame
};

}  // namespace fissure
