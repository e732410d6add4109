#include "check/word_wrap.hpp"

#include "core/characters.hpp"

namespace wobble::check {

namespace {
// One line of text (no '\n'), wrapped, without its final '\n'.
std::string one_line_wrapped(const std::string& text, std::size_t width, const std::string& first,
                             const std::string& rest) {
  std::string out = first;
  std::size_t used = columns(first);
  const std::size_t indent = columns(rest);
  bool line_has_word = false;
  std::size_t at = 0;
  while (at <= text.size()) {
    std::size_t end = text.find(' ', at);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(at, end - at);
    const std::size_t w = columns(word);
    // On this line if a space and the word fit, or no width is known, or it is the first word.
    if (width == 0 || !line_has_word || used + 1 + w <= width) {
      if (line_has_word) {
        out += ' ';
        ++used;
      }
      out += word;
      used += w;
    } else {
      out += "\n" + rest + word;
      used = indent + w;
    }
    line_has_word = true;
    at = end + 1;
  }
  return out;
}
}  // namespace

std::string word_wrapped(const std::string& text, std::size_t width, const std::string& first,
                         const std::string& rest) {
  // A text of several lines (a hint's paragraphs): each wrapped, those after the first after
  // `rest`.
  std::string out;
  std::size_t at = 0;
  do {
    std::size_t end = text.find('\n', at);
    if (end == std::string::npos) end = text.size();
    out += one_line_wrapped(text.substr(at, end - at), width, at == 0 ? first : rest, rest) + "\n";
    at = end + 1;
  } while (at <= text.size());
  return out;
}

}  // namespace wobble::check
