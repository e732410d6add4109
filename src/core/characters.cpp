#include "core/characters.hpp"

#include <algorithm>
#include <boost/locale/utf.hpp>
#include <cctype>
#include <cstdio>

namespace wobble {

namespace {
using Utf8 = boost::locale::utf::utf_traits<char>;
using boost::locale::utf::code_point;

struct Decoded {
  code_point code;  ///< boost::locale::utf::illegal or incomplete for a byte that is no UTF-8
  std::size_t bytes;
};

Decoded decode(const std::string& text, std::size_t i) {
  auto it = text.begin() + static_cast<std::ptrdiff_t>(i);
  const code_point c = Utf8::decode(it, text.end());
  if (c == boost::locale::utf::illegal || c == boost::locale::utf::incomplete) return {c, 1};
  return {c, static_cast<std::size_t>(it - text.begin()) - i};
}

bool is_control(code_point c) {
  return c < 0x20 || (c >= 0x7F && c <= 0x9F);
}

std::string code_text(code_point c) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "U+%04X", static_cast<unsigned>(c));
  return buf;
}

bool is_valid(code_point c) {
  return c != boost::locale::utf::illegal && c != boost::locale::utf::incomplete;
}
// The combining marks a key or an answer puts on a letter: the diacritics (the dot of ψ̇, the
// hat of x̂) and those for symbols (the arrow of v⃗). They take no column of their own.
bool is_combining(code_point c) {
  return (c >= 0x0300 && c <= 0x036F) || (c >= 0x1AB0 && c <= 0x1AFF) ||
         (c >= 0x1DC0 && c <= 0x1DFF) || (c >= 0x20D0 && c <= 0x20FF) ||
         (c >= 0xFE20 && c <= 0xFE2F);
}
}  // namespace

std::size_t columns(const std::string& text) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < text.size();) {
    const Decoded d = decode(text, i);
    if (!is_valid(d.code) || !is_combining(d.code)) ++n;
    i += d.bytes;
  }
  return n;
}

bool starts_as_utf16(const std::string& text) {
  return text.size() >= 2 &&
         ((text[0] == '\xff' && text[1] == '\xfe') || (text[0] == '\xfe' && text[1] == '\xff'));
}

bool is_letter(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) != 0;
}
bool is_digit(char c) {
  return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

std::string character_name(const std::string& text, std::size_t i, std::size_t* bytes) {
  const Decoded d = decode(text, i);
  if (bytes != nullptr) *bytes = d.bytes;
  if (!is_valid(d.code)) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "the byte 0x%02X, which is no UTF-8",
                  static_cast<unsigned char>(text[i]));
    return buf;
  }
  if (is_control(d.code)) return "the control character " + code_text(d.code);
  return "'" + text.substr(i, d.bytes) + "' (" + code_text(d.code) + ")";
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

std::string ascii_lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool is_control_at(const std::string& text, std::size_t i) {
  const Decoded d = decode(text, i);
  return is_valid(d.code) && is_control(d.code);
}

std::string printable(const std::string& text, std::size_t max_characters) {
  std::string out;
  std::size_t characters = 0, i = 0;
  for (; i < text.size() && characters < max_characters; ++characters) {
    const Decoded d = decode(text, i);
    out += is_valid(d.code) && !is_control(d.code) ? text.substr(i, d.bytes) : "?";
    i += d.bytes;
  }
  return i < text.size() ? out + "..." : out;
}

std::size_t commas_between_digits(const std::string& typed) {
  std::size_t n = 0;
  for (std::size_t i = 1; i + 1 < typed.size(); ++i) {
    if (typed[i] == ',' && is_digit(typed[i - 1]) && is_digit(typed[i + 1])) ++n;
  }
  return n;
}

