#include "render/atomic_write.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace wobble {

void require_regular_or_absent(const std::filesystem::path& target) {
  // Renaming over /dev/null or a link would replace the device node or the link itself (and as
  // root nothing stops it).
  std::error_code ec;
  const auto status = std::filesystem::symlink_status(target, ec);
  if (!ec && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
    throw std::runtime_error(target.string() +
                             ": is not a regular file (a device, folder or link); wobble writes "
                             "regular files only");
  }
}

void require_writable(const std::filesystem::path& target) {
  require_regular_or_absent(target);
  const std::filesystem::path dir = target.has_parent_path() ? target.parent_path() : ".";
  std::string tmpl = (dir / ".wobble-probe.XXXXXX").string();
  const int fd = ::mkstemp(tmpl.data());
  if (fd < 0) {
    throw std::runtime_error(target.string() + ": cannot be written here (" +
                             std::strerror(errno) + "); nothing was computed");
  }
  ::close(fd);
  ::unlink(tmpl.c_str());
}

void write_atomically(const std::filesystem::path& target, const std::string& content) {
  require_regular_or_absent(target);
  const std::filesystem::path dir = target.has_parent_path() ? target.parent_path() : ".";
  std::string name = ".";  // appended piece by piece: GCC 12 -Wrestrict false positive on "a" + s
  name += target.filename().string();
  name += ".tmp.XXXXXX";
  std::string tmpl = (dir / name).string();
  const int fd = ::mkstemp(tmpl.data());
  auto fail = [&](const std::string& what) {
    const std::string why = std::strerror(errno);
    if (fd >= 0) {
      ::close(fd);
      ::unlink(tmpl.c_str());
    }
    throw std::runtime_error(target.string() + ": cannot " + what + ": " + why);
  };
  if (fd < 0) fail("create a temporary file");
  std::size_t written = 0;
  while (written < content.size()) {
    const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("write");
    }
    written += static_cast<std::size_t>(n);
  }
  if (::fchmod(fd, 0644) != 0 || ::fsync(fd) != 0) fail("flush");
  if (::close(fd) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(tmpl.c_str());
    throw std::runtime_error(target.string() + ": cannot close: " + why);
  }
  if (::rename(tmpl.c_str(), target.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(tmpl.c_str());
    throw std::runtime_error(target.string() + ": cannot replace: " + why);
  }
}

}  // namespace wobble
