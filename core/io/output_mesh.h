// The block topology written once to results.h5:/mesh (private to core/io).
// Blocks move and deform but keep their vertices for the whole run, so one
// global vertex array (every block's vertices, block after block) and one
// triangulation of the initial polygons serve every frame.
#pragma once

#include <string>
#include <vector>

#include "core/state/rock_mass.h"

namespace fissure {

struct OutputMesh {
  std::vector<std::string> block_names;
  std::vector<int> block_material;
  std::vector<int> block_fixed;           ///< 1 for fixed blocks
  std::vector<int> block_vertex_offsets;  ///< n_blocks + 1, into the global vertex array
  std::vector<int> block_loop_offsets;    ///< n_blocks + 1, into loop_offsets
  std::vector<int> loop_offsets;          ///< n_loops + 1, global vertex indices
  std::vector<double> initial_vertices;   ///< n_vertices x 2
  std::vector<int> triangles;             ///< n_triangles x 3, global vertex indices, CCW
  std::vector<int> triangle_block;        ///< n_triangles

  int n_blocks() const { return static_cast<int>(block_names.size()); }
  int n_vertices() const { return block_vertex_offsets.back(); }
  int n_triangles() const { return static_cast<int>(triangle_block.size()); }
};

/// Builds the mesh from the blocks' initial geometry. Throws IoError when a
/// block is inconsistent (vertex and initial-vertex counts differ) or cannot be
/// triangulated.
OutputMesh build_output_mesh(const RockMass& state);

/// Empty when `state` has the mesh's topology (same blocks, same loops of the
/// same lengths); otherwise says what changed.
std::string topology_mismatch(const OutputMesh& mesh, const RockMass& state);

}  // namespace fissure
