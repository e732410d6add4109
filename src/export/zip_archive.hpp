#pragma once
/// @file
/// Files as one zip archive (libzip), for the Gradescope autograder. Kept apart from the rest of
/// the export layer: libzip brings OpenSSL's libcrypto with it, whose loading took a third of
/// every command's start-up, so the program loads it only when it writes a zip (on_demand/).
#include <string>
#include <vector>

#include "export/output_file.hpp"

namespace wobble::exports {

/// The files as one zip archive, in memory: scripts executable (mode 0755), a .deb stored as it
/// is (it is compressed already), the rest deflated. @throws std::runtime_error if libzip fails.
std::string zip_archive(const std::vector<OutputFile>& files);

}  // namespace wobble::exports
