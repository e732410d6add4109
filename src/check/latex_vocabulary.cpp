#include "check/latex_vocabulary.hpp"

#include <cctype>

#include "core/characters.hpp"

namespace wobble::check {

const std::set<std::string>& accents() {
  static const std::set<std::string> s{"dot",      "ddot",  "hat",     "bar",
                                       "vec",      "tilde", "mathbf",  "boldsymbol",
                                       "overline", "check", "widehat", "widetilde"};
  return s;
}

const std::set<std::string>& greek() {
  static const std::set<std::string> s{
      "alpha", "beta",     "gamma",   "delta", "epsilon", "varepsilon", "zeta",   "eta",
      "theta", "vartheta", "iota",    "kappa", "lambda",  "mu",         "nu",     "xi",
      "pi",    "rho",      "varrho",  "sigma", "tau",     "upsilon",    "phi",    "varphi",
      "chi",   "psi",      "omega",   "Gamma", "Delta",   "Theta",      "Lambda", "Xi",
      "Pi",    "Sigma",    "Upsilon", "Phi",   "Psi",     "Omega"};
  return s;
}

// The letter a Greek command names in ASCII: \varphi is phi.
std::string greek_name(const std::string& command) {
  return command.rfind("var", 0) == 0 ? command.substr(3) : command;
}

// LaTeX's function commands and the names the expression reader knows them by.
const std::map<std::string, std::string>& function_commands() {
  static const std::map<std::string, std::string> m{
      {"sin", "sin"},     {"cos", "cos"},     {"tan", "tan"},   {"arcsin", "asin"},
      {"arccos", "acos"}, {"arctan", "atan"}, {"sinh", "sinh"}, {"cosh", "cosh"},
      {"tanh", "tanh"},   {"exp", "exp"},     {"ln", "log"},    {"log", "log"}};
  return m;
}

// Function names typed as letters (inside \operatorname too); diag makes a diagonal matrix
// (check/written_forms.hpp).
const std::set<std::string>& function_names() {
  static const std::set<std::string> s{"sin",   "cos",  "tan",       "asin",      "acos", "atan",
                                       "atan2", "sinh", "cosh",      "tanh",      "exp",  "log",
                                       "sqrt",  "abs",  "EllipticK", "EllipticE", "diag"};
  return s;
}

const std::set<std::string>& spacing() {
  static const std::set<std::string> s{
      ",",         ";",         ":",        "!",       " ",    "quad", "qquad", "displaystyle",
      "textstyle", "thinspace", "medspace", "enspace", "hline"};
  return s;
}

const std::set<std::string>& text_wrappers() {
  static const std::set<std::string> s{"mathrm", "text", "textrm", "mathit", "mathsf", "rm"};
  return s;
}

const std::set<std::string>& sizes() {
  static const std::set<std::string> s{"big",  "Big",  "bigg",  "Bigg",  "bigl",  "bigr",
                                       "Bigl", "Bigr", "biggl", "biggr", "Biggl", "Biggr"};
  return s;
}

std::optional<std::string> latex_unit_text(const std::string& raw) {
  std::string out;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    const char c = raw[i];
    if (c == '{' || c == '}') continue;
    if (c == '~') {
      out += ' ';
      continue;
    }
    if (c == '^') {
      std::size_t j = i + 1;
      if (j < raw.size() && raw[j] == '{') ++j;
      if (raw.compare(j, 5, "\\circ") == 0) {
        out += " deg";
        i = j + 4;
        continue;
      }
      out += '^';
      continue;
    }
    if (c != '\\') {
      out += c;
      continue;
    }
    std::size_t j = i + 1;
    if (j < raw.size() && !is_letter(raw[j])) {
      if (!spacing().count(raw.substr(j, 1))) return std::nullopt;
      out += ' ';
      i = j;
      continue;
    }
    while (j < raw.size() && is_letter(raw[j])) ++j;
    const std::string cmd = raw.substr(i + 1, j - i - 1);
    if (cmd == "cdot") {
      // Between units ("kg \cdot m^2"), never before the first: "2 \cdot m" is a product.
      if (trim(out).empty()) return std::nullopt;
      out += ' ';
    } else if (cmd == "circ") {
      out += " deg";
    } else if (spacing().count(cmd)) {
      out += ' ';
    } else if (!text_wrappers().count(cmd)) {
      return std::nullopt;
    }
    i = j - 1;
  }
  // Collapse spaces: "kg  m^2" -> "kg m^2".
  std::string collapsed;
  for (const char c : trim(out)) {
    if (c == ' ' && !collapsed.empty() && collapsed.back() == ' ') continue;
    collapsed += c;
  }
  // A unit begins with its name, or is 1/s: "* m" and "/ 2" are no unit.
  if (collapsed.empty() || !(is_letter(collapsed[0]) || collapsed.rfind("1/", 0) == 0))
    return std::nullopt;
  return collapsed;
}

}  // namespace wobble::check
