#include "check/program_notation.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <string_view>
#include <vector>

#include "check/brackets.hpp"
#include "symbolic/expression.hpp"
#include "symbolic/expression_guard.hpp"

namespace wobble::check {

namespace {
// How a program's call is read here.
enum class Reading {
  same,           // the function of the name `to`, the arguments as they are
  parameter,      // an elliptic integral of the parameter m: `to`(sqrt(m))
  value,          // Mathematica's N[x] (N[x, digits]): x itself
  swapped,        // Mathematica's ArcTan[x, y]: atan2(y, x); with one argument, atan
  degrees,        // np.radians(x): x degrees in radians
  two_arguments,  // Maple's arctan(y, x): atan2(y, x); with one argument, atan
};

struct Call {
  std::string_view from;
  std::string_view to;
  Reading reading = Reading::same;
};

// Mathematica's functions, called with square brackets.
constexpr std::array<Call, 16> kMathematica{{{"Sqrt", "sqrt"},
                                             {"Sin", "sin"},
                                             {"Cos", "cos"},
                                             {"Tan", "tan"},
                                             {"ArcSin", "asin"},
                                             {"ArcCos", "acos"},
                                             {"ArcTan", "atan", Reading::swapped},
                                             {"Exp", "exp"},
                                             {"Log", "log"},
                                             {"Sinh", "sinh"},
                                             {"Cosh", "cosh"},
                                             {"Tanh", "tanh"},
                                             {"Abs", "abs"},
                                             {"EllipticK", "EllipticK", Reading::parameter},
                                             {"EllipticE", "EllipticE", Reading::parameter},
                                             {"N", "", Reading::value}}};

// Python's and MATLAB's names for functions wobble names otherwise, called with parentheses.
// Maple's and Julia's two-argument arctangent, arctan(y, x) and atan(y, x), is atan2(y, x);
// Maple's evalf(x) is x, as Mathematica's N[x].
constexpr std::array<Call, 12> kPython{{{"arctan2", "atan2"},
                                        {"atan", "atan", Reading::two_arguments},
                                        {"arctan", "atan", Reading::two_arguments},
                                        {"evalf", "", Reading::value},
                                        {"fabs", "abs"},
                                        {"ellipk", "EllipticK", Reading::parameter},
                                        {"ellipe", "EllipticE", Reading::parameter},
                                        {"elliptic_k", "EllipticK", Reading::parameter},
                                        {"elliptic_e", "EllipticE", Reading::parameter},
                                        {"ellipke", "EllipticK", Reading::parameter},
                                        {"radians", "", Reading::degrees},
                                        {"deg2rad", "", Reading::degrees}}};

// Python's modules, the longest first ("scipy.special." before "special.").
constexpr std::array<std::string_view, 8> kModules{"scipy.special.", "special.", "numpy.", "np.",
                                                   "math.",          "sympy.",   "sp.",    "cmath."};

bool name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

template <std::size_t N>
const Call* find_call(const std::array<Call, N>& calls, const std::string& name) {
  for (const auto& c : calls) {
    if (c.from == name) return &c;
  }
  return nullptr;
}

// The name at s[at] and its end.
std::size_t name_end(const std::string& s, std::size_t at) {
  while (at < s.size() && name_char(s[at])) ++at;
  return at;
}

// Whether a module's prefix before `name` is a program's: the name is a function wobble reads
// (under any of its names) or pi. Other names keep theirs ("np.array(", which the reader
// unwraps, "np.float64(").
bool module_member(const std::string& name) {
  return name == "pi" || sym::is_function_name(name) || find_call(kPython, name) != nullptr;
}

std::string rewritten(const std::string& s);

// The call of `c` on `args` (each rewritten), as the reader writes it.
// `whole`: the call is the whole text (N[{40, 30, 70} Degree] is a vector, not a group).
std::string call_text(const Call& c, const std::vector<std::string>& args, bool whole) {
  std::string joined_args;
  for (const auto& a : args) joined_args += (joined_args.empty() ? "" : ", ") + a;
  switch (c.reading) {
    case Reading::parameter:
      return std::string(c.to) + "(sqrt(" + joined_args + "))";
    case Reading::value:  // a vector stays one: N[{1, 2}] is [1, 2], not ([1, 2])
      if (args.empty()) return "()";
      return whole || wrapped(args[0], '[') || wrapped(args[0], '{') ? args[0]
                                                                     : "(" + args[0] + ")";
    case Reading::swapped:
      if (args.size() == 2) return "atan2(" + args[1] + ", " + args[0] + ")";
      break;
    case Reading::degrees:
      // np.radians([40, 30, 70]): each entry of a list.
      if (args.size() == 1 && (wrapped(args[0], '[') || wrapped(args[0], '{'))) {
        std::string entries;
        for (const auto& e : top_level(args[0].substr(1, args[0].size() - 2), ','))
          entries += (entries.empty() ? "" : ", ") + ("((" + e + ")*pi/180)");
        return "[" + entries + "]";
      }
      return "((" + joined_args + ")*pi/180)";
    case Reading::two_arguments:
      if (args.size() == 2) return "atan2(" + joined_args + ")";
      break;
    case Reading::same:
      break;
  }
  return std::string(c.to) + "(" + joined_args + ")";
}

// The arguments between s[open] and its partner `close`, each rewritten.
std::vector<std::string> arguments(const std::string& s, std::size_t open, std::size_t close) {
  std::vector<std::string> args;
  for (const auto& a : top_level(s.substr(open + 1, close - open - 1), ',')) {
    args.push_back(rewritten(a));
  }
  return args;
}

// The end of Python's zero imaginary part at s[i], "+0j", "-0.j", "+0.00000000e+00j" (as
// NumPy shows a real root of np.roots, 4.995+0.j), or i if there is none there.
std::size_t zero_imaginary_end(const std::string& s, std::size_t i) {
  if (i >= s.size() || (s[i] != '+' && s[i] != '-')) return i;
  std::size_t k = i + 1;
  bool digits = false;
  for (; k < s.size() && (s[k] == '0' || s[k] == '.'); ++k) digits = digits || s[k] == '0';
  if (digits && k < s.size() && (s[k] == 'e' || s[k] == 'E')) {
    ++k;
    if (k < s.size() && (s[k] == '+' || s[k] == '-')) ++k;
    while (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k]))) ++k;
  }
  if (!digits || k >= s.size() || s[k] != 'j' || (k + 1 < s.size() && name_char(s[k + 1])))
    return i;
  return k + 1;
}