std::string digits_ungrouped(const std::string& typed) {
  // The separator at i and its length: a comma, a space, or a thin, narrow no-break or no-break
  // space (as SI writes and word processors set long numbers).
  const auto separator_at = [&](std::size_t i) -> std::pair<std::string, std::size_t> {
    for (const std::string sep : {",", " ", "\u2009", "\u202F", "\u00A0"}) {
      if (typed.compare(i, sep.size(), sep) == 0) return {sep, sep.size()};
    }
    return {"", 0};
  };
  std::size_t i = typed.find_first_not_of(" ");
  if (i == std::string::npos) return "";
  std::string out;
  if (typed[i] == '-' || typed[i] == '+') out += typed[i++];
  const std::size_t lead = i;
  while (i < typed.size() && is_digit(typed[i])) out += typed[i++];
  if (i == lead || i - lead > 3) return "";
  std::string used;  // the separator, the same throughout
  int groups = 0;
  for (;;) {
    const auto [sep, length] = separator_at(i);
    if (length == 0 || (!used.empty() && sep != used)) break;
    const std::size_t digits = i + length;
    std::size_t end = digits;
    while (end < typed.size() && is_digit(typed[end])) ++end;
    if (end - digits != 3) break;
    used = sep;
    out += typed.substr(digits, 3);
    i = end;
    ++groups;
  }
  if (groups == 0) return "";
  bool fraction = false;
  // A decimal point, or after groups of spaces a decimal comma ("26 233 128,66", as French
  // and SI write it).
  if (i < typed.size() && (typed[i] == '.' || (typed[i] == ',' && used != ","))) {
    const std::size_t start = ++i;
    while (i < typed.size() && is_digit(typed[i])) ++i;
    fraction = i > start;
    if (fraction) out += "." + typed.substr(start, i - start);
  }
  if (used == "," && groups == 1 && !fraction) return "";
  // Then nothing, a unit after a space, or one glued on; no more digits or separators.
  if (i == typed.size() || typed[i] == ' ') return out;
  const auto c = static_cast<unsigned char>(typed[i]);
  return std::isalpha(c) != 0 || (c >= 0x80 && separator_at(i).second == 0) ? out : "";
}

std::string decimal_comma_or_grouping(const std::string& typed) {
  if (!looks_like_decimal_comma(typed)) return "";
  const std::size_t lead = typed.find_first_not_of("-+ "), comma = typed.find(',');
  std::size_t end = comma + 1;
  while (end < typed.size() && is_digit(typed[end])) ++end;
  const bool exponent = end < typed.size() && (typed[end] == 'e' || typed[end] == 'E');
  if (comma - lead > 3 || typed[lead] == '0' || end - comma != 4 || exponent) return "";
  return typed.substr(typed.find_first_not_of(' '), comma - typed.find_first_not_of(' ')) +
         typed.substr(comma + 1, 3);
}

bool looks_like_decimal_comma(const std::string& typed) {
  const std::size_t comma = typed.find(',');
  if (comma == std::string::npos || typed.find(',', comma + 1) != std::string::npos) return false;
  const std::size_t start = std::min(typed.find_first_not_of("-+ "), comma);
  if (start == comma || !std::all_of(typed.begin() + static_cast<std::ptrdiff_t>(start),
                                     typed.begin() + static_cast<std::ptrdiff_t>(comma), is_digit))
    return false;
  const auto digits_from = [&](std::size_t i) {
    while (i < typed.size() && is_digit(typed[i])) ++i;
    return i;
  };
  std::size_t end = digits_from(comma + 1);
  if (end == comma + 1) return false;
  if (end < typed.size() && (typed[end] == 'e' || typed[end] == 'E')) {  // an exponent "e-2"
    const std::size_t power =
        end + 1 < typed.size() && (typed[end + 1] == '-' || typed[end + 1] == '+') ? end + 2
                                                                                   : end + 1;
    end = digits_from(power);
    if (end == power) return false;
  }
  // Then nothing, or a unit: after a space, or glued on ("15,5deg", "15,5°").
  if (end == typed.size() || typed[end] == ' ') return true;
  const auto c = static_cast<unsigned char>(typed[end]);
  return std::isalpha(c) != 0 || c >= 0x80;
}

}  // namespace wobble
