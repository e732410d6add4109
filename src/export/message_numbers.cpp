#include "export/message_numbers.hpp"

#include <cctype>
#include <stdexcept>

namespace wobble::exports {

namespace {
bool digit(char c) {
  return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

// A byte a name may hold before a digit: "rate_axis2", "I3", "ω3" (UTF-8's bytes), "0.5".
bool name_byte(char c) {
  const auto u = static_cast<unsigned char>(c);
  return std::isalnum(u) || c == '_' || c == '.' || u >= 0x80;
}

// The end of the number that starts at text[at] (a digit).
std::size_t number_end(const std::string& text, std::size_t at) {
  std::size_t end = at;
  while (end < text.size() && digit(text[end])) ++end;
  if (end + 1 < text.size() && text[end] == '.' && digit(text[end + 1])) {
    ++end;
    while (end < text.size() && digit(text[end])) ++end;
  }
  // "1e+10", "2.623e-07": an exponent only where digits follow (not "1 end", "2e").
  if (end < text.size() && (text[end] == 'e' || text[end] == 'E')) {
    std::size_t exp = end + 1;
    if (exp < text.size() && (text[exp] == '+' || text[exp] == '-')) ++exp;
    if (exp < text.size() && digit(text[exp])) {
      while (exp < text.size() && digit(text[exp])) ++exp;
      end = exp;
    }
  }
  return end;
}
}  // namespace

MessageNumbers message_numbers(const std::string& message) {
  MessageNumbers out;
  std::string words;
  for (std::size_t at = 0; at < message.size();) {
    const bool starts = digit(message[at]) && (at == 0 || !name_byte(message[at - 1]));
    if (!starts) {
      words += message[at++];
      continue;
    }
    // "2π/2.094": 2 is a number, π a word after it.
    const std::size_t end = number_end(message, at);
    // "1/s", "1/day": a unit's 1 is a word of the unit.
    if (end == at + 1 && message[at] == '1' && end + 1 < message.size() && message[end] == '/' &&
        std::isalpha(static_cast<unsigned char>(message[end + 1]))) {
      words += message[at++];
      continue;
    }
    out.words.push_back(std::move(words));
    words.clear();
    out.numbers.push_back(message.substr(at, end - at));
    at = end;
  }
  out.words.push_back(std::move(words));
  return out;
}

std::string with_numbers(const MessageNumbers& m, const std::vector<std::string>& numbers) {
  if (numbers.size() + 1 != m.words.size())
    throw std::logic_error("with_numbers: one number for each place between words");
  std::string out = m.words[0];
  for (std::size_t i = 0; i < numbers.size(); ++i) out += numbers[i] + m.words[i + 1];
  return out;
}

}  // namespace wobble::exports
