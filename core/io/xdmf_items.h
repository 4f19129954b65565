// The pieces of XDMF text that every grid of results.xdmf is made of:
// heavy-data references into results.h5 and attributes. Every results part
// (results_part.h) uses them, so that all grids spell them alike.
#pragma once

#include <string>

namespace fissure {

enum class XdmfNumber { Float64, Int32 };

/// <DataItem> referring to the dataset `h5_path` ("results.h5:/frames/...").
std::string xdmf_data_item(const std::string& dimensions, XdmfNumber number,
                           const std::string& h5_path);

/// One <Attribute> with its data item, indented for a grid inside a frame's
/// Spatial collection. `type` is Scalar or Vector, `center` Node or Cell.
std::string xdmf_attribute(const std::string& name, const char* type, const char* center,
                           const std::string& dimensions, XdmfNumber number,
                           const std::string& h5_path);

}  // namespace fissure
