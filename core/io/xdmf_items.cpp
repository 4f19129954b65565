#include "core/io/xdmf_items.h"

#include <fmt/format.h>

namespace fissure {

std::string xdmf_data_item(const std::string& dimensions, XdmfNumber number,
                           const std::string& h5_path) {
  const char* type = number == XdmfNumber::Float64 ? "NumberType=\"Float\" Precision=\"8\""
                                                   : "NumberType=\"Int\" Precision=\"4\"";
  return fmt::format("<DataItem Dimensions=\"{}\" {} Format=\"HDF\">{}</DataItem>", dimensions,
                     type, h5_path);
}

std::string xdmf_attribute(const std::string& name, const char* type, const char* center,
                           const std::string& dimensions, XdmfNumber number,
                           const std::string& h5_path, const char* unit) {
  return fmt::format(
      "          <Attribute Name=\"{}\" AttributeType=\"{}\" Center=\"{}\">\n"
      "{}"
      "            {}\n"
      "          </Attribute>\n",
      name, type, center, xdmf_information("unit", unit, 12),
      xdmf_data_item(dimensions, number, h5_path));
}

std::string xdmf_information(const std::string& name, const std::string& value, int indent) {
  return fmt::format("{:{}}<Information Name=\"{}\" Value=\"{}\"/>\n", "", indent, name, value);
}

}  // namespace fissure
