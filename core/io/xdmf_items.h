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
/// `unit` goes into an <Information Name="unit"> element (ParaView ignores
/// it; a reader of the file finds every field's unit there): "Pa", "m/s",
/// "degC", "-" for a number without unit (ids, flags, unit normals).
std::string xdmf_attribute(const std::string& name, const char* type, const char* center,
                           const std::string& dimensions, XdmfNumber number,
                           const std::string& h5_path, const char* unit);

/// An <Information Name="name" Value="value"/> element, indented by `indent`
/// spaces: what the index says about its items beside their data (the unit
/// of time, the geometry of a grid).
std::string xdmf_information(const std::string& name, const std::string& value, int indent);

}  // namespace fissure
