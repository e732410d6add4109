#pragma once
/// @file
/// Where wobble's data lives: the folders problems/, scenes/ and solutions/.
///
/// One rule, in this order (the first that applies wins):
/// 1. `--data-dir DIR` given on the command line (set_data_dir): DIR/problems, ...;
/// 2. the environment: WOBBLE_PROBLEMS, WOBBLE_SCENES, WOBBLE_SOLUTIONS name one folder each,
///    WOBBLE_DATA_DIR the folder holding all three;
/// 3. next to the program: BIN/../share/wobble/ when the program is installed
///    (`cmake --install`, the .deb), found from /proc/self/exe;
/// 4. the source tree the program was built from (a build that was not installed).
/// An explicit choice wins over the installed copy, and that over the source tree.
#include <filesystem>
#include <string>

namespace wobble {

/// "problems", "scenes" or "solutions": the folder by the rule above.
std::filesystem::path data_folder(const std::string& name);

/// --data-dir: every data folder is looked up under `dir` from now on.
/// @throws InputError if `dir` is not a folder.
void set_data_dir(const std::filesystem::path& dir);

}  // namespace wobble
