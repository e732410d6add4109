#include "check/siunitx.hpp"

#include <array>
#include <cctype>
#include <map>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include "core/input_error.hpp"
#include "symbolic/units.hpp"

namespace wobble::check {

namespace {
const std::map<std::string, std::string>& unit_macros() {
  static const std::map<std::string, std::string> m{
      {"gram", "g"},     {"kilogram", "kg"}, {"metre", "m"},          {"meter", "m"},
      {"second", "s"},   {"minute", "min"},  {"hour", "h"},           {"day", "day"},
      {"radian", "rad"}, {"degree", "deg"},  {"arcminute", "arcmin"}, {"arcsecond", "arcsec"},
      {"joule", "J"},    {"newton", "N"},    {"hertz", "Hz"}};
  return m;
}

const std::map<std::string, std::string>& prefix_macros() {
  static const std::map<std::string, std::string> m{{"giga", "G"},  {"mega", "M"},  {"kilo", "k"},
                                                    {"centi", "c"}, {"milli", "m"}, {"micro", "u"},
                                                    {"nano", "n"}};
  return m;
}

// The siunitx commands read, and how many brace groups each takes.
const std::map<std::string, int>& commands() {
  static const std::map<std::string, int> m{{"SI", 2}, {"qty", 2},  {"num", 1},
                                            {"si", 1}, {"unit", 1}, {"ang", 1}};
  return m;
}

// The name of the command at s[i] == '\\' ("SI" for "\SI{"), "" if none.
std::string command_at(const std::string& s, std::size_t i) {
  std::size_t j = i + 1;
  while (j < s.size() && std::isalpha(static_cast<unsigned char>(s[j]))) ++j;
  return s.substr(i + 1, j - i - 1);
}

struct Scan {
  const std::string& s;
  std::size_t i;
  const std::string& field;

