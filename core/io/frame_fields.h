// The block fields of one output frame, laid out on the output mesh as they
// are written to results.h5:/frames/NNNNNN (private to core/io). Vectors get
// a zero z component so that ParaView treats them as vectors.
#pragma once

#include <vector>

#include "core/io/output_mesh.h"
#include "core/state/rock_mass.h"

namespace fissure {

struct FrameFields {
  std::vector<double> vertices;       ///< n_vertices x 2, current positions (m)
  std::vector<double> displacement;   ///< n_vertices x 3, current - initial (m)
  std::vector<double> velocity;       ///< n_vertices x 3 (m/s)
  std::vector<double> sxx, syy, sxy;  ///< per triangle, the block's stress (Pa)
  std::vector<int> block_id;          ///< per triangle
};

/// The mesh must match the state's topology (topology_mismatch is empty).
FrameFields gather_frame_fields(const OutputMesh& mesh, const RockMass& state);

}  // namespace fissure
