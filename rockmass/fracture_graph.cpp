#include "rockmass/fracture_graph.h"

#include <cmath>

namespace fissure {

void FractureGraph::add_box_sides(const Vec2& lo, const Vec2& hi, double tol) {
  auto& left = boundary_nodes["left"];
  auto& right = boundary_nodes["right"];
  auto& bottom = boundary_nodes["bottom"];
  auto& top = boundary_nodes["top"];
  for (int v = 0; v < n_nodes(); ++v) {
    const Vec2& x = nodes[v];
    if (std::abs(x.x() - lo.x()) <= tol) left.push_back(v);
    if (std::abs(x.x() - hi.x()) <= tol) right.push_back(v);
    if (std::abs(x.y() - lo.y()) <= tol) bottom.push_back(v);
    if (std::abs(x.y() - hi.y()) <= tol) top.push_back(v);
  }
}

}  // namespace fissure
