#include "flow/cubic_law/flow_results.h"

#include <fmt/format.h>

#include "flow/cubic_law/fracture_pressure.h"
#include "rockmass/fields/fracture_flow.h"
#include "rockmass/fracture_graph.h"

namespace fissure::flow {

namespace {

/// The flow state when it belongs to the state's graph (sizes match); null
/// otherwise (no graph, or the state of another graph: nothing to draw it on).
const FractureFlowState* flow_on_graph(const RockMass& state, const FractureGraph*& graph) {
  graph = state.fields.find(kFractureGraph);
  const FractureFlowState* flow = state.fields.find(kFractureFlow);
  if (!graph || !flow) return nullptr;
  const std::size_t n = graph->nodes.size(), m = graph->segments.size();
  const bool matches = m > 0 && flow->pressure.size() == n && flow->aperture_a.size() == m &&
                       flow->aperture_b.size() == m && flow->flux.size() == m;
  return matches ? flow : nullptr;
}

}  // namespace

void FlowResults::write_mesh(FrameWriter& frame, const RockMass&) {
  write_point_markers(frame, wells_);
}

std::size_t FlowResults::frame_bytes(const RockMass& state) const {
  const FractureGraph* graph = nullptr;
  if (!flow_on_graph(state, graph)) return 0;
  return 8 * 2 * graph->nodes.size() + 8 * 4 * graph->segments.size();
}

void FlowResults::write_frame(FrameWriter& frame, const RockMass& state) {
  const FractureGraph* graph = nullptr;
  const FractureFlowState* flow = flow_on_graph(state, graph);
  if (!flow) return;
  const std::size_t n = graph->nodes.size(), m = graph->segments.size();
  std::vector<double> head, aperture_mean;
  if (head_.active()) {
    head.reserve(n);
    for (std::size_t v = 0; v < n; ++v)
      head.push_back(head_.head(flow->pressure[v], graph->nodes[v]));
  }
  aperture_mean.reserve(m);
  for (std::size_t s = 0; s < m; ++s)
    aperture_mean.push_back(0.5 * (flow->aperture_a[s] + flow->aperture_b[s]));

  Hdf5File& h5 = frame.h5();
  const Hdf5Group& g = frame.frame_group("fractures");
  const hsize_t nn = static_cast<hsize_t>(n), ns = static_cast<hsize_t>(m);
  h5.write(g, "pressure", flow->pressure, {nn});
  if (!head.empty()) h5.write(g, "head", head, {nn});
  h5.write(g, "aperture_a", flow->aperture_a, {ns});
  h5.write(g, "aperture_b", flow->aperture_b, {ns});
  h5.write(g, "aperture_mean", aperture_mean, {ns});
  h5.write(g, "flux", flow->flux, {ns});

  // Its fields on the "fractures" grid (whose cells the fracture graph gives).
  XdmfGrid& grid = frame.grid("fractures");
  const std::string at = g.path + "/";
  const std::string nodes = std::to_string(n), cells = std::to_string(m);
  constexpr auto Float = XdmfNumber::Float64;
  grid.frame_attributes.push_back(xdmf_attribute("pressure", "Scalar", "Node", nodes, Float,
                                                 frame.xdmf_path(at + "pressure"), "Pa"));
  if (!head.empty())
    grid.frame_attributes.push_back(
        xdmf_attribute("head", "Scalar", "Node", nodes, Float, frame.xdmf_path(at + "head"), "m"));
  for (const auto& [name, unit] : {std::pair{"aperture_a", "m"},
                                   {"aperture_b", "m"},
                                   {"aperture_mean", "m"},
                                   {"flux", "m^2/s"}})
    grid.frame_attributes.push_back(
        xdmf_attribute(name, "Scalar", "Cell", cells, Float, frame.xdmf_path(at + name), unit));
}

void PressureMonitors::values(const RockMass& state, int point, std::span<double> out) const {
  out[0] = fracture_pressure_at(state, state.points[point].current);
}

std::string PressureMonitors::why_missing(const RockMass& state, int, std::string_view) const {
  const FractureGraph* graph = state.fields.find(kFractureGraph);
  const double distance = graph ? pressure_search_distance(*graph) : 0.0;
  return fmt::format(
      "is not on the fracture network (no segment within {:g} m, {:g} x the network's size)",
      distance, kPressureSearchFraction);
}

}  // namespace fissure::flow
