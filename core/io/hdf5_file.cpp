#include "core/io/hdf5_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <numeric>

#include "core/base/errors.h"

// How a kill cannot destroy frames that were complete (docs/output.md):
// HDF5 1.10 has no journal, and a flush writes its dirty metadata blocks in
// address order, so a kill during a flush can leave an old block pointing at a
// new one that was never written. The writers therefore
//  * build each frame in a detached group and flush it (only new blocks are
//    written), then link it and flush again (one or two blocks change in place);
//  * keep the one growing group (/frames) from moving or splitting: a reserved
//    name heap, and symbol-table leaves of 1024 names (a split, every 512
//    frames, is the one flush left where a kill can still do damage);
//  * keep the file on disk at least as long as the size HDF5 may record in it
//    (reserve(), no aggregation blocks), so a kill cannot leave a "truncated" file.
// Killing writers at random moments 4000 times lost nothing with these
// measures; with plain flushes about one kill in 400 destroyed earlier frames.

namespace fissure {

namespace {

/// Symbol-table leaf size: a leaf holds 2 * 512 names before it splits.
constexpr unsigned kSymbolLeafK = 512;
constexpr unsigned kSymbolTreeK = 16;  // HDF5's default
/// Slack added to the file length before a flush: more than the metadata a
/// flush may still allocate.
constexpr hsize_t kFlushSlack = 64 * 1024;

/// Switches off HDF5's automatic error printing for the current scope and
/// restores whatever was set before (another part of the program may rely on it).
class QuietHdf5Errors {
 public:
  QuietHdf5Errors() {
    H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietHdf5Errors() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }
  QuietHdf5Errors(const QuietHdf5Errors&) = delete;
  QuietHdf5Errors& operator=(const QuietHdf5Errors&) = delete;

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

/// The outermost and innermost descriptions on HDF5's error stack: the API
/// call that failed and the low-level reason (e.g. "No space left on device").
std::string hdf5_reason() {
  std::vector<std::string> descriptions;
  auto collect = [](unsigned, const H5E_error2_t* e, void* out) -> herr_t {
    if (e->desc && *e->desc) static_cast<std::vector<std::string>*>(out)->emplace_back(e->desc);
    return 0;
  };
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, collect, &descriptions);
  H5Eclear2(H5E_DEFAULT);
  if (descriptions.empty()) return "no reason given by HDF5";
  if (descriptions.size() == 1) return descriptions.front();
  return descriptions.front() + ": " + descriptions.back();
}

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& what) {
  const std::string reason = hdf5_reason();
  throw IoError(file.string() + ": cannot " + what + " (HDF5: " + reason + ")");
}

hid_t checked_id(hid_t id, const std::filesystem::path& file, const std::string& what) {
  if (id < 0) fail(file, what);
  return id;
}

void checked_status(herr_t status, const std::filesystem::path& file, const std::string& what) {
  if (status < 0) fail(file, what);
}

std::string child_path(const Hdf5Group& parent, const std::string& name) {
  return parent.path == "/" ? "/" + name : parent.path + "/" + name;
}

}  // namespace

Hdf5Handle& Hdf5Handle::operator=(Hdf5Handle&& o) noexcept {
  if (this != &o) {
    reset();
    id_ = o.id_;
    closer_ = o.closer_;
    o.id_ = -1;
  }
  return *this;
}

void Hdf5Handle::reset() {
  if (id_ >= 0 && closer_) closer_(id_);
  id_ = -1;
}

namespace {

/// File access properties shared by every mode.
Hdf5Handle file_access_properties(const std::filesystem::path& file, const std::string& what) {
  Hdf5Handle fapl(checked_id(H5Pcreate(H5P_FILE_ACCESS), file, what), H5Pclose);
  // No file lock, so that ParaView or h5py can look at the frames written so
  // far while the run goes on.
  checked_status(H5Pset_file_locking(fapl.get(), false, true), file, what);
  // No aggregation blocks: HDF5 hands the unused tail of such a block back
  // during a flush, after it has recorded the longer file size, and then
  // trims the file below the recorded size (a kill there is "truncated file").
  checked_status(H5Pset_meta_block_size(fapl.get(), 0), file, what);
  checked_status(H5Pset_small_data_block_size(fapl.get(), 0), file, what);
  // A small metadata cache: every flush scans all cached entries (HDF5 1.10),
  // and the entries of earlier frames are not needed again, so a large cache
  // only makes each frame slower than the one before.
  H5AC_cache_config_t cache;
  cache.version = H5AC__CURR_CACHE_CONFIG_VERSION;
  checked_status(H5Pget_mdc_config(fapl.get(), &cache), file, what);
  cache.set_initial_size = true;
  cache.initial_size = cache.min_size = 256 * 1024;
  cache.max_size = 1024 * 1024;
  checked_status(H5Pset_mdc_config(fapl.get(), &cache), file, what);
  return fapl;
}

}  // namespace

