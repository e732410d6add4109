#pragma once
/// @file
/// Writing a file so that readers see the old content or the new, never a part: the content
/// goes to a temporary file in the same folder, is flushed to disk, then renamed over the target.
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace wobble {

/// Writes all of `data` to `fd`, retrying after a signal (EINTR) and after a short write.
/// @return false with errno set on a write error.
bool write_fully(int fd, std::string_view data);

/// @throws std::runtime_error if `target` exists and is not a regular file (a device such as
///         /dev/null, a folder, a symbolic link): wobble replaces regular files only.
void require_regular_or_absent(const std::filesystem::path& target);

/// Fails before any work if no file can be created in the folder `dir` (a temporary is created
/// there exclusively and removed again).
/// @throws std::runtime_error "`what`: cannot be written here (why); nothing was computed".
void require_can_create_in(const std::filesystem::path& dir, const std::string& what);

/// Fails before any work if the folder `dir` (given as option `option`) is a file, or is missing
/// and could not be created with its parents, or exists and takes no file: the nearest folder on
/// its path that exists must take one.
/// @throws InputError "`option`: `dir` is a file, not a folder" (or an ancestor is);
///         std::runtime_error "`option`: `dir` (in that folder): cannot be written here (why)".
void require_folder_can_be_made(const std::filesystem::path& dir, const std::string& option);

/// Fails before any work if `target` could not be written: not a regular file, or its folder
/// missing or not writable (a temporary is created there exclusively and removed again).
/// @throws std::runtime_error naming the file and why.
void require_writable(const std::filesystem::path& target);

/// @throws std::runtime_error naming the file if any step fails, or if the target exists and is
///         not a regular file (a device such as /dev/null, a folder, a symbolic link); the
///         temporary is removed and the target is left as it was.
void write_atomically(const std::filesystem::path& target, const std::string& content);

/// The same for content produced a piece at a time: `produce` is called once with a function
/// that appends a piece (buffered, written as it grows), so a large file is never held whole.
void write_atomically_with(
    const std::filesystem::path& target,
    const std::function<void(const std::function<void(std::string_view)>& append)>& produce);

/// A set of files written all or nothing. stage() writes each content to an exclusive temporary
/// beside its target (flushed to disk); commit() renames them all into place. Destroyed before
/// commit (an error, Ctrl-C), it removes its temporaries and no target has changed.
/// With replace = false, commit() moves each file with no-replace (renameat2), so two runs
/// writing the same folder at once cannot mix: if a target appeared meanwhile, the files this
/// set already moved are taken back and commit() throws.
class StagedFiles {
 public:
  explicit StagedFiles(bool replace) : replace_(replace) {}
  ~StagedFiles();
  StagedFiles(const StagedFiles&) = delete;
  StagedFiles& operator=(const StagedFiles&) = delete;

  /// @throws std::runtime_error naming the target if the temporary cannot be written.
  void stage(const std::filesystem::path& target, const std::string& content);
  /// @throws std::runtime_error naming the file (nothing of this set left in place).
  void commit();
  std::size_t size() const { return staged_.size(); }

 private:
  bool replace_;
  bool committed_ = false;
  std::vector<std::pair<std::filesystem::path, std::filesystem::path>> staged_;  ///< temp, target
};

}  // namespace wobble
