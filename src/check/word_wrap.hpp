#pragma once
/// @file
/// Lines of the worksheet broken at spaces to the terminal's width, so that a long verdict or
/// hint does not break inside a word ("(Eul" | "er's)") where the terminal folds it.
#include <cstddef>
#include <string>

namespace wobble::check {

/// `text` (one line) after `first`, broken at its spaces into lines of at most `width` columns
/// (core/characters.hpp's columns), each line after the first begun with `rest`, each ended by
/// '\n'. A word wider than a line stays whole on its own line (the terminal folds it); `width`
/// 0 leaves the text one line (piped output, where no width is known).
std::string word_wrapped(const std::string& text, std::size_t width, const std::string& first,
                         const std::string& rest);

}  // namespace wobble::check
