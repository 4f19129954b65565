#include "rockmass/fracture_graph_results.h"

#include <utility>
#include <vector>

#include "core/geometry/network_connectivity.h"
#include "rockmass/fracture_graph.h"

namespace fissure {

namespace {

hsize_t size(std::size_t n) {
  return static_cast<hsize_t>(n);
}

std::vector<double> node_coordinates(const FractureGraph& graph) {
  std::vector<double> nodes;
  nodes.reserve(2 * graph.nodes.size());
  for (const Vec2& p : graph.nodes) nodes.insert(nodes.end(), {p.x(), p.y()});
  return nodes;
}

std::vector<int> segment_nodes(const FractureGraph& graph) {
  std::vector<int> segments;
  segments.reserve(2 * graph.segments.size());
  for (const FractureSegment& s : graph.segments)
    segments.insert(segments.end(), {s.node_a, s.node_b});
  return segments;
}

/// The state's graph; null when it has none, or none with segments.
const FractureGraph* graph_of(const RockMass& state) {
  const FractureGraph* g = state.fields.find(kFractureGraph);
  return g && g->n_segments() > 0 ? g : nullptr;
}

}  // namespace

void FractureGraphResults::restore_mesh(const RockMass& state) {
  if (const FractureGraph* graph = graph_of(state)) {
    mesh_nodes_ = node_coordinates(*graph);
    mesh_segments_ = segment_nodes(*graph);
  }
}

void FractureGraphResults::write_mesh(FrameWriter& frame, const RockMass& state) {
  const FractureGraph* graph = graph_of(state);
  if (!graph) return;
  Hdf5File& h5 = frame.h5();
  const hsize_t nn = size(graph->nodes.size());
  const hsize_t ns = size(graph->segments.size());
  std::vector<int> set, fracture, left, right;
  std::vector<double> aperture, length;
  std::vector<std::pair<int, int>> ends;
  for (int s = 0; s < graph->n_segments(); ++s) {
    const FractureSegment& f = graph->segments[s];
    ends.emplace_back(f.node_a, f.node_b);
    set.push_back(f.joint_set);
    fracture.push_back(f.fracture);
    left.push_back(f.left.block);
    right.push_back(f.right.block);
    aperture.push_back(f.aperture);
    length.push_back(graph->length(s));
  }
  const NetworkConnectivity c = analyze_connectivity(graph->n_nodes(), ends, graph->boundary_nodes);
  const std::vector<int> dead_end(c.dead_end.begin(), c.dead_end.end());
  mesh_nodes_ = node_coordinates(*graph);
  mesh_segments_ = segment_nodes(*graph);

  const Hdf5Group g = h5.create_group(frame.mesh(), "fractures");
  h5.write(g, "nodes", mesh_nodes_, {nn, 2});
  h5.write(g, "segments", mesh_segments_, {ns, 2});
  h5.write(g, "aperture", aperture, {ns});
  h5.write(g, "length", length, {ns});
  h5.write(g, "set", set, {ns});
  h5.write(g, "fracture", fracture, {ns});
  h5.write(g, "left_block", left, {ns});
  h5.write(g, "right_block", right, {ns});
  h5.write(g, "component", c.segment_component, {ns});
  h5.write(g, "dead_end", dead_end, {ns});
  if (!graph->set_names.empty()) h5.write_strings(g, "set_names", graph->set_names);
  const Hdf5Group b = h5.create_group(g, "boundaries");
  for (const auto& [name, list] : graph->boundary_nodes)
    h5.write(b, name, list, {static_cast<hsize_t>(list.size())});
}

std::size_t FractureGraphResults::frame_bytes(const RockMass& state) const {
  const FractureGraph* graph = graph_of(state);
  return graph ? 8 * 2 * graph->nodes.size() + 4 * 2 * graph->segments.size() : 0;
}

void FractureGraphResults::write_frame(FrameWriter& frame, const RockMass& state) {
  const FractureGraph* graph = graph_of(state);
  if (!graph) return;
  std::vector<double> nodes = node_coordinates(*graph);
  std::vector<int> segments = segment_nodes(*graph);
  const bool same_graph =
      !mesh_segments_.empty() && nodes == mesh_nodes_ && segments == mesh_segments_;
  const std::string n = std::to_string(graph->n_nodes());
  const std::string cells = std::to_string(graph->n_segments());
  constexpr auto Float = XdmfNumber::Float64;
  constexpr auto Int = XdmfNumber::Int32;

  // The geometry: /mesh/fractures, or the frame's own.
  std::string geometry = "/mesh/fractures/";
  if (!same_graph) {
    Hdf5File& h5 = frame.h5();
    const Hdf5Group& g = frame.frame_group("fractures");
    h5.write(g, "nodes", nodes, {size(graph->nodes.size()), 2});
    h5.write(g, "segments", segments, {size(graph->segments.size()), 2});
    geometry = g.path + "/";
  }
  XdmfGrid& grid = frame.grid("fractures");
  grid.topology_type = "Polyline";
  grid.n_elements = graph->n_segments();
  grid.nodes_per_element = 2;
  grid.connectivity = xdmf_data_item(cells + " 2", Int, frame.xdmf_path(geometry + "segments"));
  grid.geometry = xdmf_data_item(n + " 2", Float, frame.xdmf_path(geometry + "nodes"));
  // The graph's fixed fields belong to the graph in /mesh/fractures only.
  if (same_graph) {
    for (const char* name : {"aperture", "length"})
      grid.mesh_attributes.push_back(xdmf_attribute(name, "Scalar", "Cell", cells, Float,
                                                    frame.xdmf_path(geometry + name), "m"));
    for (const char* name : {"set", "fracture", "component", "dead_end"})
      grid.mesh_attributes.push_back(xdmf_attribute(name, "Scalar", "Cell", cells, Int,
                                                    frame.xdmf_path(geometry + name), "-"));
  }
}

}  // namespace fissure
