#include "rockmass/block_motion.h"

#include <Eigen/Dense>

namespace fissure {

BlockReference initial_geometry(const std::vector<Block>& blocks) {
  BlockReference reference(blocks.size());
  for (std::size_t b = 0; b < blocks.size(); ++b) reference[b] = blocks[b].initial_vertices;
  return reference;
}

std::vector<BlockMap> block_maps(const std::vector<Block>& blocks,
                                 const BlockReference& reference) {
  std::vector<BlockMap> maps(blocks.size());
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const Block& block = blocks[b];
    const std::vector<Vec2>& from = reference[b];
    if (block.fixed || from.size() != block.polygon.vertices.size()) continue;
    // Least squares for [A | c] about the reference centroid of the vertices
    // (centred coordinates keep the normal equations well conditioned).
    const int n = static_cast<int>(from.size());
    Vec2 x0 = Vec2::Zero(), y0 = Vec2::Zero();
    for (int k = 0; k < n; ++k) x0 += from[k], y0 += block.polygon.vertices[k];
    x0 /= n;
    y0 /= n;
    Eigen::Matrix2d xx = Eigen::Matrix2d::Zero(), yx = Eigen::Matrix2d::Zero();
    for (int k = 0; k < n; ++k) {
      const Vec2 dx = from[k] - x0, dy = block.polygon.vertices[k] - y0;
      xx += dx * dx.transpose();
      yx += dy * dx.transpose();
    }
    maps[b].a = yx * xx.inverse();
    maps[b].c = y0 - maps[b].a * x0;
  }
  return maps;
}

}  // namespace fissure
