#include "rockmass/fields/contact_results.h"

namespace fissure {

std::size_t ContactResults::frame_bytes(const RockMass& state) const {
  const std::vector<ContactRecord>* contacts = state.fields.find(kContacts);
  return contacts ? (8 * (2 + 3 + 3) + 4 * 4) * contacts->size() : 0;
}

void ContactResults::write_frame(FrameWriter& frame, const RockMass& state) {
  const std::vector<ContactRecord>* found = state.fields.find(kContacts);
  if (!found || found->empty()) return;
  const std::vector<ContactRecord>& contacts = *found;
  const int n = static_cast<int>(contacts.size());
  std::vector<double> points, normal, gap, normal_force, shear_force;
  std::vector<int> states, block_i, block_j, cells;
  for (const ContactRecord& r : contacts) {
    cells.push_back(static_cast<int>(cells.size()));
    points.insert(points.end(), {r.point.x(), r.point.y()});
    normal.insert(normal.end(), {r.normal.x(), r.normal.y(), 0.0});
    states.push_back(static_cast<int>(r.state));
    gap.push_back(r.gap);
    normal_force.push_back(r.normal_force);
    shear_force.push_back(r.shear_force);
    block_i.push_back(r.block_i);
    block_j.push_back(r.block_j);
  }
  Hdf5File& h5 = frame.h5();
  const hsize_t nc = static_cast<hsize_t>(n);
  const Hdf5Group& g = frame.frame_group("contacts");
  h5.write(g, "points", points, {nc, 2});
  h5.write(g, "normal", normal, {nc, 3});
  h5.write(g, "state", states, {nc});
  h5.write(g, "gap", gap, {nc});
  h5.write(g, "normal_force", normal_force, {nc});
  h5.write(g, "shear_force", shear_force, {nc});
  h5.write(g, "block_i", block_i, {nc});
  h5.write(g, "block_j", block_j, {nc});
  h5.write(g, "cells", cells, {nc});

  // ParaView makes no cells from a Polyvertex topology without connectivity
  // (nothing would be drawn), hence the explicit point list.
  XdmfGrid& grid = frame.grid("contacts");
  const std::string c = g.path + "/";
  const std::string m = std::to_string(n);
  constexpr auto Float = XdmfNumber::Float64;
  constexpr auto Int = XdmfNumber::Int32;
  grid.topology_type = "Polyvertex";
  grid.n_elements = n;
  grid.nodes_per_element = 1;
  grid.connectivity = xdmf_data_item(m, Int, frame.xdmf_path(c + "cells"));
  grid.geometry = xdmf_data_item(m + " 2", Float, frame.xdmf_path(c + "points"));
  grid.frame_attributes.push_back(xdmf_attribute("normal", "Vector", "Node", m + " 3", Float,
                                                 frame.xdmf_path(c + "normal"), "-"));
  grid.frame_attributes.push_back(
      xdmf_attribute("state", "Scalar", "Node", m, Int, frame.xdmf_path(c + "state"), "-"));
  for (const auto& [s, unit] :
       {std::pair{"gap", "m"}, {"normal_force", "N/m"}, {"shear_force", "N/m"}})
    grid.frame_attributes.push_back(
        xdmf_attribute(s, "Scalar", "Node", m, Float, frame.xdmf_path(c + s), unit));
  for (const char* s : {"block_i", "block_j"})
    grid.frame_attributes.push_back(
        xdmf_attribute(s, "Scalar", "Node", m, Int, frame.xdmf_path(c + s), "-"));
}

}  // namespace fissure
