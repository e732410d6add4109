#pragma once
/// @file
/// Writing a file so that readers see the old content or the new, never a part: the content
/// goes to a temporary file in the same folder, is flushed to disk, then renamed over the target.
#include <filesystem>
#include <string>

namespace wobble {

/// @throws std::runtime_error if `target` exists and is not a regular file (a device such as
///         /dev/null, a folder, a symbolic link): wobble replaces regular files only.
void require_regular_or_absent(const std::filesystem::path& target);

/// Fails before any work if `target` could not be written: not a regular file, or its folder
/// missing or not writable (a temporary is created there exclusively and removed again).
/// @throws std::runtime_error naming the file and why.
void require_writable(const std::filesystem::path& target);

/// @throws std::runtime_error naming the file if any step fails, or if the target exists and is
///         not a regular file (a device such as /dev/null, a folder, a symbolic link); the
///         temporary is removed and the target is left as it was.
void write_atomically(const std::filesystem::path& target, const std::string& content);

}  // namespace wobble
