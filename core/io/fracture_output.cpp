#include "core/io/fracture_output.h"

#include <fmt/format.h>

#include <utility>
#include <vector>

#include "core/geometry/network_connectivity.h"

namespace fissure {

void write_fracture_mesh(Hdf5File& h5, const Hdf5Group& mesh, const FractureGraph& graph) {
  const hsize_t nn = static_cast<hsize_t>(graph.n_nodes());
  const hsize_t ns = static_cast<hsize_t>(graph.n_segments());
  std::vector<double> nodes;
  nodes.reserve(2 * nn);
  for (const Vec2& p : graph.nodes) {
    nodes.push_back(p.x());
    nodes.push_back(p.y());
  }
  std::vector<int> segments, set, fracture, left, right;
  std::vector<double> aperture, length;
  std::vector<std::pair<int, int>> ends;
  for (int s = 0; s < graph.n_segments(); ++s) {
    const FractureSegment& f = graph.segments[s];
    segments.push_back(f.node_a);
    segments.push_back(f.node_b);
    ends.emplace_back(f.node_a, f.node_b);
    set.push_back(f.joint_set);
    fracture.push_back(f.fracture);
    left.push_back(f.left.block);
    right.push_back(f.right.block);
    aperture.push_back(f.aperture);
    length.push_back(graph.length(s));
  }
  const NetworkConnectivity c = analyze_connectivity(graph.n_nodes(), ends, graph.boundary_nodes);
  const std::vector<int> dead_end(c.dead_end.begin(), c.dead_end.end());

  const Hdf5Group g = h5.create_group(mesh, "fractures");
  h5.write(g, "nodes", nodes, {nn, 2});
  h5.write(g, "segments", segments, {ns, 2});
  h5.write(g, "aperture", aperture, {ns});
  h5.write(g, "length", length, {ns});
  h5.write(g, "set", set, {ns});
  h5.write(g, "fracture", fracture, {ns});
  h5.write(g, "left_block", left, {ns});
  h5.write(g, "right_block", right, {ns});
  h5.write(g, "component", c.segment_component, {ns});
  h5.write(g, "dead_end", dead_end, {ns});
  if (!graph.set_names.empty()) h5.write_strings(g, "set_names", graph.set_names);
  const Hdf5Group b = h5.create_group(g, "boundaries");
  for (const auto& [name, list] : graph.boundary_nodes)
    h5.write(b, name, list, {static_cast<hsize_t>(list.size())});
}

std::string fracture_grid_xml(const std::string& h5_name, int n_nodes, int n_segments) {
  const std::string f = h5_name + ":/mesh/fractures/";
  auto item = [](const std::string& dims, bool real, const std::string& path) {
    return fmt::format("<DataItem Dimensions=\"{}\" NumberType=\"{}\" Precision=\"{}\" "
                       "Format=\"HDF\">{}</DataItem>",
                       dims, real ? "Float" : "Int", real ? 8 : 4, path);
  };
  const std::string cells = std::to_string(n_segments);
  std::string xml = fmt::format(
      "        <Grid Name=\"fractures\" GridType=\"Uniform\">\n"
      "          <Topology TopologyType=\"Polyline\" NumberOfElements=\"{}\" "
      "NodesPerElement=\"2\">\n"
      "            {}\n"
      "          </Topology>\n"
      "          <Geometry GeometryType=\"XY\">\n"
      "            {}\n"
      "          </Geometry>\n",
      n_segments, item(cells + " 2", false, f + "segments"),
      item(fmt::format("{} 2", n_nodes), true, f + "nodes"));
  for (const char* name : {"aperture", "length"})
    xml += fmt::format(
        "          <Attribute Name=\"{}\" AttributeType=\"Scalar\" Center=\"Cell\">\n"
        "            {}\n"
        "          </Attribute>\n",
        name, item(cells, true, f + name));
  for (const char* name : {"set", "fracture", "component", "dead_end"})
    xml += fmt::format(
        "          <Attribute Name=\"{}\" AttributeType=\"Scalar\" Center=\"Cell\">\n"
        "            {}\n"
        "          </Attribute>\n",
        name, item(cells, false, f + name));
  xml += "        </Grid>\n";
  return xml;
}

}  // namespace fissure