Hdf5File::Hdf5File(const std::filesystem::path& file, Mode mode, std::size_t user_block_bytes)
    : file_name_(file), read_only_(mode == Mode::Read) {
  QuietHdf5Errors quiet;
  if (mode != Mode::Create) {
    const std::string what = "open the file";
    FISSURE_CHECK(std::filesystem::exists(file), IoError,
                  file.string() << ": cannot " << what << " (no such file)");
    Hdf5Handle fapl = file_access_properties(file, what);
    file_ = Hdf5Handle(
        checked_id(H5Fopen(file.c_str(), read_only_ ? H5F_ACC_RDONLY : H5F_ACC_RDWR, fapl.get()),
                   file, what),
        H5Fclose);
    return;
  }
  const std::string what = "create the file";
  Hdf5Handle fcpl(checked_id(H5Pcreate(H5P_FILE_CREATE), file, what), H5Pclose);
  checked_status(H5Pset_sym_k(fcpl.get(), kSymbolTreeK, kSymbolLeafK), file, what);
  if (user_block_bytes > 0)
    checked_status(H5Pset_userblock(fcpl.get(), user_block_bytes), file, what);
  Hdf5Handle fapl = file_access_properties(file, what);
  file_ = Hdf5Handle(
      checked_id(H5Fcreate(file.c_str(), H5F_ACC_TRUNC, fcpl.get(), fapl.get()), file, what),
      H5Fclose);
}

Hdf5File::~Hdf5File() {
  QuietHdf5Errors quiet;
  // Closing only ever shrinks the file's allocated size, so cutting the
  // unused tail that reserve() added leaves everything HDF5 wrote.
  hsize_t size = 0;
  const bool known = !read_only_ && file_.get() >= 0 && H5Fget_filesize(file_.get(), &size) >= 0;
  file_.reset();
  std::error_code ec;
  if (known && std::filesystem::file_size(file_name_, ec) > size && !ec)
    std::filesystem::resize_file(file_name_, size, ec);
}

Hdf5Group Hdf5File::root() {
  QuietHdf5Errors quiet;
  return {Hdf5Handle(checked_id(H5Gopen2(file_.get(), "/", H5P_DEFAULT), file_name_,
                                "open the root group"),
                     H5Gclose),
          "/"};
}

namespace {

/// Group creation properties of a small group: links in its object header.
Hdf5Handle compact_group_properties(const std::filesystem::path& file, const std::string& what) {
  Hdf5Handle gcpl(checked_id(H5Pcreate(H5P_GROUP_CREATE), file, what), H5Pclose);
  // Tracking creation order makes HDF5 use the compact (1.8) group format;
  // it also lists a frame's datasets in the order they were written.
  checked_status(H5Pset_link_creation_order(gcpl.get(), H5P_CRT_ORDER_TRACKED), file, what);
  checked_status(H5Pset_obj_track_times(gcpl.get(), false), file, what);
  return gcpl;
}

/// Dataset creation properties: no modification times in the object
/// headers, so that the same run writes the same bytes (reproducible to the
/// bit, issue 22).
Hdf5Handle dataset_properties(const std::filesystem::path& file, const std::string& what) {
  Hdf5Handle dcpl(checked_id(H5Pcreate(H5P_DATASET_CREATE), file, what), H5Pclose);
  checked_status(H5Pset_obj_track_times(dcpl.get(), false), file, what);
  return dcpl;
}

}  // namespace

