#include "thermal/convection/fracture_fluid_grid.h"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

#include "core/base/errors.h"

namespace fissure::thermal {

namespace {

/// Weights below this are zero (a wall node at a fluid node).
constexpr double kAtNode = 1e-9;

/// The mesh nodes of a block face with their parameter along the segment
/// (distance from node_a towards node_b), sorted by it.
std::vector<std::pair<double, int>> face_nodes(const ThermalMesh& mesh, const BlockFace& face,
                                               const Vec2& a, const Vec2& direction) {
  std::vector<std::pair<double, int>> out;
  if (face.block < 0 || face.edge < 0 || face.block >= static_cast<int>(mesh.edge_nodes.size()) ||
      face.edge >= static_cast<int>(mesh.edge_nodes[face.block].size()))
    return out;
  for (const int node : mesh.edge_nodes[face.block][face.edge])
    out.emplace_back((mesh.nodes[node] - a).dot(direction), node);
  std::sort(out.begin(), out.end());
  return out;
}

/// The wall trace of the piece [s0, s1] on a face's sorted nodes: the mesh
/// edge that holds its midpoint.
WallTrace trace_on(const std::vector<std::pair<double, int>>& nodes, double s0, double s1) {
  WallTrace w;
  const double mid = 0.5 * (s0 + s1);
  for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
    const auto& [p, np] = nodes[i];
    const auto& [q, nq] = nodes[i + 1];
    if (!(p <= mid && mid <= q) || !(q > p)) continue;
    w.nodes = {np, nq};
    const auto weights = [&](double s) {
      const double t = std::clamp((s - p) / (q - p), 0.0, 1.0);
      return std::array<double, 2>{1 - t, t};
    };
    w.at_from = weights(s0);
    w.at_to = weights(s1);
    return w;
  }
  return w;
}

}  // namespace

FluidGrid build_fluid_grid(const FractureGraph& graph, const ThermalMesh& mesh, double tolerance) {
  FluidGrid grid;
  grid.fluid_node_of_graph.resize(graph.n_nodes());
  for (int v = 0; v < graph.n_nodes(); ++v) {
    grid.fluid_node_of_graph[v] = v;
    grid.positions.push_back(graph.nodes[v]);
    grid.graph_node.push_back(v);
  }
  grid.first_piece.push_back(0);
  for (int s = 0; s < graph.n_segments(); ++s) {
    const FractureSegment& seg = graph.segments[s];
    const Vec2 &a = graph.nodes[seg.node_a], &b = graph.nodes[seg.node_b];
    const double length = (b - a).norm();
    if (!(length > tolerance)) {
      grid.first_piece.push_back(static_cast<int>(grid.pieces.size()));
      continue;
    }
    const Vec2 direction = (b - a) / length;
    const std::array<std::vector<std::pair<double, int>>, 2> faces = {
        face_nodes(mesh, seg.left, a, direction), face_nodes(mesh, seg.right, a, direction)};
    // The fluid nodes: both walls' nodes inside the segment (projected on
    // it: a face lies along its segment, up to where the blocks have moved
    // since the network was cut), and its ends.
    std::vector<double> at = {0, length};
    for (const auto& face : faces)
      for (const auto& [p, node] : face)
        if (p > tolerance && p < length - tolerance) at.push_back(p);
    std::sort(at.begin(), at.end());
    std::vector<double> kept = {0};
    for (const double p : at)
      if (p - kept.back() > tolerance && length - p > tolerance) kept.push_back(p);
    kept.push_back(length);
    std::vector<int> nodes = {grid.fluid_node_of_graph[seg.node_a]};
    for (std::size_t k = 1; k + 1 < kept.size(); ++k) {
      nodes.push_back(grid.n_nodes());
      grid.positions.push_back(a + kept[k] * direction);
      grid.graph_node.push_back(-1);
    }
    nodes.push_back(grid.fluid_node_of_graph[seg.node_b]);
    for (std::size_t k = 0; k + 1 < kept.size(); ++k) {
      FluidPiece piece;
      piece.segment = s;
      piece.from = nodes[k];
      piece.to = nodes[k + 1];
      piece.length = kept[k + 1] - kept[k];
      for (int side = 0; side < 2; ++side)
        piece.walls[side] = trace_on(faces[side], kept[k], kept[k + 1]);
      grid.pieces.push_back(piece);
    }
    grid.first_piece.push_back(static_cast<int>(grid.pieces.size()));
  }
  return grid;
}

std::vector<std::vector<int>> wall_nodes_at_fluid_nodes(const FluidGrid& grid,
                                                        const FractureGraph& graph,
                                                        const std::string& where) {
  std::vector<std::vector<int>> at(grid.n_nodes());
  const auto add = [&](int fluid_node, const WallTrace& w, const std::array<double, 2>& weight,
                       const FluidPiece& piece) {
    for (int k = 0; k < 2; ++k)
      if (weight[k] >= 1 - kAtNode) {
        at[fluid_node].push_back(w.nodes[k]);
        return;
      }
    const Vec2& x = grid.positions[fluid_node];
    const FractureSegment& seg = graph.segments[piece.segment];
    throw SceneError(fmt::format(
        "{}: found nusselt wall_temperature, but fracture segment {} from ({:g}, {:g}) to "
        "({:g}, {:g}) has no wall node on one side at ({:g}, {:g}) (the block meshes of its two "
        "sides do not match there); expected matching walls, or a number for nusselt",
        where, piece.segment, graph.nodes[seg.node_a].x(), graph.nodes[seg.node_a].y(),
        graph.nodes[seg.node_b].x(), graph.nodes[seg.node_b].y(), x.x(), x.y()));
  };
  for (const FluidPiece& piece : grid.pieces)
    for (const WallTrace& w : piece.walls) {
      if (!w.exists()) continue;
      add(piece.from, w, w.at_from, piece);
      add(piece.to, w, w.at_to, piece);
    }
  for (std::vector<int>& nodes : at) {
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  }
  return at;
}

}  // namespace fissure::thermal
