#include "core/io/hdf5_file.h"

#include <numeric>

#include "core/base/errors.h"

namespace fissure {

namespace {

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
    if (e->desc && *e->desc)
      static_cast<std::vector<std::string>*>(out)->emplace_back(e->desc);
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

Hdf5File::Hdf5File(const std::filesystem::path& file) : file_name_(file) {
  QuietHdf5Errors quiet;
  // Freed file space is never handed out again within the run: otherwise a
  // frame's raw data could overwrite a block (an old group heap, say) that
  // the last flushed metadata still points to, and a kill during that frame
  // would corrupt frames that were already complete.
  Hdf5Handle fcpl(checked_id(H5Pcreate(H5P_FILE_CREATE), file, "create a property list"),
                  H5Pclose);
  checked_status(H5Pset_file_space_strategy(fcpl.get(), H5F_FSPACE_STRATEGY_AGGR, 0, 1), file,
                 "set the file space strategy");
  // No file lock, so that ParaView or h5py can look at the frames written so
  // far while the run goes on.
  Hdf5Handle fapl(checked_id(H5Pcreate(H5P_FILE_ACCESS), file, "create a property list"),
                  H5Pclose);
  checked_status(H5Pset_file_locking(fapl.get(), false, true), file, "disable file locking");
  // A small metadata cache: every flush scans all cached entries (HDF5 1.10),
  // and entries of earlier frames are never needed again, so a large cache
  // only makes each frame slower than the one before.
  H5AC_cache_config_t cache;
  cache.version = H5AC__CURR_CACHE_CONFIG_VERSION;
  checked_status(H5Pget_mdc_config(fapl.get(), &cache), file, "read the cache settings");
  cache.set_initial_size = true;
  cache.initial_size = cache.min_size = 256 * 1024;
  cache.max_size = 1024 * 1024;
  checked_status(H5Pset_mdc_config(fapl.get(), &cache), file, "set the cache size");
  file_ = Hdf5Handle(
      checked_id(H5Fcreate(file.c_str(), H5F_ACC_TRUNC, fcpl.get(), fapl.get()), file,
                 "create the file"),
      H5Fclose);
}

Hdf5File::~Hdf5File() {
  QuietHdf5Errors quiet;
  file_.reset();
}

void Hdf5File::create_group(const std::string& path) {
  QuietHdf5Errors quiet;
  Hdf5Handle group(checked_id(H5Gcreate2(file_.get(), path.c_str(), H5P_DEFAULT, H5P_DEFAULT,
                                         H5P_DEFAULT),
                              file_name_, "create group " + path),
                   H5Gclose);
}

void Hdf5File::write(const std::string& path, std::span<const double> data,
                     const std::vector<hsize_t>& shape) {
  write_dataset(path, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, data.data(), data.size(), shape);
}

void Hdf5File::write(const std::string& path, std::span<const int> data,
                     const std::vector<hsize_t>& shape) {
  write_dataset(path, H5T_STD_I32LE, H5T_NATIVE_INT, data.data(), data.size(), shape);
}

void Hdf5File::write_dataset(const std::string& path, hid_t file_type, hid_t mem_type,
                             const void* data, std::size_t n, const std::vector<hsize_t>& shape) {
  const hsize_t expected =
      std::accumulate(shape.begin(), shape.end(), hsize_t{1}, std::multiplies<hsize_t>());
  FISSURE_CHECK(expected == n, IoError,
                file_name_.string() << ": cannot write dataset " << path << ": " << n
                                    << " values do not fill its shape");
  QuietHdf5Errors quiet;
  const std::string what = "write dataset " + path;
  Hdf5Handle space(checked_id(H5Screate_simple(static_cast<int>(shape.size()), shape.data(),
                                               nullptr),
                              file_name_, what),
                   H5Sclose);
  Hdf5Handle dataset(checked_id(H5Dcreate2(file_.get(), path.c_str(), file_type, space.get(),
                                           H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                                file_name_, what),
                     H5Dclose);
  // An empty dataset has nothing to transfer (and HDF5 rejects a null buffer).
  if (n == 0) return;
  checked_status(H5Dwrite(dataset.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
                 file_name_, what);
}

void Hdf5File::write_strings(const std::string& path, const std::vector<std::string>& values) {
  QuietHdf5Errors quiet;
  const std::string what = "write dataset " + path;
  Hdf5Handle type(checked_id(H5Tcopy(H5T_C_S1), file_name_, what), H5Tclose);
  checked_status(H5Tset_size(type.get(), H5T_VARIABLE), file_name_, what);
  checked_status(H5Tset_cset(type.get(), H5T_CSET_UTF8), file_name_, what);
  const hsize_t n = values.size();
  Hdf5Handle space(checked_id(H5Screate_simple(1, &n, nullptr), file_name_, what), H5Sclose);
  Hdf5Handle dataset(checked_id(H5Dcreate2(file_.get(), path.c_str(), type.get(), space.get(),
                                           H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                                file_name_, what),
                     H5Dclose);
  if (n == 0) return;
  std::vector<const char*> pointers;
  pointers.reserve(values.size());
  for (const std::string& v : values) pointers.push_back(v.c_str());
  checked_status(H5Dwrite(dataset.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT,
                          pointers.data()),
                 file_name_, what);
}

void Hdf5File::write_scalar_attribute(const std::string& object, const std::string& name,
                                      hid_t file_type, hid_t mem_type, const void* value) {
  QuietHdf5Errors quiet;
  const std::string what = "write attribute " + name + " of " + object;
  Hdf5Handle space(checked_id(H5Screate(H5S_SCALAR), file_name_, what), H5Sclose);
  Hdf5Handle attribute(checked_id(H5Acreate_by_name(file_.get(), object.c_str(), name.c_str(),
                                                    file_type, space.get(), H5P_DEFAULT,
                                                    H5P_DEFAULT, H5P_DEFAULT),
                                  file_name_, what),
                       H5Aclose);
  checked_status(H5Awrite(attribute.get(), mem_type, value), file_name_, what);
}

void Hdf5File::write_attribute(const std::string& object, const std::string& name,
                               double value) {
  write_scalar_attribute(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
}

void Hdf5File::write_attribute(const std::string& object, const std::string& name, int value) {
  write_scalar_attribute(object, name, H5T_STD_I32LE, H5T_NATIVE_INT, &value);
}

void Hdf5File::write_attribute(const std::string& object, const std::string& name,
                               const std::string& value) {
  QuietHdf5Errors quiet;
  const std::string what = "write attribute " + name + " of " + object;
  Hdf5Handle type(checked_id(H5Tcopy(H5T_C_S1), file_name_, what), H5Tclose);
  checked_status(H5Tset_size(type.get(), value.size() + 1), file_name_, what);
  checked_status(H5Tset_strpad(type.get(), H5T_STR_NULLTERM), file_name_, what);
  checked_status(H5Tset_cset(type.get(), H5T_CSET_UTF8), file_name_, what);
  write_scalar_attribute(object, name, type.get(), type.get(), value.c_str());
}

void Hdf5File::flush() {
  QuietHdf5Errors quiet;
  checked_status(H5Fflush(file_.get(), H5F_SCOPE_GLOBAL), file_name_, "flush the file");
}

}  // namespace fissure
