#include "symbolic/plain_text.hpp"

#include <cctype>
#include <map>

#include "symbolic/unicode_notation.hpp"

namespace wobble {

namespace {
bool is_alpha(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
bool is_alnum(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; }

const std::map<std::string, std::string>& symbols() {
  static const std::map<std::string, std::string> s{
      {"pm", "±"},     {"mp", "∓"},    {"times", "×"},      {"cdot", "·"},     {"le", "≤"},
      {"leq", "≤"},    {"ge", "≥"},    {"geq", "≥"},        {"ne", "≠"},       {"neq", "≠"},
      {"approx", "≈"}, {"to", "→"},    {"rightarrow", "→"}, {"infty", "∞"},    {"partial", "∂"},
      {"sum", "Σ"},    {"int", "∫"},   {"ldots", "…"},      {"dots", "…"},     {"cdots", "…"},
      {"prime", "′"},  {"circ", "°"},  {"perp", "⊥"},       {"parallel", "∥"}, {"lt", "<"},
      {"gt", ">"},     {"quad", " "},  {"qquad", " "},      {"ell", "ℓ"},      {"hbar", "ħ"},
      {"lvert", "|"},  {"rvert", "|"}, {"vert", "|"},       {"lVert", "‖"},    {"rVert", "‖"},
      {"Vert", "‖"}};
  return s;
}

bool is_function(const std::string& name) {
  static const char* const names[] = {"sin", "cos", "tan", "exp", "log", "ln", "arctan", "arcsin",
                                      "arccos", "sinh", "cosh", "tanh", "det", "max", "min"};
  for (const char* n : names) {
    if (name == n) return true;
  }
  return false;
}

// Unicode for sub- and superscript digits and signs; empty if `s` has other characters.
std::string scripted(const std::string& s, bool super) {
  static const char* const sup[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  static const char* const sub[] = {"₀", "₁", "₂", "₃", "₄", "₅", "₆", "₇", "₈", "₉"};
  if (s.empty()) return "";
  std::string out;
  for (const char c : s) {
    if (std::isdigit(static_cast<unsigned char>(c))) {
      out += (super ? sup : sub)[c - '0'];
    } else if (c == '-') {
      out += super ? "⁻" : "₋";
    } else if (c == '+') {
      out += super ? "⁺" : "₊";
    } else if (super && c == 'T' && s.size() == 1) {
      out += "ᵀ";
    } else {
      return "";
    }
  }
  return out;
}

// A single "token" (no operator or space inside) needs no parentheses after √ or around a/b.
bool simple(const std::string& s) {
  for (const char c : s) {
    if (c == ' ' || c == '+' || c == '-' || c == '/' || c == '*' || c == ',') return false;
  }
  return !s.empty();
}

struct MathReader {
  const std::string& s;
  std::size_t i = 0;

  // One argument: a braced group, a command, or one character.
  std::string argument() {
    while (i < s.size() && s[i] == ' ') ++i;
    if (i >= s.size()) return "";
    if (s[i] == '{') {
      ++i;
      std::string g = until_close();
      return g;
    }
    if (s[i] == '\\') return command();
    std::string c(1, s[i++]);
    // A multi-byte character (already Unicode) stays whole.
    while (i < s.size() && (static_cast<unsigned char>(s[i]) & 0xC0) == 0x80) c += s[i++];
    return c;
  }

  // Text up to the matching '}' (consumed), converted.
  std::string until_close() {
    std::string out;
    while (i < s.size() && s[i] != '}') next(out);
    if (i < s.size()) ++i;
    return out;
  }

  std::string command() {
    ++i;  // the backslash
    if (i >= s.size()) return "";
    if (!is_alpha(s[i])) {  // \, \; \! \\ \{ \} \% \_ \|
      const char c = s[i++];
      if (c == ',' || c == ';' || c == ':' || c == '\\') return " ";
      if (c == '!') return "";
      return std::string(1, c);
    }
    std::size_t j = i;
    while (j < s.size() && is_alpha(s[j])) ++j;
    const std::string name = s.substr(i, j - i);
    i = j;
    const auto& greek = sym::greek_letters();
    if (const auto g = greek.find(name); g != greek.end()) return g->second;
    if (const auto sy = symbols().find(name); sy != symbols().end()) return sy->second;
    if (name == "dot" || name == "ddot" || name == "hat" || name == "bar" || name == "vec") {
      const std::string arg = argument();
      const char* mark = name == "dot"    ? "\u0307"
                         : name == "ddot" ? "\u0308"
                         : name == "hat"  ? "\u0302"
                         : name == "bar"  ? "\u0304"
                                          : "\u20d7";
      // The mark goes after the first character (a letter, possibly several bytes).
      std::size_t first = 1;
      while (first < arg.size() && (static_cast<unsigned char>(arg[first]) & 0xC0) == 0x80)
        ++first;
      return arg.substr(0, first) + mark + arg.substr(std::min(first, arg.size()));
    }
    if (name == "sqrt") {
      const std::string arg = argument();
      return simple(arg) ? "√" + arg : "√(" + arg + ")";
    }
    if (name == "frac" || name == "tfrac" || name == "dfrac") {
      const std::string num = argument(), den = argument();
      return (simple(num) ? num : "(" + num + ")") + "/" + (simple(den) ? den : "(" + den + ")");
    }
    if (name == "left" || name == "right" || name == "big" || name == "Big" ||
        name == "displaystyle") {
      return "";
    }
    if (name == "mathbf" || name == "mathrm" || name == "text" || name == "mathit" ||
        name == "operatorname" || name == "boldsymbol" || name == "mathsf") {
      return argument();
    }
    if (is_function(name)) {
      // "\sin\alpha" -> "sin α"; "\sin(" -> "sin(".
      std::size_t k = i;
      while (k < s.size() && s[k] == ' ') ++k;
      const bool glued = k < s.size() && (s[k] == '(' || s[k] == '^' || s[k] == '_');
      return glued ? name : name + " ";
    }
    return name;  // unknown: its name, never a backslash
  }

  std::string script(bool super) {
    ++i;  // '^' or '_'
    const std::string arg = argument();
    const std::string u = scripted(arg, super);
    if (!u.empty()) return u;
    if (super) return simple(arg) ? "^" + arg : "^(" + arg + ")";
    return "_" + arg;
  }

  // The next piece of the math appended to `out`.
  void next(std::string& out) {
    const char c = s[i];
    if (c == '\\') {
      // A word LaTeX sets apart by its font ("\frac{A}{C}\tan\alpha") keeps a space after a
      // letter or digit: "A/C tan α", not "A/Ctan α".
      const std::string word = command();
      if (!out.empty() && is_alnum(out.back()) && !word.empty() && is_alpha(word.front()))
        out += ' ';
      out += word;
      return;
    }
    if (c == '^' || c == '_') {
      out += script(c == '^');
      return;
    }
    if (c == '{') {
      ++i;
      out += until_close();
      return;
    }
    ++i;
    out += c;
  }
};

// Runs of spaces made by removed commands ("sin α  x") become one.
std::string single_spaces(const std::string& s) {
  std::string out;
  for (const char c : s) {
    if (c == ' ' && !out.empty() && out.back() == ' ') continue;
    out += c;
  }
  return out;
}
}  // namespace

std::string math_to_unicode(const std::string& latex) {
  MathReader r{latex};
  std::string out;
  while (r.i < latex.size()) r.next(out);
  return single_spaces(out);
}

std::string plain_text(const std::string& md) {
  std::string out;
  for (std::size_t i = 0; i < md.size();) {
    const char c = md[i];
    if (c == '$') {
      const bool display = md.compare(i, 2, "$$") == 0;
      const std::size_t open = i + (display ? 2 : 1);
      const std::size_t close = md.find(display ? "$$" : "$", open);
      if (close == std::string::npos) {  // a lone dollar: text
        out += c;
        ++i;
        continue;
      }
      out += math_to_unicode(md.substr(open, close - open));
      i = close + (display ? 2 : 1);
    } else if (c == '`') {
      ++i;  // code spans print as their text
    } else if (md.compare(i, 2, "**") == 0 || md.compare(i, 2, "__") == 0) {
      i += 2;
    } else if (c == '\\' && i + 1 < md.size() && !is_alnum(md[i + 1])) {
      out += md[i + 1];  // a Markdown escape: \| \* \_
      i += 2;
    } else if (c == '\\') {
      ++i;  // a stray command outside math: its name only
    } else {
      out += c;
      ++i;
    }
  }
  return out;
}

}  // namespace wobble
