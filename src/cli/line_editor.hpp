#pragma once
/// @file
/// Reading the worksheet's answers at a terminal with line editing: arrow keys, Emacs keys and
/// the history of this session (libedit's readline interface). Piped input does not use it.
#include "check/worksheet.hpp"

namespace wobble::cli {

/// Lines from the terminal through libedit; false at end of input (Ctrl-D).
check::ReadLine terminal_lines();

}  // namespace wobble::cli