namespace {

/// UTF-8 strings of any length (datasets of names).
Hdf5Handle variable_string_type(const std::filesystem::path& file, const std::string& what) {
  Hdf5Handle type(checked_id(H5Tcopy(H5T_C_S1), file, what), H5Tclose);
  checked_status(H5Tset_size(type.get(), H5T_VARIABLE), file, what);
  checked_status(H5Tset_cset(type.get(), H5T_CSET_UTF8), file, what);
  return type;
}

/// An existing dataset, its data space and its number of elements.
struct OpenDataset {
  Hdf5Handle dataset, space;
  std::size_t size = 0;
};

OpenDataset open_dataset(const Hdf5Group& where, const std::string& name,
                         const std::filesystem::path& file, const std::string& what) {
  OpenDataset d;
  d.dataset = Hdf5Handle(
      checked_id(H5Dopen2(where.id.get(), name.c_str(), H5P_DEFAULT), file, what), H5Dclose);
  d.space = Hdf5Handle(checked_id(H5Dget_space(d.dataset.get()), file, what), H5Sclose);
  const hssize_t n = H5Sget_simple_extent_npoints(d.space.get());
  checked_status(n < 0 ? -1 : 0, file, what);
  d.size = static_cast<std::size_t>(n);
  return d;
}

}  // namespace

Hdf5Group Hdf5File::create_group(const Hdf5Group& parent, const std::string& name) {
  QuietHdf5Errors quiet;
  const std::string path = child_path(parent, name);
  const std::string what = "create group " + path;
  Hdf5Handle gcpl = compact_group_properties(file_name_, what);
  return {Hdf5Handle(checked_id(H5Gcreate2(parent.id.get(), name.c_str(), H5P_DEFAULT, gcpl.get(),
                                           H5P_DEFAULT),
                                file_name_, what),
                     H5Gclose),
          path};
}

Hdf5Group Hdf5File::create_growing_group(const Hdf5Group& parent, const std::string& name,
                                         std::size_t name_bytes) {
  QuietHdf5Errors quiet;
  const std::string path = child_path(parent, name);
  const std::string what = "create group " + path;
  Hdf5Handle gcpl(checked_id(H5Pcreate(H5P_GROUP_CREATE), file_name_, what), H5Pclose);
  checked_status(H5Pset_local_heap_size_hint(gcpl.get(), name_bytes), file_name_, what);
  checked_status(H5Pset_obj_track_times(gcpl.get(), false), file_name_, what);
  return {Hdf5Handle(checked_id(H5Gcreate2(parent.id.get(), name.c_str(), H5P_DEFAULT, gcpl.get(),
                                           H5P_DEFAULT),
                                file_name_, what),
                     H5Gclose),
          path};
}

Hdf5Group Hdf5File::create_detached_group(const std::string& path) {
  QuietHdf5Errors quiet;
  const std::string what = "create group " + path;
  Hdf5Handle gcpl = compact_group_properties(file_name_, what);
  return {
      Hdf5Handle(checked_id(H5Gcreate_anon(file_.get(), gcpl.get(), H5P_DEFAULT), file_name_, what),
                 H5Gclose),
      path};
}

