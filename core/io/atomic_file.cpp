#include "core/io/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

#include "core/base/errors.h"

namespace fissure {

namespace {

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& what, int error) {
  throw IoError(file.string() + ": cannot " + what + " (" + std::strerror(error) + ")");
}

}  // namespace

void write_file_atomically(const std::filesystem::path& file, std::string_view content) {
  write_file_atomically(file, {content});
}

void write_file_atomically(const std::filesystem::path& file,
                           std::initializer_list<std::string_view> pieces) {
  std::filesystem::path temporary = file;
  temporary += ".tmp";
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail(temporary, "create the file", errno);
  for (std::string_view content : pieces) {
    std::size_t written = 0;
    while (written < content.size()) {
      const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) {
        const int error = errno;
        ::close(fd);
        ::unlink(temporary.c_str());
        fail(temporary, "write", error);
      }
      written += static_cast<std::size_t>(n);
    }
  }
  // No fsync: the guarantee is against the process dying, which leaves the
  // page cache intact; an fsync per output frame would cost more than the frame.
  if (::close(fd) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    fail(temporary, "write", error);
  }
  if (std::rename(temporary.c_str(), file.c_str()) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    fail(file, "replace the file with " + temporary.filename().string(), error);
  }
}

}  // namespace fissure
