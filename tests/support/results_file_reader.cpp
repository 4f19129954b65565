#include "tests/support/results_file_reader.h"

#include <limits>
#include <regex>

namespace fissure::test {

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// The lines of a text file.
std::vector<std::string> text_lines(const std::filesystem::path& file) {
  std::vector<std::string> out;
  std::istringstream in(read_text(file));
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

/// The numbers of a comma-separated row.
std::vector<double> csv_numbers(const std::string& row) {
  // Every cell, the empty ones (a missing value) as nan.
  std::vector<double> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = row.find(',', start);
    const std::string cell = row.substr(start, comma == std::string::npos ? comma : comma - start);
    out.push_back(cell.empty() ? std::numeric_limits<double>::quiet_NaN() : std::stod(cell));
    if (comma == std::string::npos) return out;
    start = comma + 1;
  }
}

std::map<std::string, std::vector<double>> monitor_columns(const std::string& outdir) {
  const std::vector<std::string> lines = text_lines(outdir + "/monitors.csv");
  std::map<std::string, std::vector<double>> columns;
  if (lines.empty()) return columns;
  std::vector<std::string> names;
  std::stringstream header(lines[0]);
  for (std::string name; std::getline(header, name, ',');) names.push_back(name);
  for (std::size_t r = 1; r < lines.size(); ++r) {
    const std::vector<double> values = csv_numbers(lines[r]);
    for (std::size_t c = 0; c < names.size() && c < values.size(); ++c)
      columns[names[c]].push_back(values[c]);
  }
  return columns;
}

/// The <Time Value="..."/> entries of an XDMF file, in order, parsed exactly.
std::vector<double> xdmf_times(const std::string& xml) {
  std::vector<double> times;
  const std::regex re(R"re(<Time Value="([^"]+)"/>)re");
  for (std::sregex_iterator it(xml.begin(), xml.end(), re), end; it != end; ++it)
    times.push_back(std::strtod((*it)[1].str().c_str(), nullptr));
  return times;
}

std::vector<XdmfDataItem> xdmf_data_items(const std::string& xml) {
  std::vector<XdmfDataItem> items;
  const std::regex re(
      R"re(<DataItem Dimensions="([0-9 ]+)" NumberType="(\w+)" Precision="(\d)" Format="HDF">([^:<]+):([^<]+)</DataItem>)re");
  for (std::sregex_iterator it(xml.begin(), xml.end(), re), end; it != end; ++it) {
    XdmfDataItem item;
    std::istringstream dims((*it)[1].str());
    for (hsize_t d; dims >> d;) item.dimensions.push_back(d);
    item.number_type = (*it)[2].str();
    item.precision = std::stoi((*it)[3].str());
    item.file = (*it)[4].str();
    item.path = (*it)[5].str();
    items.push_back(item);
  }
  return items;
}

int count_occurrences(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t pos = text.find(what); pos != std::string::npos; pos = text.find(what, pos + 1))
    ++n;
  return n;
}

/// Whether every element is closed in the right order (no attributes with '>'
/// are used in our files, so a tag scan is enough). Catches a truncated file.
bool xml_tags_balanced(const std::string& xml) {
  std::vector<std::string> open;
  for (std::size_t pos = xml.find('<'); pos != std::string::npos; pos = xml.find('<', pos + 1)) {
    const std::size_t end = xml.find('>', pos);
    if (end == std::string::npos) return false;
    const std::string tag = xml.substr(pos + 1, end - pos - 1);
    if (tag.empty() || tag[0] == '?' || tag[0] == '!' || tag.back() == '/') continue;
    const std::string name =
        tag.substr(tag[0] == '/', tag.find_first_of(" \t\n") - (tag[0] == '/'));
    if (tag[0] != '/') {
      open.push_back(name);
    } else {
      if (open.empty() || open.back() != name) return false;
      open.pop_back();
    }
  }
  return open.empty();
}

/// Checks that every heavy-data reference of the XDMF text names a dataset of
/// `h5` with the same dimensions and number type.
void expect_xdmf_refs_match(const std::string& xml, const H5Reader& h5,
                            const std::string& h5_name) {
  const auto items = xdmf_data_items(xml);
  ASSERT_FALSE(items.empty());
  for (const XdmfDataItem& item : items) {
    SCOPED_TRACE(item.path);
    EXPECT_EQ(item.file, h5_name);
    ASSERT_TRUE(h5.exists(item.path));
    EXPECT_EQ(item.dimensions, h5.shape(item.path));
    const auto [cls, bytes] = h5.type(item.path);
    EXPECT_EQ(cls, item.number_type == "Float" ? H5T_FLOAT : H5T_INTEGER);
    EXPECT_EQ(static_cast<int>(bytes), item.precision);
  }
}

}  // namespace fissure::test