void Hdf5File::link(const Hdf5Group& group, const Hdf5Group& parent, const std::string& name) {
  reserve(kFlushSlack);  // a link may split a symbol-table node
  QuietHdf5Errors quiet;
  checked_status(H5Olink(group.id.get(), parent.id.get(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT),
                 file_name_, "link group " + child_path(parent, name));
}

Hdf5Group Hdf5File::open_group(const Hdf5Group& parent, const std::string& name) {
  QuietHdf5Errors quiet;
  const std::string path = child_path(parent, name);
  return {Hdf5Handle(checked_id(H5Gopen2(parent.id.get(), name.c_str(), H5P_DEFAULT), file_name_,
                                "open group " + path),
                     H5Gclose),
          path};
}

void Hdf5File::unlink(const Hdf5Group& parent, const std::string& name) {
  QuietHdf5Errors quiet;
  checked_status(H5Ldelete(parent.id.get(), name.c_str(), H5P_DEFAULT), file_name_,
                 "remove " + child_path(parent, name));
}

std::vector<std::string> Hdf5File::links(const Hdf5Group& parent) {
  QuietHdf5Errors quiet;
  std::vector<std::string> names;
  auto collect = [](hid_t, const char* name, const H5L_info_t*, void* out) -> herr_t {
    static_cast<std::vector<std::string>*>(out)->emplace_back(name);
    return 0;
  };
  checked_status(
      H5Literate(parent.id.get(), H5_INDEX_NAME, H5_ITER_NATIVE, nullptr, collect, &names),
      file_name_, "list group " + parent.path);
  return names;
}

bool Hdf5File::exists(const Hdf5Group& parent, const std::string& name) {
  QuietHdf5Errors quiet;
  return H5Lexists(parent.id.get(), name.c_str(), H5P_DEFAULT) > 0;
}

void Hdf5File::write(const Hdf5Group& where, const std::string& name, std::span<const double> data,
                     const std::vector<hsize_t>& shape) {
  write_dataset(where, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, data.data(), data.size(), shape);
}

void Hdf5File::write(const Hdf5Group& where, const std::string& name, std::span<const int> data,
                     const std::vector<hsize_t>& shape) {
  write_dataset(where, name, H5T_STD_I32LE, H5T_NATIVE_INT, data.data(), data.size(), shape);
}

void Hdf5File::write_dataset(const Hdf5Group& where, const std::string& name, hid_t file_type,
                             hid_t mem_type, const void* data, std::size_t n,
                             const std::vector<hsize_t>& shape) {
  const std::string what = "write dataset " + child_path(where, name);
  const hsize_t expected =
      std::accumulate(shape.begin(), shape.end(), hsize_t{1}, std::multiplies<hsize_t>());
  FISSURE_CHECK(expected == n, IoError,
                file_name_.string()
                    << ": cannot " << what << ": " << n << " values do not fill its shape");
  QuietHdf5Errors quiet;
  Hdf5Handle space(
      checked_id(H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr),
                 file_name_, what),
      H5Sclose);
  Hdf5Handle dcpl = dataset_properties(file_name_, what);
  Hdf5Handle dataset(checked_id(H5Dcreate2(where.id.get(), name.c_str(), file_type, space.get(),
                                           H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
                                file_name_, what),
                     H5Dclose);
  // An empty dataset has nothing to transfer (and HDF5 rejects a null buffer).
  if (n == 0) return;
  checked_status(H5Dwrite(dataset.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), file_name_,
                 what);
}

void Hdf5File::write_strings(const Hdf5Group& where, const std::string& name,
                             const std::vector<std::string>& values) {
  QuietHdf5Errors quiet;
  const std::string what = "write dataset " + child_path(where, name);
  const Hdf5Handle type = variable_string_type(file_name_, what);
  const hsize_t n = values.size();
  Hdf5Handle space(checked_id(H5Screate_simple(1, &n, nullptr), file_name_, what), H5Sclose);
  Hdf5Handle dcpl = dataset_properties(file_name_, what);
  Hdf5Handle dataset(checked_id(H5Dcreate2(where.id.get(), name.c_str(), type.get(), space.get(),
                                           H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
                                file_name_, what),
                     H5Dclose);
  if (n == 0) return;
  std::vector<const char*> pointers;
  pointers.reserve(values.size());
  for (const std::string& v : values) pointers.push_back(v.c_str());
  checked_status(
      H5Dwrite(dataset.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data()),
      file_name_, what);
}

void Hdf5File::write_scalar_attribute(const Hdf5Group& group, const std::string& name,
                                      hid_t file_type, hid_t mem_type, const void* value) {
  QuietHdf5Errors quiet;
  const std::string what = "write attribute " + name + " of " + group.path;
  Hdf5Handle space(checked_id(H5Screate(H5S_SCALAR), file_name_, what), H5Sclose);
  Hdf5Handle attribute(checked_id(H5Acreate2(group.id.get(), name.c_str(), file_type, space.get(),
                                             H5P_DEFAULT, H5P_DEFAULT),
                                  file_name_, what),
                       H5Aclose);
  checked_status(H5Awrite(attribute.get(), mem_type, value), file_name_, what);
}

void Hdf5File::write_attribute(const Hdf5Group& group, const std::string& name, double value) {
  write_scalar_attribute(group, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
}

void Hdf5File::write_attribute(const Hdf5Group& group, const std::string& name, int value) {
  write_scalar_attribute(group, name, H5T_STD_I32LE, H5T_NATIVE_INT, &value);
}

void Hdf5File::write_attribute(const Hdf5Group& group, const std::string& name,
                               const std::string& value) {
  QuietHdf5Errors quiet;
  const std::string what = "write attribute " + name + " of " + group.path;
  Hdf5Handle type(checked_id(H5Tcopy(H5T_C_S1), file_name_, what), H5Tclose);
  checked_status(H5Tset_size(type.get(), value.size() + 1), file_name_, what);
  checked_status(H5Tset_strpad(type.get(), H5T_STR_NULLTERM), file_name_, what);
  checked_status(H5Tset_cset(type.get(), H5T_CSET_UTF8), file_name_, what);
  write_scalar_attribute(group, name, type.get(), type.get(), value.c_str());
}

std::vector<double> Hdf5File::read_doubles(const Hdf5Group& where, const std::string& name) {
  QuietHdf5Errors quiet;
  const std::string what = "read dataset " + child_path(where, name);
  const OpenDataset d = open_dataset(where, name, file_name_, what);
  const std::size_t n = d.size;
  std::vector<double> values(n);
  if (n > 0)
    checked_status(
        H5Dread(d.dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
        file_name_, what);
  return values;
}

std::vector<std::string> Hdf5File::read_strings(const Hdf5Group& where, const std::string& name) {
  QuietHdf5Errors quiet;
  const std::string what = "read dataset " + child_path(where, name);
  const OpenDataset d = open_dataset(where, name, file_name_, what);
  const std::size_t n = d.size;
  const Hdf5Handle type = variable_string_type(file_name_, what);
  std::vector<char*> pointers(n, nullptr);
  if (n > 0)
    checked_status(
        H5Dread(d.dataset.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data()),
        file_name_, what);
  std::vector<std::string> values;
  for (char* p : pointers) values.emplace_back(p ? p : "");
  if (n > 0) H5Dvlen_reclaim(type.get(), d.space.get(), H5P_DEFAULT, pointers.data());
  return values;
}

double Hdf5File::read_double_attribute(const Hdf5Group& group, const std::string& name) {
  QuietHdf5Errors quiet;
  const std::string what = "read attribute " + name + " of " + group.path;
  Hdf5Handle attribute(
      checked_id(H5Aopen(group.id.get(), name.c_str(), H5P_DEFAULT), file_name_, what), H5Aclose);
  double value = 0;
  checked_status(H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, &value), file_name_, what);
  return value;
}

std::string Hdf5File::read_string_attribute(const Hdf5Group& group, const std::string& name) {
  QuietHdf5Errors quiet;
  const std::string what = "read attribute " + name + " of " + group.path;
  Hdf5Handle attribute(
      checked_id(H5Aopen(group.id.get(), name.c_str(), H5P_DEFAULT), file_name_, what), H5Aclose);
  Hdf5Handle type(checked_id(H5Aget_type(attribute.get()), file_name_, what), H5Tclose);
  FISSURE_CHECK(H5Tget_class(type.get()) == H5T_STRING && !H5Tis_variable_str(type.get()), IoError,
                file_name_.string() << ": cannot " << what << " (not a fixed-length string)");
  std::string value(H5Tget_size(type.get()), '\0');
  checked_status(H5Aread(attribute.get(), type.get(), value.data()), file_name_, what);
  value.resize(std::strlen(value.c_str()));
  return value;
}

void Hdf5File::reserve(std::size_t bytes) {
  // HDF5 records the file's allocated size in the superblock, at a flush or
  // whenever its cache evicts the superblock, before the file on disk is that
  // long; a reader refuses a file shorter than the recorded size ("truncated
  // file"). Extending the file first (sparse, so free) closes that gap;
  // HDF5 trims the file back to its size at the next flush.
  QuietHdf5Errors quiet;
  const std::string what = "reserve file space";
  hsize_t size = 0;
  checked_status(H5Fget_filesize(file_.get(), &size), file_name_, what);
  void* handle = nullptr;
  checked_status(H5Fget_vfd_handle(file_.get(), H5P_DEFAULT, &handle), file_name_, what);
  const int fd = *static_cast<int*>(handle);
  struct stat st {};
  const hsize_t wanted = size + bytes;
  if (::fstat(fd, &st) != 0 || (static_cast<hsize_t>(st.st_size) < wanted &&
                                ::ftruncate(fd, static_cast<off_t>(wanted)) != 0))
    throw IoError(file_name_.string() + ": cannot " + what + " (" + std::strerror(errno) + ")");
}

void Hdf5File::flush() {
  reserve(kFlushSlack);
  QuietHdf5Errors quiet;
  checked_status(H5Fflush(file_.get(), H5F_SCOPE_GLOBAL), file_name_, "flush the file");
}

}  // namespace fissure
