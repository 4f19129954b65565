#include "flow/network/boundary_conditions.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "core/base/errors.h"
#include "core/geometry/segment_predicates.h"

namespace fissure::flow {

namespace {

using Type = FlowBoundaryCondition::Type;

std::string boundary_list(const FractureGraph& graph) {
  std::ostringstream s;
  bool first = true;
  for (const auto& [name, nodes] : graph.boundary_nodes) {
    if (nodes.empty()) continue;
    s << (first ? "" : ", ") << name << " (" << nodes.size() << " nodes)";
    first = false;
  }
  return first ? "none" : s.str();
}

const std::vector<int>* nodes_of(const FractureGraph& graph, const std::string& boundary) {
  const auto it = graph.boundary_nodes.find(boundary);
  return it == graph.boundary_nodes.end() || it->second.empty() ? nullptr : &it->second;
}

bool fixes_pressure(const FlowBoundaryCondition& c) {
  return c.type != Type::Flux;
}

}  // namespace

void check_condition_boundaries(const FractureGraph& graph,
                                std::span<const FlowBoundaryCondition> conditions) {
  std::ostringstream problems;
  for (const FlowBoundaryCondition& c : conditions)
    if (!nodes_of(graph, c.boundary))
      problems << c.path << ".boundary: found '" << c.boundary
               << "', which holds no node of the fracture network (no fracture reaches it); "
                  "expected one of the network's boundaries: "
               << boundary_list(graph) << "\n";
  const std::string text = problems.str();
  FISSURE_CHECK(text.empty(), SceneError, text.substr(0, text.size() - 1));
}

int locate_well(FractureGraph& graph, const FlowWell& well, double tolerance) {
  const Vec2 p = well.point;
  int best_node = -1;
  double best = 1e300;
  for (int v = 0; v < graph.n_nodes(); ++v) {
    const double d = (graph.nodes[v] - p).norm();
    if (d < best) best = d, best_node = v;
  }
  if (best_node >= 0 && best <= tolerance) return best_node;
  int best_segment = -1;
  double best_d = 1e300;
  for (int s = 0; s < graph.n_segments(); ++s) {
    const FractureSegment& seg = graph.segments[s];
    const double d = point_segment_distance(p, graph.nodes[seg.node_a], graph.nodes[seg.node_b]);
    if (d < best_d) best_d = d, best_segment = s;
  }
  FISSURE_CHECK(best_segment >= 0 && best_d <= tolerance, SceneError,
                well.path << ".point: found (" << p.x() << ", " << p.y() << "), "
                          << (best_segment < 0
                                  ? std::string("but the network has no fracture")
                                  : "at " + std::to_string(best_d) + " m from the nearest fracture")
                          << "; expected a point on a fracture (within " << tolerance << " m)");
  // Split the segment at the foot of the perpendicular.
  FractureSegment& seg = graph.segments[best_segment];
  const Vec2 a = graph.nodes[seg.node_a], b = graph.nodes[seg.node_b];
  const double t = closest_parameter(p, a, b);
  const int node = graph.n_nodes();
  graph.nodes.push_back(a + t * (b - a));
  FractureSegment second = seg;
  second.node_a = node;
  seg.node_b = node;
  graph.segments.push_back(second);
  return node;
}

NodeConditions resolve_conditions(const FractureGraph& graph,
                                  std::span<const FlowBoundaryCondition> conditions,
                                  std::span<const FlowWell> wells, std::span<const int> well_nodes,
                                  const FluidProperties& fluid, const Vec2& gravity, double t) {
  NodeConditions nc(graph.n_nodes());
  const double g = gravity.norm();
  for (const FlowBoundaryCondition& c : conditions) {
    const std::vector<int>* nodes = nodes_of(graph, c.boundary);
    if (!nodes) continue;  // reported by check_condition_boundaries
    const double value = c.value * history_factor(c.history, t);
    for (int v : *nodes) {
      switch (c.type) {
        case Type::Pressure:
          nc.fixed_pressure[v] = value;
          break;
        case Type::Head:
          nc.fixed_pressure[v] =
              fluid.density * g * value + hydrostatic_offset(fluid, gravity, graph.nodes[v]);
          break;
        case Type::Flux:
          nc.source[v] += value / static_cast<double>(nodes->size());
          break;
      }
    }
  }
  for (std::size_t w = 0; w < wells.size(); ++w)
    nc.source[well_nodes[w]] += wells[w].rate * history_factor(wells[w].history, t);
  return nc;
}

void check_pressure_boundaries_connected(const FractureGraph& graph,
                                         std::span<const FlowBoundaryCondition> conditions,
                                         std::span<const int> component) {
  // Components touched by each fixed-pressure condition.
  std::vector<std::set<int>> touched;
  std::vector<const FlowBoundaryCondition*> fixed;
  for (const FlowBoundaryCondition& c : conditions) {
    const std::vector<int>* nodes = nodes_of(graph, c.boundary);
    if (!fixes_pressure(c) || !nodes) continue;
    std::set<int> comps;
    for (int v : *nodes)
      if (component[v] >= 0) comps.insert(component[v]);
    touched.push_back(std::move(comps));
    fixed.push_back(&c);
  }
  if (fixed.size() < 2) return;
  for (std::size_t i = 0; i < fixed.size(); ++i)
    for (std::size_t j = i + 1; j < fixed.size(); ++j)
      for (int c : touched[i])
        if (touched[j].count(c)) return;
  // Located at the first condition (a scene error starts with its place);
  // the others are named with theirs.
  std::ostringstream names;
  for (std::size_t i = 0; i < fixed.size(); ++i)
    names << (i == 0                  ? ""
              : i + 1 == fixed.size() ? " and "
                                      : ", ")
          << "'" << fixed[i]->boundary << "'" << (i == 0 ? "" : " (" + fixed[i]->path + ")");
  FISSURE_CHECK(
      false, SceneError,
      fixed[0]->path << ": the fracture network does not connect the pressure boundaries "
                     << names.str()
                     << ": no fracture path joins any two of them, so no flow can cross the "
                        "model; expected a connected (percolating) network, or other boundaries");
}

}  // namespace fissure::flow
