#include "flow/cubic_law/fracture_pressure.h"

#include <algorithm>
#include <limits>

#include "rockmass/fields/fracture_flow.h"

namespace fissure {

SegmentProjection nearest_segment(const FractureGraph& graph, const Vec2& x) {
  SegmentProjection best;
  best.distance = std::numeric_limits<double>::infinity();
  for (int k = 0; k < graph.n_segments(); ++k) {
    const Vec2& a = graph.nodes[graph.segments[k].node_a];
    const Vec2 d = graph.nodes[graph.segments[k].node_b] - a;
    const double length2 = d.squaredNorm();
    const double s = length2 > 0 ? std::clamp((x - a).dot(d) / length2, 0.0, 1.0) : 0.0;
    const double distance = (a + s * d - x).norm();
    if (distance < best.distance) best = {k, s, distance};
  }
  return best;
}

double pressure_search_distance(const FractureGraph& graph) {
  if (graph.nodes.empty()) return 0;
  Vec2 lo = graph.nodes.front(), hi = lo;
  for (const Vec2& p : graph.nodes) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return kPressureSearchFraction * (hi - lo).maxCoeff();
}

double fracture_pressure_at(const RockMass& state, const Vec2& x) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const FractureGraph* graph = state.fields.find(kFractureGraph);
  const FractureFlowState* flow = state.fields.find(kFractureFlow);
  if (!graph || !flow) return kNaN;
  const FractureGraph& g = *graph;
  const std::vector<double>& p = flow->pressure;
  if (g.n_segments() == 0 || static_cast<int>(p.size()) != g.n_nodes()) return kNaN;
  const SegmentProjection near = nearest_segment(g, x);
  if (!(near.distance <= pressure_search_distance(g))) return kNaN;
  const FractureSegment& seg = g.segments[near.segment];
  return (1 - near.s) * p[seg.node_a] + near.s * p[seg.node_b];
}

}  // namespace fissure
