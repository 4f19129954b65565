#include "core/io/xdmf_index.h"

#include <fmt/format.h>

#include "core/io/atomic_file.h"

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

XdmfIndex::XdmfIndex(std::filesystem::path file, std::string h5_name, TimeUnit time_unit)
    : file_(std::move(file)), h5_name_(std::move(h5_name)) {
  // The Time values are in s (ParaView shows them as they are); the
  // scene's unit lets a reader convert them (docs/output.md, "Time").
  header_ =
      std::string(kHeader) + xdmf_information("time_unit", "s", 6) +
      xdmf_information("scene_time_unit", time_unit.name, 6) +
      xdmf_information("scene_time_unit_seconds", fmt::format("{:.17g}", time_unit.seconds), 6);
}

void XdmfIndex::add_frame(double time, const std::string& group,
                          const std::deque<XdmfGrid>& grids) {
  const std::string name = group.substr(group.find_last_of('/') + 1);
  std::string xml = fmt::format(
      "      <Grid Name=\"frame_{}\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
      "        <Time Value=\"{:.17g}\"/>\n",
      name, time);
  // ParaView cannot draw a grid without cells: a part that set no topology
  // (a model without blocks, a frame without contacts) has no grid.
  for (const XdmfGrid& g : grids)
    if (g.has_topology() && g.n_elements > 0) xml += g.xml();
  xml += "      </Grid>\n";

  const std::size_t previous = frames_xml_.size();
  frames_xml_ += xml;
  try {
    write();
  } catch (...) {
    // A frame that is not in the file is not in the index either.
    frames_xml_.resize(previous);
    throw;
  }
}

void XdmfIndex::write() const {
  write_file_atomically(file_, {header_, frames_xml_, kFooter});
}

}  // namespace fissure
