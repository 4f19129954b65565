// A thin, checked front to the HDF5 C API for the output writers (private to
// core/io). Every call is checked; a failure becomes an IoError that names the
// file, what was being done and HDF5's own reason. HDF5's habit of printing
// its error stack to stderr is switched off while these functions run, so the
// user sees one clear message instead of a page of traces.
//
// The file is laid out so that a process killed at any moment leaves the
// state of the last flush readable (docs/output.md, "Nothing is lost"); see
// the comments in hdf5_file.cpp for how.
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

/// An open group and its path (for messages; a detached group has the path
/// it will be linked to).
struct Hdf5Group {
  Hdf5Handle id;
  std::string path;
};

/// An HDF5 file opened for writing (or, for checkpoints and restarts, an
/// existing one for reading or appending). Datasets and attributes are
/// written into a group given by the caller; shapes are row-major and
/// data.size() must equal their product.
class Hdf5File {
 public:
  enum class Mode {
    Create,  ///< create (truncate) the file
    Append,  ///< open an existing file to read and write
    Read,    ///< open an existing file to read
  };
  /// Creates (truncates) the file, or opens it. A created file may begin
  /// with `user_block_bytes` (0, or a power of 2 >= 512) that HDF5 leaves to
  /// its writer (checkpoints keep their integrity record there).
  explicit Hdf5File(const std::filesystem::path& file, Mode mode = Mode::Create,
                    std::size_t user_block_bytes = 0);
  /// Closes the file; a failure here cannot be reported, so it is silent.
  ~Hdf5File();
  Hdf5File(const Hdf5File&) = delete;
  Hdf5File& operator=(const Hdf5File&) = delete;

  Hdf5Group root();
  /// A small group: its links live in its own object header.
  Hdf5Group create_group(const Hdf5Group& parent, const std::string& name);
  /// A group that will hold many links (one per output frame): a symbol table
  /// whose name heap is reserved for `name_bytes` so it does not move as it grows.
  Hdf5Group create_growing_group(const Hdf5Group& parent, const std::string& name,
                                 std::size_t name_bytes);
  /// A small group that no other group links to yet (see link()).
  Hdf5Group create_detached_group(const std::string& path);
  /// Links a detached group into `parent`, under `name`.
  void link(const Hdf5Group& group, const Hdf5Group& parent, const std::string& name);
  /// An existing group.
  Hdf5Group open_group(const Hdf5Group& parent, const std::string& name);
  /// Removes the link `name` from `parent` (the space is not reclaimed).
  void unlink(const Hdf5Group& parent, const std::string& name);
  /// Whether `parent` has a link `name`.
  bool exists(const Hdf5Group& parent, const std::string& name);
  /// The names of the links in `parent`.
  std::vector<std::string> links(const Hdf5Group& parent);

  void write(const Hdf5Group& where, const std::string& name, std::span<const double> data,
             const std::vector<hsize_t>& shape);
  void write(const Hdf5Group& where, const std::string& name, std::span<const int> data,
             const std::vector<hsize_t>& shape);
  void write_strings(const Hdf5Group& where, const std::string& name,
                     const std::vector<std::string>& values);
  void write_attribute(const Hdf5Group& group, const std::string& name, double value);
  void write_attribute(const Hdf5Group& group, const std::string& name, int value);
  void write_attribute(const Hdf5Group& group, const std::string& name, const std::string& value);

  /// Every value of a dataset of numbers (any shape), converted to double.
  std::vector<double> read_doubles(const Hdf5Group& where, const std::string& name);
  std::vector<std::string> read_strings(const Hdf5Group& where, const std::string& name);
  double read_double_attribute(const Hdf5Group& group, const std::string& name);
  std::string read_string_attribute(const Hdf5Group& group, const std::string& name);

  /// Makes the file at least `bytes` longer than HDF5's current size, so that
  /// the size HDF5 records in the file never exceeds its length on disk, even
  /// when HDF5 writes its superblock in the middle of a frame. Call with an
  /// upper bound of what is about to be written.
  void reserve(std::size_t bytes);

  /// Writes everything so far to the operating system, so that it survives
  /// the process being killed.
  void flush();

  const std::filesystem::path& path() const { return file_name_; }

 private:
  void write_dataset(const Hdf5Group& where, const std::string& name, hid_t file_type,
                     hid_t mem_type, const void* data, std::size_t n,
                     const std::vector<hsize_t>& shape);
  void write_scalar_attribute(const Hdf5Group& group, const std::string& name, hid_t file_type,
                              hid_t mem_type, const void* value);

  std::filesystem::path file_name_;
  bool read_only_ = false;
  Hdf5Handle file_;
};

}  // namespace fissure
