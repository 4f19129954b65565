#include "core/io/results_part.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace fissure {

std::string XdmfGrid::xml() const {
  const std::string per_element =
      nodes_per_element > 0 ? fmt::format(" NodesPerElement=\"{}\"", nodes_per_element) : "";
  std::string xml = fmt::format(
      "        <Grid Name=\"{}\" GridType=\"Uniform\">\n"
      "{}"
      "          <Topology TopologyType=\"{}\" NumberOfElements=\"{}\"{}>\n"
      "            {}\n"
      "          </Topology>\n"
      "          <Geometry GeometryType=\"XY\">\n"
      "            {}\n"
      "          </Geometry>\n",
      name, fmt::join(information, ""), topology_type, n_elements, per_element, connectivity,
      geometry);
  for (const std::string& a : mesh_attributes) xml += a;
  for (const std::string& a : frame_attributes) xml += a;
  xml += "        </Grid>\n";
  return xml;
}

FrameWriter::FrameWriter(Hdf5File& h5, std::string h5_name, double time, const Hdf5Group& mesh)
    : h5_(h5), h5_name_(std::move(h5_name)), time_(time), mesh_(mesh) {}

const Hdf5Group& FrameWriter::frame_group(const std::string& name) {
  for (const auto& [n, group] : groups_)
    if (n == name) return group;
  groups_.emplace_back(name, h5_.create_group(frame(), name));
  return groups_.back().second;
}

std::string FrameWriter::xdmf_path(const std::string& dataset_path) const {
  return h5_name_ + ":" + dataset_path;
}

XdmfGrid& FrameWriter::grid(const std::string& name) {
  for (XdmfGrid& g : grids_)
    if (g.name == name) return g;
  XdmfGrid& grid = grids_.emplace_back();
  grid.name = name;
  return grid;
}

}  // namespace fissure
