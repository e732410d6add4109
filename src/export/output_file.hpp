#pragma once
/// @file
/// What an export produces: files as bytes with their paths (relative to where the user asked
/// for them), written by the command line all or nothing (io/atomic_write.hpp).
#include <string>
#include <vector>

namespace wobble::exports {

struct OutputFile {
  std::string path;  ///< relative, '/'-separated
  std::string content;
  bool executable = false;  ///< a script (mode 0755)
};

}  // namespace wobble::exports
