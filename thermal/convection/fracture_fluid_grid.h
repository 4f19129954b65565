// Where the fracture water's temperature lives (docs/thermal.md 7): nodes
// along every segment of the fracture graph, at the wall nodes of the block
// meshes on both of its sides (their union), so that the water exchanges
// heat with each wall through the wall's own P1 trace and the energy the
// water gives is exactly the energy the walls receive. One node per graph
// node is shared by the segments that meet there (mixing).
#pragma once

#include <array>
#include <vector>

#include "core/geometry/vec2.h"
#include "rockmass/fracture_graph.h"
#include "thermal/conduction/thermal_mesh.h"

namespace fissure::thermal {

/// A wall's temperature along a piece of a segment: linear between two wall
/// mesh nodes, T_w(from) = at_from . T(nodes), T_w(to) = at_to . T(nodes).
struct WallTrace {
  std::array<int, 2> nodes = {-1, -1};  ///< mesh nodes; -1: no wall on this side
  std::array<double, 2> at_from = {0, 0}, at_to = {0, 0};
  bool exists() const { return nodes[0] >= 0; }
};

/// A piece of a segment between two consecutive fluid nodes, in the
/// segment's direction (node_a -> node_b).
struct FluidPiece {
  int segment = -1;
  int from = -1, to = -1;          ///< fluid nodes
  double length = 0;               ///< m
  std::array<WallTrace, 2> walls;  ///< left, right of node_a -> node_b
};

struct FluidGrid {
  std::vector<Vec2> positions;           ///< per fluid node (reference geometry)
  std::vector<int> graph_node;           ///< per fluid node: its graph node, or -1
  std::vector<int> fluid_node_of_graph;  ///< per graph node
  std::vector<FluidPiece> pieces;        ///< segment by segment
  std::vector<int> first_piece;          ///< per segment + 1: its pieces
  int n_nodes() const { return static_cast<int>(positions.size()); }
};

/// The fluid grid of `graph` on the walls of `mesh` (points closer than
/// `tolerance` m are the same). Segments with no block face on a side have
/// no wall there; a segment with none on either side is one piece.
FluidGrid build_fluid_grid(const FractureGraph& graph, const ThermalMesh& mesh, double tolerance);

/// The wall-temperature limit (h -> infinity): per fluid node, the wall mesh
/// nodes at its place (the fluid and they become one unknown). Throws
/// SceneError (with `where`) when a wall has no node at a fluid node (the two
/// sides' nodes do not match).
std::vector<std::vector<int>> wall_nodes_at_fluid_nodes(const FluidGrid& grid,
                                                        const FractureGraph& graph,
                                                        const std::string& where);

}  // namespace fissure::thermal
