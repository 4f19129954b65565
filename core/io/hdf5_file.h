// A thin, checked front to the HDF5 C API for the output writers (private to
// core/io). Every call is checked; a failure becomes an IoError that names the
// file, what was being done and HDF5's own reason. HDF5's habit of printing
// its error stack to stderr is switched off while these functions run, so the
// user sees one clear message instead of a page of traces.
#pragma once

#include <hdf5.h>

#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace fissure {

/// Owns one HDF5 identifier and releases it with the matching close function.
class Hdf5Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Hdf5Handle() = default;
  Hdf5Handle(hid_t id, Closer closer) : id_(id), closer_(closer) {}
  ~Hdf5Handle() { reset(); }
  Hdf5Handle(Hdf5Handle&& o) noexcept : id_(o.id_), closer_(o.closer_) { o.id_ = -1; }
  Hdf5Handle& operator=(Hdf5Handle&& o) noexcept;
  Hdf5Handle(const Hdf5Handle&) = delete;
  Hdf5Handle& operator=(const Hdf5Handle&) = delete;

  hid_t get() const { return id_; }
  void reset();

 private:
  hid_t id_ = -1;
  Closer closer_ = nullptr;
};

/// An HDF5 file opened for writing. Paths are absolute ("/frames/000001/vertices");
/// parent groups must exist (create_group). Shapes are row-major; data.size()
/// must equal the product of the shape.
class Hdf5File {
 public:
  /// Creates (truncates) the file.
  explicit Hdf5File(const std::filesystem::path& file);
  /// Closes the file; a failure here cannot be reported, so it is silent.
  ~Hdf5File();
  Hdf5File(const Hdf5File&) = delete;
  Hdf5File& operator=(const Hdf5File&) = delete;

  void create_group(const std::string& path);
  void write(const std::string& path, std::span<const double> data,
             const std::vector<hsize_t>& shape);
  void write(const std::string& path, std::span<const int> data,
             const std::vector<hsize_t>& shape);
  void write_strings(const std::string& path, const std::vector<std::string>& values);
  void write_attribute(const std::string& object, const std::string& name, double value);
  void write_attribute(const std::string& object, const std::string& name, int value);
  void write_attribute(const std::string& object, const std::string& name,
                       const std::string& value);

  /// Pushes everything written so far to the operating system, so that it
  /// survives the process being killed.
  void flush();

  const std::filesystem::path& path() const { return file_name_; }

 private:
  void write_dataset(const std::string& path, hid_t file_type, hid_t mem_type, const void* data,
                     std::size_t n, const std::vector<hsize_t>& shape);
  void write_scalar_attribute(const std::string& object, const std::string& name,
                              hid_t file_type, hid_t mem_type, const void* value);

  std::filesystem::path file_name_;
  Hdf5Handle file_;
};

}  // namespace fissure
