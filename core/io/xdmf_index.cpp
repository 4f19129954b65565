#include "core/io/xdmf_index.h"

#include <fmt/format.h>

#include "core/io/atomic_file.h"
#include "core/io/fracture_output.h"
#include "core/io/xdmf_items.h"

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

}  // namespace

XdmfIndex::XdmfIndex(std::filesystem::path file, std::string h5_name)
    : file_(std::move(file)), h5_name_(std::move(h5_name)) {}

void XdmfIndex::set_mesh(int n_vertices, int n_triangles) {
  n_vertices_ = n_vertices;
  n_triangles_ = n_triangles;
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
        n_triangles_,
        xdmf_data_item(cells + " 3", XdmfNumber::Int32, h5_name_ + ":/mesh/triangles"),
        xdmf_data_item(nodes2, XdmfNumber::Float64, h5 + "vertices"));
    xml += xdmf_attribute("displacement", "Vector", "Node", nodes3, XdmfNumber::Float64,
                          h5 + "displacement");
    xml +=
        xdmf_attribute("velocity", "Vector", "Node", nodes3, XdmfNumber::Float64, h5 + "velocity");
    for (const char* s : {"sxx", "syy", "sxy"})
      xml += xdmf_attribute(s, "Scalar", "Cell", cells, XdmfNumber::Float64, h5 + s);
    xml += xdmf_attribute("block_id", "Scalar", "Cell", cells, XdmfNumber::Int32, h5 + "block_id");
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
        frame.n_contacts, xdmf_data_item(points, XdmfNumber::Int32, c + "cells"),
        xdmf_data_item(points + " 2", XdmfNumber::Float64, c + "points"));
    xml += xdmf_attribute("normal", "Vector", "Node", points + " 3", XdmfNumber::Float64,
                          c + "normal");
    xml += xdmf_attribute("state", "Scalar", "Node", points, XdmfNumber::Int32, c + "state");
    for (const char* s : {"gap", "normal_force", "shear_force"})
      xml += xdmf_attribute(s, "Scalar", "Node", points, XdmfNumber::Float64, c + s);
    for (const char* s : {"block_i", "block_j"})
      xml += xdmf_attribute(s, "Scalar", "Node", points, XdmfNumber::Int32, c + s);
    xml += "        </Grid>\n";
  }
  if (frame.fractures.n_segments > 0) xml += fracture_grid_xml(h5_name_, frame.fractures);
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
