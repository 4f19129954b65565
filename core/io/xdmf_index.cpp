#include "core/io/xdmf_index.h"

#include <fmt/format.h>

#include "core/io/atomic_file.h"
#include "core/io/fracture_output.h"

namespace fissure {

namespace {

constexpr const char* kHeader =
    "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
    "<Xdmf xmlns:xi=\"http://www.w3.org/2001/XInclude\" Version=\"3.0\">\n"
    "  <Domain>\n"
    "    <Grid Name=\"fissure\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
constexpr const char* kFooter =
    "    </Grid>\n"
    "  </Domain>\n"
    "</Xdmf>\n";

enum class Kind { Float64, Int32 };

std::string data_item(const std::string& dimensions, Kind kind, const std::string& h5_path) {
  const char* type = kind == Kind::Float64 ? "NumberType=\"Float\" Precision=\"8\""
                                           : "NumberType=\"Int\" Precision=\"4\"";
  return fmt::format("<DataItem Dimensions=\"{}\" {} Format=\"HDF\">{}</DataItem>", dimensions,
                     type, h5_path);
}

/// One <Attribute> with its data item, indented for a grid at depth 5.
std::string attribute(const std::string& name, const char* type, const char* center,
                      const std::string& dimensions, Kind kind, const std::string& h5_path) {
  return fmt::format(
      "          <Attribute Name=\"{}\" AttributeType=\"{}\" Center=\"{}\">\n"
      "            {}\n"
      "          </Attribute>\n",
      name, type, center, data_item(dimensions, kind, h5_path));
}

}  // namespace

XdmfIndex::XdmfIndex(std::filesystem::path file, std::string h5_name)
    : file_(std::move(file)), h5_name_(std::move(h5_name)) {}

void XdmfIndex::set_mesh(int n_vertices, int n_triangles) {
  n_vertices_ = n_vertices;
  n_triangles_ = n_triangles;
}

void XdmfIndex::set_fractures(int n_nodes, int n_segments) {
  n_fracture_nodes_ = n_nodes;
  n_fracture_segments_ = n_segments;
}

std::string XdmfIndex::frame_xml(const XdmfFrame& frame) const {
  const std::string h5 = h5_name_ + ":" + frame.group + "/";
  const std::string name = frame.group.substr(frame.group.find_last_of('/') + 1);
  std::string xml = fmt::format(
      "      <Grid Name=\"frame_{}\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
      "        <Time Value=\"{:.17g}\"/>\n",
      name, frame.time);

  // ParaView cannot draw a grid without cells, so a model without blocks has
  // no "blocks" grid.
  if (n_triangles_ > 0) {
    const std::string nodes2 = fmt::format("{} 2", n_vertices_);
    const std::string nodes3 = fmt::format("{} 3", n_vertices_);
    const std::string cells = std::to_string(n_triangles_);
    xml += fmt::format(
        "        <Grid Name=\"blocks\" GridType=\"Uniform\">\n"
        "          <Topology TopologyType=\"Triangle\" NumberOfElements=\"{}\">\n"
        "            {}\n"
        "          </Topology>\n"
        "          <Geometry GeometryType=\"XY\">\n"
        "            {}\n"
        "          </Geometry>\n",
        n_triangles_, data_item(cells + " 3", Kind::Int32, h5_name_ + ":/mesh/triangles"),
        data_item(nodes2, Kind::Float64, h5 + "vertices"));
    xml += attribute("displacement", "Vector", "Node", nodes3, Kind::Float64, h5 + "displacement");
    xml += attribute("velocity", "Vector", "Node", nodes3, Kind::Float64, h5 + "velocity");
    for (const char* s : {"sxx", "syy", "sxy"})
      xml += attribute(s, "Scalar", "Cell", cells, Kind::Float64, h5 + s);
    xml += attribute("block_id", "Scalar", "Cell", cells, Kind::Int32, h5 + "block_id");
    xml += "        </Grid>\n";
  }

  if (frame.n_contacts > 0) {
    const std::string c = h5 + "contacts/";
    const std::string points = std::to_string(frame.n_contacts);
    // ParaView makes no cells from a Polyvertex topology without
    // connectivity (nothing would be drawn), hence the explicit point list.
    xml += fmt::format(
        "        <Grid Name=\"contacts\" GridType=\"Uniform\">\n"
        "          <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"{}\" "
        "NodesPerElement=\"1\">\n"
        "            {}\n"
        "          </Topology>\n"
        "          <Geometry GeometryType=\"XY\">\n"
        "            {}\n"
        "          </Geometry>\n",
        frame.n_contacts, data_item(points, Kind::Int32, c + "cells"),
        data_item(points + " 2", Kind::Float64, c + "points"));
    xml += attribute("normal", "Vector", "Node", points + " 3", Kind::Float64, c + "normal");
    xml += attribute("state", "Scalar", "Node", points, Kind::Int32, c + "state");
    for (const char* s : {"gap", "normal_force", "shear_force"})
      xml += attribute(s, "Scalar", "Node", points, Kind::Float64, c + s);
    for (const char* s : {"block_i", "block_j"})
      xml += attribute(s, "Scalar", "Node", points, Kind::Int32, c + s);
    xml += "        </Grid>\n";
  }
  if (n_fracture_segments_ > 0)
    xml += fracture_grid_xml(h5_name_, n_fracture_nodes_, n_fracture_segments_);
  xml += "      </Grid>\n";
  return xml;
}

void XdmfIndex::add_frame(const XdmfFrame& frame) {
  const std::size_t previous = frames_xml_.size();
  frames_xml_ += frame_xml(frame);
  try {
    write();
  } catch (...) {
    // A frame that is not in the file is not in the index either.
    frames_xml_.resize(previous);
    throw;
  }
}

void XdmfIndex::write() const {
  write_file_atomically(file_, {kHeader, frames_xml_, kFooter});
}

}  // namespace fissure
