#pragma once
/// @file
/// A message's numbers apart from its words: "this is the fast-top approximation M g l / (I3 ω3),
/// 16.2% below the exact value here" is the words around one number, 16.2. Two variants' lines
/// of one mistake differ only in their numbers, so a quiz that shows one feedback for every
/// variant (Moodle's, whose wildcards it substitutes per variant) shows the words once with a
/// wildcard in each number's place.
///
/// A number is ASCII digits with an optional decimal part and exponent ("0.3333", "1e+10",
/// "2.623e+07") that follows no letter, digit, '_', '.' or non-ASCII byte: a name's digits
/// (rate_axis2, I3, ω3) are words, and so is a unit's 1 ("1/s"). A sign is a word ("-308" is "-"
/// and 308).
#include <string>
#include <vector>

namespace wobble::exports {

struct MessageNumbers {
  std::vector<std::string> words;    ///< the text around the numbers: one more than numbers
  std::vector<std::string> numbers;  ///< as written
};

MessageNumbers message_numbers(const std::string& message);

/// The message again: words[0] numbers[0] words[1] .. (with `numbers` in their place).
std::string with_numbers(const MessageNumbers& m, const std::vector<std::string>& numbers);

}  // namespace wobble::exports
