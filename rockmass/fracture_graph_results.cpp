#include "core/io/fracture_output.h"

#include <fmt/format.h>

#include <utility>
#include <vector>

#include "core/geometry/network_connectivity.h"
#include "core/io/xdmf_items.h"

namespace fissure {

namespace {

hsize_t size(std::size_t n) {
  return static_cast<hsize_t>(n);
}

}  // namespace

void write_fracture_mesh(Hdf5File& h5, const Hdf5Group& mesh, const FractureGraph& graph) {
  const hsize_t nn = size(graph.nodes.size());
  const hsize_t ns = size(graph.segments.size());
  const FractureFields geometry = gather_fracture_geometry(graph);
  std::vector<int> set, fracture, left, right;
  std::vector<double> aperture, length;
  std::vector<std::pair<int, int>> ends;
  for (int s = 0; s < graph.n_segments(); ++s) {
    const FractureSegment& f = graph.segments[s];
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
  h5.write(g, "nodes", geometry.nodes, {nn, 2});
  h5.write(g, "segments", geometry.segments, {ns, 2});
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

XdmfFractures write_fracture_frame(Hdf5File& h5, const Hdf5Group& frame, const FractureFields& f,
                                   const std::string& mesh_group) {
  XdmfFractures where{f.n_nodes(), f.n_segments(), mesh_group, mesh_group, "", false};
  const bool with_geometry = mesh_group.empty();
  if (f.n_segments() == 0 || (!with_geometry && !f.flow)) return where;
  const hsize_t nn = size(f.n_nodes());
  const hsize_t ns = size(f.n_segments());
  const Hdf5Group g = h5.create_group(frame, "fractures");
  if (with_geometry) {
    h5.write(g, "nodes", f.nodes, {nn, 2});
    h5.write(g, "segments", f.segments, {ns, 2});
    where.geometry = g.path;
  }
  if (f.flow) {
    h5.write(g, "pressure", f.pressure, {nn});
    if (!f.head.empty()) h5.write(g, "head", f.head, {nn});
    h5.write(g, "aperture_a", f.aperture_a, {ns});
    h5.write(g, "aperture_b", f.aperture_b, {ns});
    h5.write(g, "aperture_mean", f.aperture_mean, {ns});
    h5.write(g, "flux", f.flux, {ns});
    where.flow = g.path;
    where.head = !f.head.empty();
  }
  return where;
}

std::string fracture_grid_xml(const std::string& h5_name, const XdmfFractures& where) {
  const std::string geometry = h5_name + ":" + where.geometry + "/";
  const std::string nodes = std::to_string(where.n_nodes);
  const std::string cells = std::to_string(where.n_segments);
  constexpr auto Float = XdmfNumber::Float64;
  constexpr auto Int = XdmfNumber::Int32;
  std::string xml = fmt::format(
      "        <Grid Name=\"fractures\" GridType=\"Uniform\">\n"
      "          <Topology TopologyType=\"Polyline\" NumberOfElements=\"{}\" "
      "NodesPerElement=\"2\">\n"
      "            {}\n"
      "          </Topology>\n"
      "          <Geometry GeometryType=\"XY\">\n"
      "            {}\n"
      "          </Geometry>\n",
      where.n_segments, xdmf_data_item(cells + " 2", Int, geometry + "segments"),
      xdmf_data_item(nodes + " 2", Float, geometry + "nodes"));
  if (!where.graph.empty()) {
    const std::string graph = h5_name + ":" + where.graph + "/";
    for (const char* name : {"aperture", "length"})
      xml += xdmf_attribute(name, "Scalar", "Cell", cells, Float, graph + name);
    for (const char* name : {"set", "fracture", "component", "dead_end"})
      xml += xdmf_attribute(name, "Scalar", "Cell", cells, Int, graph + name);
  }
  if (!where.flow.empty()) {
    const std::string flow = h5_name + ":" + where.flow + "/";
    xml += xdmf_attribute("pressure", "Scalar", "Node", nodes, Float, flow + "pressure");
    if (where.head) xml += xdmf_attribute("head", "Scalar", "Node", nodes, Float, flow + "head");
    for (const char* name : {"aperture_a", "aperture_b", "aperture_mean", "flux"})
      xml += xdmf_attribute(name, "Scalar", "Cell", cells, Float, flow + name);
  }
  xml += "        </Grid>\n";
  return xml;
}

}  // namespace fissure