  void spaces() {
    while (i < s.size() && s[i] == ' ') ++i;
  }
  // The content of the brace group at i, and i past it.
  std::string group(const std::string& command) {
    spaces();
    if (i >= s.size() || s[i] != '{') {
      throw InputError(field + ": \\" + command + " without its {..}");
    }
    int depth = 0;
    for (std::size_t start = ++i; i < s.size(); ++i) {
      if (s[i] == '{') ++depth;
      if (s[i] == '}' && depth-- == 0) return s.substr(start, i++ - start);
    }
    throw InputError(field + ": \\" + command + "'s '{' without its '}'");
  }
  // "[per-mode=symbol]": options change only how siunitx prints.
  void options() {
    spaces();
    if (i < s.size() && s[i] == '[') {
      const std::size_t close = s.find(']', i);
      i = close == std::string::npos ? s.size() : close + 1;
    }
  }
};

// siunitx's number: spacing dropped, d or D as the exponent's e, x before a power of ten as
// \times ("1.2x10^3").
std::string number(const std::string& n) {
  std::string out;
  for (std::size_t i = 0; i < n.size(); ++i) {
    const char c = n[i];
    if (c == ' ' || c == '~' || c == '{' || c == '}') continue;
    if (c == '\\' && i + 1 < n.size() && (n[i + 1] == ',' || n[i + 1] == ' ')) {
      ++i;
      continue;
    }
    if (c == '\\') {  // "\times", "\cdot": a command as it stands, its letters no exponent's d
      std::size_t end = i + 1;
      while (end < n.size() && std::isalpha(static_cast<unsigned char>(n[end]))) ++end;
      out += n.substr(i, end - i) + " ";
      i = end - 1;
    } else if (c == '^') {  // "10^-4": the power's sign and digits in one group, as LaTeX wants
      const bool braced = i + 1 < n.size() && n[i + 1] == '{';
      const std::size_t from = i + 1 + (braced ? 1 : 0);
      std::size_t end = from;
      if (end < n.size() && (n[end] == '-' || n[end] == '+')) ++end;
      while (end < n.size() && std::isdigit(static_cast<unsigned char>(n[end]))) ++end;
      out += "^{" + n.substr(from, end - from) + "}";
      i = braced && end < n.size() && n[end] == '}' ? end : end - 1;
    } else if (c == 'x') {
      out += "\\times ";
    } else {
      out += c == 'd' || c == 'D' ? 'e' : c;
    }
  }
  return out;
}

// A unit in siunitx's macros, or as text, in the answer reader's grammar: "kg\,m^{2}".
std::string unit(const std::string& u, const std::string& field) {
  if (u.find('\\') == std::string::npos || u.find("\\,") != std::string::npos) {
    std::string out;  // "kg.m^2", "kg~m^2", "kg\,m^2": a dot or a tie joins units
    for (const char c : u) out += c == '.' || c == '~' ? std::string("\\,") : std::string(1, c);
    return out;
  }
  std::vector<std::pair<std::string, int>> units;
  std::string prefix;
  int next_power = 1, next_sign = 1;
  for (Scan p{u, 0, field}; p.i < u.size();) {
    p.spaces();
    if (p.i >= u.size()) break;
    if (u[p.i] != '\\') throw InputError(field + ": '" + u + "' mixes siunitx's macros with text");
    const std::string name = command_at(u, p.i);
    p.i += name.size() + 1;
    const auto power_of_last = [&](int power) {
      if (units.empty()) throw InputError(field + ": \\" + name + " after no unit in '" + u + "'");
      units.back().second *= power;
    };
    if (const auto pre = prefix_macros().find(name); pre != prefix_macros().end()) {
      prefix += pre->second;
    } else if (const auto m = unit_macros().find(name); m != unit_macros().end()) {
      units.emplace_back(prefix + m->second, next_sign * next_power);
      prefix.clear();
      next_power = next_sign = 1;
    } else if (name == "per") {
      next_sign = -1;
    } else if (name == "square" || name == "cubic") {
      next_power = name == "square" ? 2 : 3;
    } else if (name == "squared" || name == "cubed") {
      power_of_last(name == "squared" ? 2 : 3);
    } else if (name == "tothe" || name == "raiseto") {
      const std::string n = p.group(name);
      int power = 0;
      for (const char c : n) {
        if (!std::isdigit(static_cast<unsigned char>(c)) || power > 9) {
          throw InputError(field + ": \\" + name + "{" + n + "}: a power is a small whole number");
        }
        power = power * 10 + (c - '0');
      }
      if (name == "tothe") {
        power_of_last(power);
      } else {
        next_power = power;
      }
    } else {
      throw InputError(field + ": \\" + name +
                       " in a siunitx unit is not read (\\kilo\\gram\\metre\\squared, "
                       "\\radian\\per\\second, or the unit as text: kg.m^2)");
    }
  }
  if (units.empty()) throw InputError(field + ": no unit in '" + u + "'");
  std::string out;
  for (const auto& [name, power] : units)
    out +=
        (out.empty() ? "" : "\\,") + name + (power == 1 ? "" : "^{" + std::to_string(power) + "}");
  return out;
}

// \ang{44;41;37}: degrees, minutes and seconds of arc, as their sum in degrees.
std::string angle(const std::string& a, const std::string& field) {
  std::array<std::string, 3> parts;
  std::size_t k = 0;
  for (const char c : a) {
    if (c == ';') {
      if (++k == parts.size())
        throw InputError(field + ": \\ang{" + a + "} has more than three parts");
    } else if (c != ' ') {
      parts[k] += c;
    }
  }
  if (k == 0) return number(parts[0]) + "^\\circ";
  const std::string ascii = (parts[0].empty() ? "0" : parts[0]) + " deg " +
                            (parts[1].empty() ? "0" : parts[1]) + " arcmin" +
                            (k == 2 ? " " + (parts[2].empty() ? "0" : parts[2]) + " arcsec" : "");
  const std::string sum = sexagesimal_degrees(ascii, field);  // "(44 + 41/60) deg"
  if (sum == ascii) throw InputError(field + ": \\ang{" + a + "} is no angle");
  const std::size_t open = sum.find('(');  // after a sign, if any
  return sum.substr(0, open) + "\\left" + sum.substr(open, sum.rfind(')') - open) +
         "\\right)\\,\\mathrm{deg}";
}
}  // namespace

std::string siunitx_as_latex(const std::string& latex, const std::string& field) {
  std::string out;
  std::size_t done = 0;
  for (std::size_t i = latex.find('\\'); i != std::string::npos; i = latex.find('\\', i + 1)) {
    const std::string name = command_at(latex, i);
    const auto it = commands().find(name);
    if (it == commands().end()) continue;
    Scan p{latex, i + 1 + name.size(), field};
    p.options();
    const std::string first = p.group(name);
    std::string written;
    if (name == "num") written = number(first);
    if (name == "si" || name == "unit") written = "\\mathrm{" + unit(first, field) + "}";
    if (name == "ang") written = angle(first, field);
    if (it->second == 2)
      written = number(first) + "\\,\\mathrm{" + unit(p.group(name), field) + "}";
    out += latex.substr(done, i - done) + written;
    done = p.i;
    i = p.i - 1;
  }
  return done == 0 ? latex : out + latex.substr(done);
}

}  // namespace wobble::check
