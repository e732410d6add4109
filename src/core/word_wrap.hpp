#pragma once
/// @file
/// Text broken at spaces to a terminal's width, so that a long verdict, hint or step does not
/// break inside a word ("(Eul" | "er's)") where the terminal folds it.
#include <cstddef>
#include <string>

namespace wobble {

/// `text` (one line) after `first`, broken at its spaces into lines of at most `width` columns
/// (core/characters.hpp's columns), each line after the first begun with `rest`, each ended by
/// '\n'. A word wider than a line stays whole on its own line (the terminal folds it). A text of
/// several lines has each broken, those after the first after `rest`. `width` 0 gives
/// first + text + '\n' as it is (piped output, where no width is known).
std::string word_wrapped(const std::string& text, std::size_t width, const std::string& first,
                         const std::string& rest);

/// A document at `width` columns: its paragraphs (runs of lines at the margin, as a problem
/// file breaks its statement, which Markdown reads as one) joined and broken again at spaces,
/// its indented lines (a table of values) each broken after their indent and two spaces more;
/// a blank line, a Markdown list's item or a table's row begins a paragraph. As it is where
/// `width` is 0.
std::string reflowed(const std::string& text, std::size_t width);

}  // namespace wobble
