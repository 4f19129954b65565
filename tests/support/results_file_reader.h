// Reading results.h5 back with the HDF5 C API and checking results.xdmf as
// text, for the output tests (core/io). Independent of the writer's code on
// purpose: a bug there must not be hidden by the same bug here. The text
// checks (std::regex) are compiled once, in results_file_reader.cpp.
#pragma once

#include <gtest/gtest.h>
#include <hdf5.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace fissure::test {

/// The text of a file.
std::string read_text(const std::filesystem::path& file);

/// The lines of a text file.
std::vector<std::string> text_lines(const std::filesystem::path& file);

/// The numbers of a comma-separated row.
std::vector<double> csv_numbers(const std::string& row);

/// The columns of a run's monitors.csv (in `outdir`) by name.
std::map<std::string, std::vector<double>> monitor_columns(const std::string& outdir);

/// A results.h5 opened read-only. Throws std::runtime_error on any failure.
class H5Reader {
 public:
  explicit H5Reader(const std::filesystem::path& file) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    file_ = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (file_ < 0) throw std::runtime_error("cannot open " + file.string());
  }
  ~H5Reader() { H5Fclose(file_); }
  H5Reader(const H5Reader&) = delete;
  H5Reader& operator=(const H5Reader&) = delete;

  /// Whether every link along the absolute path exists.
  bool exists(const std::string& path) const {
    std::string prefix;
    std::size_t pos = 1;
    while (pos <= path.size()) {
      const std::size_t next = std::min(path.find('/', pos), path.size());
      prefix = path.substr(0, next);
      if (H5Lexists(file_, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
      pos = next + 1;
    }
    return true;
  }

  std::vector<hsize_t> shape(const std::string& path) const {
    const hid_t d = open(path);
    const hid_t space = H5Dget_space(d);
    std::vector<hsize_t> dims(H5Sget_simple_extent_ndims(space));
    H5Sget_simple_extent_dims(space, dims.data(), nullptr);
    H5Sclose(space);
    H5Dclose(d);
    return dims;
  }

  /// H5T_FLOAT or H5T_INTEGER, and the size in bytes.
  std::pair<H5T_class_t, std::size_t> type(const std::string& path) const {
    const hid_t d = open(path);
    const hid_t t = H5Dget_type(d);
    const auto result = std::make_pair(H5Tget_class(t), H5Tget_size(t));
    H5Tclose(t);
    H5Dclose(d);
    return result;
  }

  std::vector<double> doubles(const std::string& path) const {
    return read<double>(path, H5T_NATIVE_DOUBLE);
  }
  std::vector<int> ints(const std::string& path) const { return read<int>(path, H5T_NATIVE_INT); }

  std::vector<std::string> strings(const std::string& path) const {
    const hid_t d = open(path);
    const hid_t t = H5Dget_type(d);
    std::vector<char*> raw(element_count(path));
    if (!raw.empty() && H5Dread(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, raw.data()) < 0)
      throw std::runtime_error("cannot read " + path);
    std::vector<std::string> out(raw.begin(), raw.end());
    for (char* p : raw) std::free(p);
    H5Tclose(t);
    H5Dclose(d);
    return out;
  }

  double double_attribute(const std::string& object, const std::string& name) const {
    const hid_t a = H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
    if (a < 0) throw std::runtime_error("no attribute " + name + " on " + object);
    double v = 0;
    H5Aread(a, H5T_NATIVE_DOUBLE, &v);
    H5Aclose(a);
    return v;
  }

  bool has_attribute(const std::string& object, const std::string& name) const {
    return H5Aexists_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT) > 0;
  }

  /// Whether the object at `path` is a group.
  bool is_group(const std::string& path) const {
    H5O_info_t info;
    return H5Oget_info_by_name(file_, path.c_str(), &info, H5P_DEFAULT) >= 0 &&
           info.type == H5O_TYPE_GROUP;
  }

  /// Names of the members of a group, in name order.
  std::vector<std::string> members(const std::string& group) const {
    std::vector<std::string> names;
    auto add = [](hid_t, const char* name, const H5L_info_t*, void* out) -> herr_t {
      static_cast<std::vector<std::string>*>(out)->emplace_back(name);
      return 0;
    };
    if (H5Literate_by_name(file_, group.c_str(), H5_INDEX_NAME, H5_ITER_INC, nullptr, add, &names,
                           H5P_DEFAULT) < 0)
      throw std::runtime_error("cannot list " + group);
    return names;
  }

 private:
  hid_t open(const std::string& path) const {
    const hid_t d = H5Dopen2(file_, path.c_str(), H5P_DEFAULT);
    if (d < 0) throw std::runtime_error("no dataset " + path);
    return d;
  }

  std::size_t element_count(const std::string& path) const {
    std::size_t n = 1;
    for (hsize_t s : shape(path)) n *= s;
    return n;
  }

  template <class T>
  std::vector<T> read(const std::string& path, hid_t mem_type) const {
    std::vector<T> out(element_count(path));
    const hid_t d = open(path);
    const herr_t status =
        out.empty() ? 0 : H5Dread(d, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data());
    H5Dclose(d);
    if (status < 0) throw std::runtime_error("cannot read " + path);
    return out;
  }

  hid_t file_ = -1;
};

/// The <Time Value="..."/> entries of an XDMF file, in order, parsed exactly.
std::vector<double> xdmf_times(const std::string& xml);

struct XdmfDataItem {
  std::vector<hsize_t> dimensions;
  std::string number_type;  ///< Float | Int
  int precision = 0;        ///< bytes
  std::string file;         ///< before the colon
  std::string path;         ///< HDF5 path after the colon
};

/// The heavy-data references of an XDMF file.
std::vector<XdmfDataItem> xdmf_data_items(const std::string& xml);

int count_occurrences(const std::string& text, const std::string& what);

/// Whether every element is closed in the right order (no attributes with '>'
/// are used in our files, so a tag scan is enough). Catches a truncated file.
bool xml_tags_balanced(const std::string& xml);

/// Checks that every heavy-data reference of the XDMF text names a dataset of
/// `h5` with the same dimensions and number type.
void expect_xdmf_refs_match(const std::string& xml, const H5Reader& h5,
                            const std::string& h5_name = "results.h5");

}  // namespace fissure::test