std::string rewritten(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    const char c = s[i];
    const bool after_digit = i > 0 && std::isdigit(static_cast<unsigned char>(s[i - 1]));
    // Python's complex number with no imaginary part: its real part.
    if (i > 0 && (after_digit || s[i - 1] == '.')) {
      if (const std::size_t end = zero_imaginary_end(s, i); end != i) {
        i = end;
        continue;
      }
    }
    // Mathematica's InputForm writes 2.395*^-7 for 2.395e-7.
    if (after_digit && s.compare(i, 2, "*^") == 0) {
      out += 'e';
      i += 2;
      continue;
    }
    // MATLAB's element-wise operators: on numbers, the operators themselves ("2.*R" is 2*R
    // read either way).
    if (c == '.' && i + 1 < s.size() && (s[i + 1] == '^' || s[i + 1] == '*' || s[i + 1] == '/')) {
      ++i;
      continue;
    }
    const bool starts_name = std::isalpha(static_cast<unsigned char>(c)) &&
                             (i == 0 || !(std::isalpha(static_cast<unsigned char>(s[i - 1])) ||
                                          s[i - 1] == '_' || s[i - 1] == '.'));
    if (!starts_name) {
      out += c;
      ++i;
      continue;
    }
    bool module = false;
    for (const auto m : kModules) {
      if (s.compare(i, m.size(), m) != 0) continue;
      const std::size_t at = i + m.size();
      if (module_member(s.substr(at, name_end(s, at) - at))) {
        i = at;
        module = true;
        break;
      }
    }
    const std::size_t end = name_end(s, i);
    const std::string name = s.substr(i, end - i);
    const Call* mathematica = find_call(kMathematica, name);
    const Call* python = find_call(kPython, name);
    const char next = end < s.size() ? s[end] : '\0';
    const std::size_t close =
        (next == '[' && mathematica) || (next == '(' && python) ? matching(s, end) : std::string::npos;
    if (close != std::string::npos) {
      const bool whole = out.empty() && close + 1 == s.size();
      out += call_text(next == '[' ? *mathematica : *python, arguments(s, end, close), whole);
      i = close + 1;
    } else if (name == "Pi" && !module) {
      out += "pi";
      i = end;
    } else if (name == "Degree") {  // a constant, pi/180: "30 Degree", "30*Degree"
      out += "(pi/180)";
      i = end;
    } else {
      out += name;
      i = end;
    }
  }
  return out;
}
}  // namespace

std::string as_programs_mean(const std::string& text) { return rewritten(text); }

std::optional<std::string> elliptic_of_parameter(const std::string& s) {
  std::string out;
  bool found = false;
  for (std::size_t i = 0; i < s.size();) {
    const std::size_t end = name_end(s, i);
    const std::string name = s.substr(i, end - i);
    const bool starts = i == 0 || !name_char(s[i - 1]);
    if (starts && (name == "EllipticK" || name == "EllipticE") && end < s.size() && s[end] == '(') {
      const std::size_t close = matching(s, end);
      if (close != std::string::npos) {
        const auto inside = elliptic_of_parameter(s.substr(end + 1, close - end - 1));
        out += name + "(sqrt(" + inside.value_or(s.substr(end + 1, close - end - 1)) + "))";
        i = close + 1;
        found = true;
        continue;
      }
    }
    out += end > i ? name : std::string(1, s[i]);
    i = std::max(end, i + 1);
  }
  if (!found) return std::nullopt;
  return out;
}

std::vector<SwappedArctangent> arctangents_swapped(const std::string& s) {
  static constexpr std::array<std::string_view, 5> kNames{"atan2", "arctan2", "ArcTan", "arctan",
                                                          "atan"};
  std::vector<SwappedArctangent> out;
  for (std::size_t i = 0; i < s.size();) {
    const std::size_t end = name_end(s, i);
    const std::string name = s.substr(i, end - i);
    const bool starts = end > i && (i == 0 || !name_char(s[i - 1]));
    if (starts && std::find(kNames.begin(), kNames.end(), name) != kNames.end() && end < s.size() &&
        (s[end] == '(' || s[end] == '[')) {
      const std::size_t close = matching(s, end);
      if (close != std::string::npos) {
        const auto arguments = top_level(s.substr(end + 1, close - end - 1), ',');
        if (arguments.size() == 2 && !arguments[0].empty() && !arguments[1].empty()) {
          out.push_back(
              {s.substr(0, end + 1) + arguments[1] + ", " + arguments[0] + s.substr(close), name});
        }
      }
    }
    i = std::max(end, i + 1);
  }
  return out;
}

}  // namespace wobble::check
