#pragma once
/// @file
/// The width of the terminal a command writes its verdicts to, for their lines to break at
/// spaces (core/word_wrap.hpp) rather than where the terminal folds them, inside a word.
#include <cstddef>

namespace wobble::cli {

/// The columns of the terminal on standard output; 0 where it is no terminal (output piped to a
/// file or a program keeps its lines whole).
std::size_t terminal_columns();

}  // namespace wobble::cli
