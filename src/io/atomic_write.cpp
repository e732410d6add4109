#include "io/atomic_write.hpp"

#include <fcntl.h>
#include <stdio.h>  // renameat2, RENAME_NOREPLACE (glibc 2.28)
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "core/input_error.hpp"

namespace wobble {

bool write_fully(int fd, std::string_view data) {
  std::size_t written = 0;
  while (written < data.size()) {
    const ssize_t n = ::write(fd, data.data() + written, data.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    written += static_cast<std::size_t>(n);
  }
  return true;
}

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

void require_can_create_in(const std::filesystem::path& dir, const std::string& what) {
  std::string tmpl = (dir / ".wobble-probe.XXXXXX").string();
  const int fd = ::mkstemp(tmpl.data());
  if (fd < 0) {
    throw std::runtime_error(what + ": cannot be written here (" + std::strerror(errno) +
                             "); nothing was computed");
  }
  ::close(fd);
  ::unlink(tmpl.c_str());
}

void require_folder_can_be_made(const std::filesystem::path& dir, const std::string& option) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) {
    throw InputError(option + ": " + dir.string() + " is a file, not a folder");
  }
  fs::path existing = fs::absolute(dir, ec);
  while (!fs::exists(existing, ec) && existing.has_relative_path())
    existing = existing.parent_path();
  if (!fs::is_directory(existing, ec)) {
    throw InputError(option + ": " + dir.string() + ": " + existing.string() +
                     " is a file, not a folder");
  }
  require_can_create_in(existing,
                        option + ": " + dir.string() +
                            (fs::exists(dir, ec) ? "" : " (in " + existing.string() + ")"));
}

void require_writable(const std::filesystem::path& target) {
  require_regular_or_absent(target);
  require_can_create_in(target.has_parent_path() ? target.parent_path() : ".", target.string());
}

namespace {
using Producer = std::function<void(const std::function<void(std::string_view)>&)>;

// The content in an exclusive temporary beside the target, flushed and closed: its path.
std::filesystem::path write_temporary(const std::filesystem::path& target, const Producer& produce) {
  require_regular_or_absent(target);
  const std::filesystem::path dir = target.has_parent_path() ? target.parent_path() : ".";
  std::string name = ".";  // appended piece by piece: GCC 12 -Wrestrict false positive on "a" + s
  name += target.filename().string();
  name += ".tmp.XXXXXX";
  std::string tmpl = (dir / name).string();
  const int fd = ::mkstemp(tmpl.data());
  bool open = fd >= 0;
  const auto discard = [&] {
    if (!open) return;
    ::close(fd);
    ::unlink(tmpl.c_str());
    open = false;
  };
  auto fail = [&](const std::string& what) {
    const std::string why = std::strerror(errno);
    discard();
    throw std::runtime_error(target.string() + ": cannot " + what + ": " + why);
  };
  if (fd < 0) fail("create a temporary file");
  const auto write_all = [&](std::string_view content) {
    if (!write_fully(fd, content)) fail("write");
  };
  std::string buffer;
  constexpr std::size_t kBuffer = std::size_t{1} << 16;
  try {
    produce([&](std::string_view piece) {
      buffer += piece;
      if (buffer.size() >= kBuffer) {
        write_all(buffer);
        buffer.clear();
      }
    });
  } catch (...) {
    discard();  // the producer failed (or was interrupted): no temporary is left behind
    throw;
  }
  write_all(buffer);
  if (::fchmod(fd, 0644) != 0 || ::fsync(fd) != 0) fail("flush");
  if (::close(fd) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(tmpl.c_str());
    throw std::runtime_error(target.string() + ": cannot close: " + why);
  }
  return tmpl;
}

// rename without replacing: renameat2 where the file system supports it, else link + unlink
// (both fail with EEXIST when the target exists).
bool move_no_replace(const std::filesystem::path& from, const std::filesystem::path& to) {
  if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0) return true;
  if (errno != EINVAL && errno != ENOSYS) return false;
  if (::link(from.c_str(), to.c_str()) != 0) return false;
  ::unlink(from.c_str());
  return true;
}
}  // namespace

void write_atomically(const std::filesystem::path& target, const std::string& content) {
  write_atomically_with(target, [&](const auto& append) { append(content); });
}

void write_atomically_with(const std::filesystem::path& target, const Producer& produce) {
  const std::filesystem::path tmp = write_temporary(target, produce);
  if (::rename(tmp.c_str(), target.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(tmp.c_str());
    throw std::runtime_error(target.string() + ": cannot replace: " + why);
  }
}

StagedFiles::~StagedFiles() {
  if (committed_) return;
  for (const auto& [tmp, target] : staged_) ::unlink(tmp.c_str());
}

void StagedFiles::stage(const std::filesystem::path& target, const std::string& content) {
  staged_.emplace_back(write_temporary(target, [&](const auto& append) { append(content); }),
                       target);
}

void StagedFiles::commit() {
  std::size_t moved = 0;
  for (; moved < staged_.size(); ++moved) {
    const auto& [tmp, target] = staged_[moved];
    const bool ok = replace_ ? ::rename(tmp.c_str(), target.c_str()) == 0
                             : move_no_replace(tmp, target);
    if (ok) continue;
    const std::string why = errno == EEXIST ? "it appeared meanwhile (another run writing there?)"
                                            : std::strerror(errno);
    // Take back what this set moved (each was absent before: no-replace), remove the rest.
    if (!replace_) {
      for (std::size_t i = 0; i < moved; ++i) ::unlink(staged_[i].second.c_str());
    }
    for (std::size_t i = moved; i < staged_.size(); ++i) ::unlink(staged_[i].first.c_str());
    committed_ = true;
    throw std::runtime_error(target.string() + ": cannot be put in place: " + why +
                             "; none of this run's files were left");
  }
  committed_ = true;
}

}  // namespace wobble
