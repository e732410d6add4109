#include "core/word_wrap.hpp"

#include "core/characters.hpp"

namespace wobble {

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
    // On this line if a space and the word fit, or it is the line's first word.
    if (!line_has_word || used + 1 + w <= width) {
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

// Whether a line begins a paragraph of its own however it follows another: a Markdown list's
// item or a table's row, which a statement could hold.
bool starts_own_line(const std::string& line) {
  return line.rfind("- ", 0) == 0 || line.rfind("* ", 0) == 0 || line.rfind("|", 0) == 0 ||
         (!line.empty() && is_digit(line[0]) && line.find(". ") != std::string::npos &&
          line.find_first_not_of("0123456789") == line.find(". "));
}

// The length of the label "(a) " or "(12) " that `paragraph` begins with, or 0.
std::size_t labelled(const std::string& paragraph) {
  const std::size_t close = paragraph.find(") ");
  if (paragraph.empty() || paragraph[0] != '(' || close == std::string::npos || close < 2 ||
      close > 4)
    return 0;
  for (std::size_t i = 1; i < close; ++i) {
    if (!is_letter(paragraph[i]) && !is_digit(paragraph[i])) return 0;
  }
  return close + 2;
}
}  // namespace

std::string word_wrapped(const std::string& text, std::size_t width, const std::string& first,
                         const std::string& rest) {
  if (width == 0) return first + text + "\n";
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

std::string reflowed(const std::string& text, std::size_t width) {
  if (width == 0) return text;
  std::string out, paragraph;
  const auto flush = [&] {
    if (!paragraph.empty()) {
      // A question's label, "(a) ", hangs: its text is indented under the text, not the label.
      const std::size_t label = labelled(paragraph);
      out += word_wrapped(paragraph.substr(label), width, paragraph.substr(0, label),
                          std::string(label, ' '));
    }
    paragraph.clear();
  };
  std::size_t at = 0;
  while (at < text.size()) {
    std::size_t end = text.find('\n', at);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(at, end - at);
    at = end + 1;
    const std::size_t indent = line.find_first_not_of(' ');
    if (indent == std::string::npos) {  // a blank line ends a paragraph
      flush();
      out += "\n";
      continue;
    }
    if (indent > 0) {
      flush();
      out += word_wrapped(line.substr(indent), width, line.substr(0, indent),
                          std::string(indent + 2, ' '));
      continue;
    }
    if (starts_own_line(line)) flush();
    paragraph += (paragraph.empty() ? "" : " ") + line;
  }
  flush();
  return out;
}

}  // namespace wobble
