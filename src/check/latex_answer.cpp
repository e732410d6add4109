#include "check/latex_answer.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>
#include <set>
#include <string_view>
#include <utility>
#include <vector>

#include "check/latex_vocabulary.hpp"
#include "check/siunitx.hpp"
#include "core/characters.hpp"
#include "core/input_error.hpp"
#include "symbolic/unicode_notation.hpp"
#include "symbolic/units.hpp"

namespace wobble::check {
namespace {

// A symbol as LaTeX draws it: marks over it, the letter (or \alpha), the subscript. Two
// spellings of one symbol ("\dot\psi_0", "\dot{\psi_{0}}") have the same key.
struct Atom {
  std::string accents;  // "dot:" per mark
  std::string base;     // "R", "\alpha"
  std::string sub;      // "0", "cm", "1,2"; braces, spaces and \mathrm dropped
  std::string key() const { return accents + base + "_" + sub; }
};

// What an expression read so far is: its text and what the answer reader must know of it.
struct Piece {
  std::string text;
  bool symbolic = false;  // has one of the problem's symbols
  bool matrix = false;    // is one pmatrix, nothing else
};

class Reader {
 public:
  Reader(std::string s, const sym::SymbolTable& table, std::string field)
      : s_(std::move(s)), table_(table), field_(std::move(field)) {}

  std::string read() {
    index_symbols();
    Piece p = expr(0);
    if (i_ < s_.size()) fail_stop();
    return unit_.empty() ? p.text : p.text + " " + unit_;
  }

  // The key of a symbol's LaTeX as the file spells it, if it is one atom.
  std::optional<std::string> atom_key_of_whole() {
    try {
      Atom a = atom();
      skip_spaces();
      if (i_ == s_.size()) return a.key();
    } catch (const InputError&) {
    }
    return std::nullopt;
  }

 private:
  const std::string s_;
  const sym::SymbolTable& table_;
  const std::string field_;
  std::size_t i_ = 0;
  int bars_ = 0;  // plain |..| open around here
  std::map<std::string, std::string> by_key_;
  std::string unit_;
  std::size_t longest_name_ = 1;  // of the problem's symbols

  [[noreturn]] void fail(const std::string& what) const { throw InputError(field_ + ": " + what); }

  void index_symbols() {
    for (const auto& name : table_.names()) {
      longest_name_ = std::max(longest_name_, name.size());
      Reader r(table_.latex_of(name), table_, field_);
      if (const auto key = r.atom_key_of_whole()) by_key_.emplace(*key, name);
    }
  }

  bool at(char c) const { return i_ < s_.size() && s_[i_] == c; }
  bool at_end() const { return i_ >= s_.size(); }

  void skip_spaces() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '~')) ++i_;
  }

  // The command at i (a backslash, then letters or one other character), without advancing.
  std::string command_at(std::size_t i) const {
    if (i >= s_.size() || s_[i] != '\\') return "";
    std::size_t j = i + 1;
    if (j < s_.size() && !is_letter(s_[j])) return s_.substr(j, 1);
    while (j < s_.size() && is_letter(s_[j])) ++j;
    return s_.substr(i + 1, j - i - 1);
  }
  std::string take_command() {
    const std::string c = command_at(i_);
    i_ += 1 + c.size();
    return c;
  }
  bool at_command(const std::string& name) const { return command_at(i_) == name && !name.empty(); }

  // Past a \bigl or \Bigr before a delimiter.
  void skip_size() {
    if (sizes().count(command_at(i_))) {
      take_command();
      skip_spaces();
    }
  }

  bool stops_here() const {
    if (at_end()) return true;
    const char c = s_[i_];
    if (c == '}' || c == ')' || c == ']' || c == '&') return true;
    if (c == '|') return bars_ > 0;
    if (c != '\\') return false;
    const std::string cmd = command_at(i_);
    if (cmd == "\\" || cmd == "right" || cmd == "end" || cmd == "rvert" || cmd == "}") return true;
    if (sizes().count(cmd)) {
      std::size_t j = i_ + 1 + cmd.size();
      while (j < s_.size() && s_[j] == ' ') ++j;
      return j < s_.size() && (s_[j] == ')' || s_[j] == ']' || (s_[j] == '|' && bars_ > 0));
    }
    return false;
  }

  [[noreturn]] void fail_stop() const {
    const char c = s_[i_];
    if (c == '}') fail("a '}' without its '{'");
    if (c == ')' || c == ']') fail(std::string("a '") + c + "' without its opening bracket");
    if (c == '&') fail("'&' outside a matrix (\\begin{pmatrix} .. \\end{pmatrix})");
    if (command_at(i_) == "\\") fail("'\\\\' (a new row) outside a matrix");
    fail("\\" + command_at(i_) + " without what opens it");
  }

  void expect(char c) {
    skip_spaces();
    skip_size();
    if (!at(c)) fail(std::string("'") + c + "' missing");
    ++i_;
  }

  // ---- expressions -----------------------------------------------------------------------

  struct Out {
    Piece p;
    bool factor_last = false;
    int factors = 0;
    void factor(const Piece& f) {
      if (factor_last) p.text += '*';
      p.text += f.text;
      p.symbolic = p.symbolic || f.symbolic;
      p.matrix = factors == 0 && f.matrix;
      factor_last = true;
      ++factors;
    }
    void op(const std::string& o) {
      p.text += o;
      p.matrix = false;
      factor_last = false;
    }
  };

  // Every recursion passes here or through argument(): each bounds the depth, so that no input
  // overflows the stack (\frac\frac\frac... nests without a brace; 14000 deep crashed).
  void check_depth(int depth) const {
    if (depth > sym::kMaxExpressionDepth) {
      fail("nested deeper than " + std::to_string(sym::kMaxExpressionDepth) + " levels");
    }
  }

  Piece expr(int depth) {
    check_depth(depth);
    Out out;
    while (!at_end() && unit_.empty()) {
      const char c = s_[i_];
      if (c == ' ' || c == '~') {
        if (!unit_here(out, depth)) ++i_;
        continue;
      }
      if (stops_here()) break;
      if (c == '\\') {
        command(out, depth);
      } else if (is_digit(c) || c == '.') {
        out.factor({number()});
      } else if (is_letter(c)) {
        letters(out, depth);
      } else if (c == '{' || c == '(' || c == '[' || c == '|') {
        out.factor(delimited(depth));
      } else if (c == '^') {
        power(out, depth);
      } else if (c == '_') {
        fail("a subscript '_' belongs to a symbol (\\omega_3, I_{1})");
      } else if (c == '+' || c == '-' || c == '*' || c == '/' || c == '=') {
        out.op(std::string(1, c));
        ++i_;
      } else if (c == ',') {
        out.op(", ");
        ++i_;
      } else {
        fail(std::string("cannot read '") + c + "' in LaTeX");
      }
    }
    return out.p;
  }

  // Digits, a decimal point, an exponent "e-05" only where digits follow it.
  std::string number() {
    const std::size_t start = i_;
    while (!at_end() && (is_digit(s_[i_]) || s_[i_] == '.')) ++i_;
    if (!at_end() && (s_[i_] == 'e' || s_[i_] == 'E')) {
      std::size_t j = i_ + 1;
      if (j < s_.size() && (s_[j] == '+' || s_[j] == '-')) ++j;
      if (j < s_.size() && is_digit(s_[j])) {
        while (j < s_.size() && is_digit(s_[j])) ++j;
        i_ = j;
      }
    }
    return s_.substr(start, i_ - start);
  }

  // The rest of the input as a unit, where the value so far is a plain number: "\,\mathrm{kg}".
  // Only near the end (a unit is short), so that trying it at every space stays linear.
  // `written_as_unit` (\mathrm, \text, ^\circ): even after symbols, so that the answer reader
  // says to drop it; else "M g" is a product.
  bool unit_here(Out& out, int depth, bool written_as_unit = false) {
    if (depth > 0 || out.factors == 0 || !out.factor_last) return false;
    if (out.p.symbolic && !written_as_unit) return false;
    if (s_.size() - i_ > 160) return false;
    std::optional<std::string> unit = latex_unit_text(s_.substr(i_));
    // "303.6\,\mathrm{d}": the SI's day, where d is no symbol (as days_written_d reads it).
    if (unit && *unit == "d" && !table_.contains("d")) unit = "day";
    if (!unit || unit->empty() || !is_unit(*unit)) return false;
    unit_ = *unit;
    i_ = s_.size();
    return true;
  }

  // A group in brackets: {..} (\frac's arguments, a grouping), (..), [..], |..| and \left..\right.
  Piece delimited(int depth) {
    skip_size();
    if (at_command("left")) return left_right(depth);
    if (at_command("lvert") || at_command("vert")) {
      take_command();
      ++bars_;
      Piece inner = expr(depth + 1);
      --bars_;
      skip_size();
      if (!at_command("rvert") && !at_command("vert") && !at('|')) fail("'\\rvert' missing");
      if (at('|'))
        ++i_;
      else
        take_command();
      return {"abs(" + inner.text + ")", inner.symbolic, false};
    }
    const char open = s_[i_++];
    if (open == '|') {
      ++bars_;
      Piece inner = expr(depth + 1);
      --bars_;
      expect('|');
      return {"abs(" + inner.text + ")", inner.symbolic, false};
    }
    Piece inner = expr(depth + 1);
    const char close = open == '{' ? '}' : open == '(' ? ')' : ']';
    expect(close);
    if (inner.matrix) return inner;
    if (open == '[') return {"[" + inner.text + "]", inner.symbolic, false};
    return {"(" + inner.text + ")", inner.symbolic, false};
  }

  Piece left_right(int depth) {
    take_command();  // \left
    skip_spaces();
    std::string open;
    if (at('\\')) {
      open = "\\" + take_command();  // \{ \lvert \langle
    } else if (!at_end()) {
      open = std::string(1, s_[i_++]);
    }
    const bool bar = open == "|" || open == "\\lvert" || open == "\\vert";
    if (open != "(" && open != "[" && open != "." && open != "\\{" && !bar) {
      fail("\\left" + open + " is not read (\\left( \\left[ \\left| \\left. are)");
    }
    if (bar) ++bars_;
    Piece inner = expr(depth + 1);
    if (bar) --bars_;
    skip_spaces();
    if (!at_command("right")) fail("\\left" + open + " without its \\right");
    take_command();
    skip_spaces();
    if (at('\\')) {
      take_command();
    } else if (!at_end()) {
      ++i_;
    }
    if (bar) return {"abs(" + inner.text + ")", inner.symbolic, false};
    if (inner.matrix) return inner;
    if (open == "[") return {"[" + inner.text + "]", inner.symbolic, false};
    return {"(" + inner.text + ")", inner.symbolic, false};
  }

  // An argument of \frac, \sqrt or ^: a braced group, or one character or command.
  Piece argument(int depth) {
    check_depth(depth);
    skip_spaces();
    if (at('{')) {
      ++i_;
      Piece inner = expr(depth + 1);
      expect('}');
      return {"(" + inner.text + ")", inner.symbolic, inner.matrix};
    }
    if (at_end()) fail("an argument is missing at the end");
    if (is_digit(s_[i_])) return {std::string(1, s_[i_++])};
    Out out;
    if (is_letter(s_[i_])) {
      out.factor(letter_symbol());
    } else if (at('\\')) {
      command(out, depth + 1);
    } else {
      fail(std::string("cannot read '") + s_[i_] + "' as an argument");
    }
    return {"(" + out.p.text + ")", out.p.symbolic, false};
  }

  // Whether the entry of a vector or matrix read so far in `out` (after its last comma) is a
  // plain number, as "-9.66" or "2.5e-3": then a unit after it is the entry's unit.
  static bool entry_is_number(const Out& out) {
    if (!out.factor_last) return false;
    const std::size_t comma = out.p.text.rfind(", ");
    std::string entry = out.p.text.substr(comma == std::string::npos ? 0 : comma + 2);
    if (!entry.empty() && (entry[0] == '-' || entry[0] == '+')) entry.erase(0, 1);
    return !entry.empty() && (is_digit(entry[0]) || entry[0] == '.') &&
           entry.find_first_not_of("0123456789.eE+-") == std::string::npos;
  }

  // "(40^\circ, 30^\circ, 70^\circ)", a pmatrix of angles: degrees after each number of a vector
  // or matrix, written " deg" for the answer reader, which reads a unit on each entry. Only
  // where the entry is a plain number and ends at the degree sign (`circ_end` is just past
  // "\circ"); then the input is taken past it.
  bool degrees_of_entry(Out& out, std::size_t circ_end) {
    if (!entry_is_number(out)) return false;
    const std::size_t resume = i_;
    i_ = circ_end;
    if (s_[circ_end - 6] == '{') expect('}');  // ^{\circ}
    skip_spaces();
    if (!(at(',') || stops_here())) {
      i_ = resume;
      return false;
    }
    out.p.text += " deg";
    return true;
  }

  // "\phi + 90^\circ": degrees after a number that is a term of a sum, written " deg" for the
  // answer reader, which takes such degrees in an expression as radians. Only where the number
  // stands alone between the signs (not "2\alpha 90^\circ" or "x/90^\circ"); then the input is
  // taken past the degree sign.
  bool degrees_of_term(Out& out, std::size_t circ_end) {
    if (!out.factor_last) return false;
    const std::string& text = out.p.text;
    const std::size_t start = text.find_last_not_of("0123456789.");
    if (start == text.size() - 1) return false;  // no digits at the end
    const char before = start == std::string::npos ? '\0' : text[start];
    if (before != '+' && before != '-' && before != '(' && before != '[' && before != ' ')
      return false;
    const std::size_t resume = i_;
    i_ = circ_end;
    if (s_[circ_end - 6] == '{') expect('}');  // ^{\circ}
    skip_spaces();
    if (!(at('+') || at('-') || at(',') || stops_here())) {
      i_ = resume;
      return false;
    }
    out.p.text += " deg";
    return true;
  }

  // "(0.128\,\mathrm{rad/s}, 1.11\,\mathrm{rad/s}, ..)", a pmatrix cell "9.66\,\mathrm{rad/s}":
  // a unit after an entry of a vector or matrix, inside the brackets, written after the entry
  // for the answer reader, which reads a unit on each entry (and says what is wrong with a mix,
  // or with a unit not SI after an expression). Only a unit set as one, in \mathrm or \text:
  // inside a vector "2\,m" stays 2 times the symbol m; after an expression, only a unit that
  // names none of the problem's symbols ("\dot\phi\,\mathrm{rad/s}", not "R\,\mathrm{m}").
  bool unit_of_entry(Out& out, int depth) {
    if (depth == 0 || !out.factor_last) return false;
    const std::size_t end = entry_end(i_);
    if (end == std::string::npos) return false;
    const std::string raw = s_.substr(i_, end - i_);
    const bool set_as_unit =
        std::any_of(text_wrappers().begin(), text_wrappers().end(),
                    [&](const std::string& w) { return raw.find("\\" + w) != std::string::npos; });
    if (!set_as_unit) return false;
    const std::optional<std::string> unit = latex_unit_text(raw);
    if (!unit || !is_unit(*unit)) return false;
    if (!entry_is_number(out) && table_.contains(*unit)) return false;
    out.p.text += " " + *unit;
    i_ = end;
    return true;
  }

  // Where the entry that goes on at i ends: at a comma, '&', '\\', \end, \right or a closing
  // bracket outside braces, or at the end of the input; npos past kLongestUnit characters (a
  // unit is short), so that trying it after every number stays linear.
  std::size_t entry_end(std::size_t i) const {
    constexpr std::size_t kLongestUnit = 160;
    const std::size_t limit = std::min(s_.size(), i + kLongestUnit);
    int braces = 0;
    while (i < limit) {
      const char c = s_[i];
      if (c == '{') {
        ++braces;
      } else if (c == '}') {
        if (braces == 0) return i;
        --braces;
      } else if (braces == 0 && (c == ',' || c == '&' || c == ')' || c == ']' || c == '|')) {
        return i;
      } else if (c == '\\') {
        const std::string cmd = command_at(i);
        if (braces == 0 &&
            (cmd == "\\" || cmd == "end" || cmd == "right" || cmd == "rvert" || sizes().count(cmd)))
          return i;
        i += cmd.size();
      }
      ++i;
    }
    return i < s_.size() ? std::string::npos : i;
  }

  void power(Out& out, int depth) {
    // "15^\circ": degrees, a unit.
    {
      std::size_t j = i_ + 1;
      if (j < s_.size() && s_[j] == '{') ++j;
      if (s_.compare(j, 5, "\\circ") == 0) {
        if (!unit_here(out, depth, true) && !degrees_of_entry(out, j + 5) &&
            !degrees_of_term(out, j + 5)) {
          fail("'^\\circ' (degrees) belongs after a number");
        }
        return;
      }
    }
    ++i_;
    if (!out.factor_last) fail("a power '^' needs something before it");
    const Piece p = argument(depth);
    out.p.text += "^" + p.text;
    out.p.symbolic = out.p.symbolic || p.symbolic;
  }

  // ---- commands ----------------------------------------------------------------------------

  void command(Out& out, int depth) {
    const std::string cmd = command_at(i_);
    const bool wrapper = text_wrappers().count(cmd) != 0;
    // "\,\mathrm{kg}" after a number: the unit, and the rest is read as units are.
    if ((wrapper || spacing().count(cmd)) &&
        (unit_here(out, depth, wrapper) || unit_of_entry(out, depth)))
      return;
    if (spacing().count(cmd)) {
      take_command();
    } else if (cmd == "cdot" || cmd == "times" || cmd == "ast" || cmd == "div") {
      take_command();
      out.op(cmd == "div" ? "/" : "*");
    } else if (sizes().count(cmd) && next_after_command_is('/')) {  // \big/
      take_command();
      skip_spaces();
      ++i_;
      out.op("/");
    } else {
      out.factor(construct(cmd, depth));
    }
  }

  bool next_after_command_is(char c) const {
    std::size_t j = i_ + 1 + command_at(i_).size();
    while (j < s_.size() && s_[j] == ' ') ++j;
    return j < s_.size() && s_[j] == c;
  }

  // What a command makes: a group, a fraction, a root, a matrix, a function's value, a symbol.
  Piece construct(const std::string& cmd, int depth) {
    if (sizes().count(cmd) || cmd == "left" || cmd == "lvert" || cmd == "vert")
      return delimited(depth);
    if (cmd == "frac" || cmd == "dfrac" || cmd == "tfrac" || cmd == "cfrac") {
      take_command();
      const Piece num = argument(depth), den = argument(depth);
      return {"(" + num.text + "/" + den.text + ")", num.symbolic || den.symbolic, false};
    }
    if (cmd == "sqrt") return root(depth);
    if (cmd == "begin") return matrix(depth);
    if (const auto f = function_commands().find(cmd); f != function_commands().end()) {
      take_command();
      return function(f->second, "\\" + cmd, depth);
    }
    if (cmd == "operatorname") {
      take_command();
      const std::string name = braced_word();
      // Any name: the expression reader knows its functions (EllipticK, atan2) and names the
      // one it does not.
      if (name.empty()) fail("\\operatorname{} without a name");
      return function(name, "\\operatorname{" + name + "}", depth);
    }
    if (text_wrappers().count(cmd)) {
      // \mathrm{m}: a symbol set upright, or a word that names one.
      const std::size_t start = i_;
      take_command();
      const std::size_t open = s_.find('{', i_);
      const std::string word = braced_word();
      if (function_names().count(word)) return function(word, word, depth);
      if (table_.contains(word)) return {word, true, false};
      // "\mathrm{rad/s}" before more: a unit, named as typed, not as the word its letters make
      // ("rads"); at the end the value's unit, read before here.
      if (const std::string inside = s_.substr(open + 1, i_ - open - 2);
          inside != word && is_unit(inside))
        unknown_symbol(inside);
      i_ = start;
      return symbol_piece(atom());
    }
    if (accents().count(cmd) || greek().count(cmd)) return symbol_piece(atom());
    if (cmd == "pm" || cmd == "mp") fail("'\\" + cmd + "' gives two answers; type one");
    fail("\\" + cmd +
         " is not read (fractions, roots, powers, Greek letters, functions, pmatrix and "
         "\\mathrm units are)");
  }

  // \sqrt{x}, \sqrt[n]{x}.
  Piece root(int depth) {
    take_command();
    skip_spaces();
    std::optional<Piece> index;
    if (at('[')) {
      ++i_;
      index = expr(depth + 1);
      expect(']');
    }
    const Piece x = argument(depth);
    const bool symbolic = x.symbolic || (index && index->symbolic);
    // A digit's argument comes unbracketed (\sqrt2, \sqrt 3); a group's in brackets.
    const std::string radicand = x.text.front() == '(' ? x.text : "(" + x.text + ")";
    if (!index) return {"sqrt" + radicand, symbolic, false};
    return {"(" + x.text + "^(1/(" + index->text + ")))", symbolic, false};
  }

  // The letters of {word} after \operatorname or \mathrm (spacing inside dropped).
  std::string braced_word() {
    skip_spaces();
    if (!at('{')) fail("'{' missing after a command");
    const std::size_t close = s_.find('}', i_);
    if (close == std::string::npos) fail("'{' without its '}'");
    std::string word;
    for (std::size_t k = i_ + 1; k < close; ++k) {
      if (std::isalnum(static_cast<unsigned char>(s_[k])) || s_[k] == '_') word += s_[k];
    }
    i_ = close + 1;
    return word;
  }

  // sin, \sin, \sin^{2}: with its argument in brackets, or one symbol (a number before it).
  Piece function(const std::string& name, const std::string& shown, int depth) {
    skip_spaces();
    std::optional<Piece> pow;
    if (at('^')) {
      ++i_;
      pow = argument(depth);
      if (pow->text == "(-1)" || pow->text == "-1") {
        fail(shown + "^{-1} may mean 1/" + shown.substr(shown[0] == '\\' ? 1 : 0) +
             " or the inverse; write " + "\\arc" + name + " or 1/" + shown);
      }
      skip_spaces();
    }
    Piece arg;
    skip_size();
    if (at('(') || at('[') || at('{') || at_command("left")) {
      arg = delimited(depth);
      if (arg.text.front() != '(') arg.text = "(" + arg.text + ")";
    } else {
      std::string number_part;
      if (!at_end() && (is_digit(s_[i_]) || s_[i_] == '.')) {
        number_part = number();
        skip_spaces();
      }
      const bool symbol_next =
          !at_end() && (is_letter(s_[i_]) || accents().count(command_at(i_)) ||
                        greek().count(command_at(i_)) || text_wrappers().count(command_at(i_)));
      if (symbol_next) {
        Out one;
        if (!number_part.empty()) one.factor({number_part});
        one.factor(is_letter(s_[i_]) ? letter_symbol() : symbol_piece(atom()));
        if (at('^')) power(one, depth + 1);
        arg = {"(" + one.p.text + ")", true, false};
      } else if (!number_part.empty()) {
        // "\cos 30^\circ": the degrees are the argument's, not the cosine's unit.
        const bool braced = s_.compare(i_, 8, "^{\\circ}") == 0;
        const bool degrees = braced || s_.compare(i_, 6, "^\\circ") == 0;
        if (degrees) i_ += braced ? 8 : 6;
        arg = {"(" + number_part + (degrees ? " deg)" : ")")};
      } else {
        fail(shown + " needs its argument: " + shown + "\\left(x\\right) or " + shown + "\\theta");
      }
    }
    std::string text = name + arg.text;
    if (pow) text += "^" + pow->text;
    return {text, arg.symbolic, false};
  }

  // ---- symbols ------------------------------------------------------------------------------

  // The subscript after _: one character or command, or a group; spacing, braces and \mathrm
  // dropped so that spellings agree.
  std::string subscript() {
    ++i_;  // _
    skip_spaces();
    if (at_end()) fail("a subscript is missing at the end");
    if (at('\\')) {
      // "\Omega_\mathrm{space}", as the statements write a subscript in words: the wrapper's
      // group is the subscript.
      const std::string cmd = take_command();
      if (!text_wrappers().count(cmd)) return "\\" + cmd;
      skip_spaces();
      if (!at('{')) return "\\" + cmd;
    }
    if (!at('{')) return std::string(1, s_[i_++]);
    int level = 0;
    std::string sub;
    for (; i_ < s_.size(); ++i_) {
      const char c = s_[i_];
      if (c == '{') {
        ++level;
      } else if (c == '}') {
        if (--level == 0) break;
      } else if (c == '\\') {
        const std::string cmd = command_at(i_);
        i_ += cmd.size();
        if (!text_wrappers().count(cmd) && !spacing().count(cmd)) sub += "\\" + cmd;
      } else if (c != ' ' && c != '~') {
        sub += c;
      }
    }
    if (at_end()) fail("'{' without its '}'");
    ++i_;
    return sub;
  }

  Atom atom() {
    Atom a;
    skip_spaces();
    for (int marks = 0; at('\\') && accents().count(command_at(i_)); ++marks) {
      if (marks > 3) fail("more marks over a letter than a symbol has");
      a.accents += take_command() + ":";
      skip_spaces();
      if (at('{')) {
        ++i_;
        const Atom inner = atom();
        skip_spaces();
        if (!at('}')) fail("a mark over more than one letter (\\dot{\\psi} is read)");
        ++i_;
        a.accents += inner.accents;
        a.base = inner.base;
        a.sub = inner.sub;
        if (subscript_next()) {
          if (!a.sub.empty()) fail("a symbol with two subscripts");
          a.sub = subscript();
        }
        return a;
      }
    }
    skip_spaces();
    if (at('\\')) {
      const std::string cmd = take_command();
      if (greek().count(cmd)) {
        a.base = "\\" + cmd;
      } else if (text_wrappers().count(cmd)) {
        a.base = braced_word();
      } else {
        fail("\\" + cmd + " is not a symbol");
      }
    } else if (!at_end() && is_letter(s_[i_])) {
      a.base = std::string(1, s_[i_++]);
    } else {
      fail("a mark (\\dot, \\hat) needs a letter under it");
    }
    if (subscript_next()) a.sub = subscript();
    return a;
  }

  // Whether a subscript follows, spaces before it skipped ("\psi _0").
  bool subscript_next() {
    std::size_t j = i_;
    while (j < s_.size() && s_[j] == ' ') ++j;
    if (j >= s_.size() || s_[j] != '_') return false;
    i_ = j;
    return true;
  }

  // The problem's symbol an atom names: by its LaTeX, else by the ASCII name its parts spell
  // (\dot\psi_0 -> psidot0, \alpha -> alpha, \varphi -> phi).
  Piece symbol_piece(const Atom& a) {
    if (const auto it = by_key_.find(a.key()); it != by_key_.end()) return {it->second, true};
    std::string base = a.base[0] == '\\' ? greek_name(a.base.substr(1)) : a.base;
    std::string marks;
    for (std::size_t k = 0; k < a.accents.size();) {
      const std::size_t colon = a.accents.find(':', k);
      const std::string mark = a.accents.substr(k, colon - k);
      if (mark == "dot" || mark == "ddot") marks += mark;
      k = colon + 1;
    }
    // A subscript's letters and digits; and with its commas as '_', as a name joins words
    // ("\\Omega_{space,rate}" for Omega_space_rate, "L_{0,\\mathrm{body}}" for L0_body).
    std::string sub, sub_words;
    for (const char c : a.sub) {
      if (std::isalnum(static_cast<unsigned char>(c))) sub += c;
      if (std::isalnum(static_cast<unsigned char>(c)) || c == ',') sub_words += c == ',' ? '_' : c;
    }
    for (const std::string& name :
         {base + marks + sub, base + sub + marks, base + marks + "_" + sub,
          base + marks + sub_words, base + marks + "_" + sub_words}) {
      if (table_.contains(name)) return {name, true};
    }
    if (base == "pi" && a.accents.empty() && a.sub.empty()) return {"Pi"};
    const std::string mark =
        a.accents.empty() ? "" : "\\" + a.accents.substr(0, a.accents.find(':')) + " ";
    unknown_symbol(mark + a.base + (a.sub.empty() ? "" : "_{" + a.sub + "}"));
  }

  [[noreturn]] void unknown_symbol(const std::string& shown) const {
    std::string known;
    for (const auto& n : table_.names()) known += (known.empty() ? "" : ", ") + table_.latex_of(n);
    fail(shown + " is not one of this problem's symbols (" + known + ")");
  }

  // A run of letters: a function's name, a symbol's ASCII name, or letters each a symbol.
  // The run of letters and digits at i, at most `limit` long; `whole` if it ends there.
  std::pair<std::string, bool> run_at(std::size_t limit) const {
    std::size_t end = i_;
    while (end < s_.size() && end - i_ < limit && std::isalnum(static_cast<unsigned char>(s_[end])))
      ++end;
    const bool whole = end >= s_.size() || !std::isalnum(static_cast<unsigned char>(s_[end]));
    return {s_.substr(i_, end - i_), whole};
  }

  void letters(Out& out, int depth) {
    // Function names are short: a run is looked at no further (a long run is read a letter at a
    // time, and rescanning it whole for each letter took time cubic in its length).
    const auto [run, whole] = run_at(16);
    if (whole && function_names().count(run)) {
      i_ += run.size();
      out.factor(function(run, run, depth));
      return;
    }
    // K(k), the complete elliptic integral of the first kind as books write it, where K is no
    // symbol of the problem (as in plain text: written_forms.hpp, elliptic_integral_named).
    if (whole && run == "K" && !table_.contains("K")) {
      std::size_t next = i_ + 1;
      while (next < s_.size() && s_[next] == ' ') ++next;
      if (next < s_.size() && (s_[next] == '(' || s_.compare(next, 5, "\\left") == 0)) {
        ++i_;
        out.factor(function("EllipticK", "K", depth));
        return;
      }
    }
    // "0.21kg": a unit glued to a plain number, where its first letter is no symbol.
    if (!table_.contains(run.substr(0, 1)) && unit_here(out, depth)) return;
    out.factor(letter_symbol());
  }

  // The symbol a run of letters begins with: a name with a subscript's digits (psidot_0), the
  // longest name of two letters or more (omega, psidot0, I1), else one letter as LaTeX reads it
  // (with its subscript if it is the run's last). Looks no further than the longest name.
  Piece letter_symbol() {
    const auto [run, whole] = run_at(longest_name_ + 1);
    const std::size_t end = i_ + run.size();
    const bool subscripted = whole && end < s_.size() && s_[end] == '_';
    if (subscripted && run.size() > 1) {
      const std::size_t save = i_;
      i_ = end;
      const std::string sub = subscript();
      std::string bare;
      for (const char c : sub) {
        if (std::isalnum(static_cast<unsigned char>(c))) bare += c;
      }
      if (table_.contains(run + bare)) return {run + bare, true};
      if (table_.contains(run)) unknown_symbol(run + "_{" + sub + "}");
      i_ = save;
    }
    for (std::size_t n = run.size(); n >= 2; --n) {
      if (table_.contains(run.substr(0, n)) && !(n == run.size() && subscripted)) {
        i_ += n;
        return {run.substr(0, n), true};
      }
    }
    if (run.size() > 1) return symbol_piece(Atom{"", std::string(1, s_[i_++]), ""});
    return symbol_piece(atom());
  }

  // ---- matrices -----------------------------------------------------------------------------

  std::string environment_name() {
    skip_spaces();
    if (!at('{')) fail("'{' missing after \\begin or \\end");
    const std::size_t close = s_.find('}', i_);
    if (close == std::string::npos) fail("'{' without its '}'");
    const std::string name = s_.substr(i_ + 1, close - i_ - 1);
    i_ = close + 1;
    return name;
  }

  // "\\[2ex]": a row's extra space, as the LaTeX key sets rows of fractions apart. As LaTeX
  // reads it, spaces before the '[' too; only a length inside ("2ex", "-0.5em", "4pt").
  void row_space() {
    std::size_t j = i_;
    while (j < s_.size() && s_[j] == ' ') ++j;
    if (j >= s_.size() || s_[j] != '[') return;
    const std::size_t close = s_.find(']', j);
    if (close == std::string::npos) return;
    const std::string length = s_.substr(j + 1, close - j - 1);
    const bool is_length = !length.empty() && std::all_of(length.begin(), length.end(), [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == ' ';
    });
    if (is_length) i_ = close + 1;
  }

  Piece matrix(int depth) {
    take_command();  // \begin
    const std::string env = environment_name();
    static const std::set<std::string> known{"pmatrix", "bmatrix",     "Bmatrix",
                                             "matrix",  "smallmatrix", "array"};
    if (!known.count(env)) fail("\\begin{" + env + "} is not read (pmatrix, bmatrix, array are)");
    if (env == "array") (void)environment_name();  // the column spec {ccc}
    std::vector<std::vector<std::string>> rows(1);
    bool symbolic = false;
    for (;;) {
      Piece cell = expr(depth + 1);
      skip_spaces();
      if (trim(cell.text).empty()) {
        // An empty last row, after a final \\.
        if (at_command("end") && rows.back().empty() && rows.size() > 1) {
          rows.pop_back();
          break;
        }
        fail("an empty entry in \\begin{" + env + "}");
      }
      symbolic = symbolic || cell.symbolic;
      rows.back().push_back(trim(cell.text));
      if (at('&')) {
        ++i_;
      } else if (at_command("\\")) {
        take_command();
        row_space();
        rows.emplace_back();
      } else if (at_command("end")) {
        break;
      } else if (at_end()) {
        fail("\\begin{" + env + "} without its \\end{" + env + "}");
      } else {
        fail_stop();
      }
    }
    take_command();  // \end
    if (environment_name() != env) fail("\\begin{" + env + "} closed by another \\end");
    if (rows.empty()) fail("an empty \\begin{" + env + "}");
    for (const auto& r : rows) {
      if (r.size() != rows[0].size()) fail("rows of different lengths in \\begin{" + env + "}");
    }
    const auto list = [](const std::vector<std::string>& items) {
      std::string s = "[";
      for (std::size_t k = 0; k < items.size(); ++k) s += (k ? ", " : "") + items[k];
      return s + "]";
    };
    if (rows.size() == 1) return {list(rows[0]), symbolic, true};
    if (rows[0].size() == 1) {
      std::vector<std::string> column;
      for (const auto& r : rows) column.push_back(r[0]);
      return {list(column), symbolic, true};
    }
    std::vector<std::string> listed;
    for (const auto& r : rows) listed.push_back(list(r));
    return {list(listed), symbolic, true};
  }
};

// The end of the brace group that opens at `open` (one past its '}'), or npos.
std::size_t group_end(const std::string& s, std::size_t open) {
  if (open >= s.size() || s[open] != '{') return std::string::npos;
  int depth = 0;
  for (std::size_t i = open; i < s.size(); ++i) {
    depth += s[i] == '{' ? 1 : s[i] == '}' ? -1 : 0;
    if (depth == 0) return i + 1;
  }
  return std::string::npos;
}

// A fraction's numerator or denominator without its spacing, its upright d plain:
// "\mathrm{d}\phi" -> "d\phi", "\mathrm{d} t" -> "dt".
std::string leibniz_part(std::string s) {
  for (const std::string upright :
       {"\\mathrm{d}", "\\text{d}", "\\operatorname{d}", "\\mathrm d"}) {
    for (auto at = s.find(upright); at != std::string::npos; at = s.find(upright, at))
      s.replace(at, upright.size(), "d");
  }
  for (const std::string space : {"\\,", "\\;", "\\!", " "}) {
    for (auto at = s.find(space); at != std::string::npos; at = s.find(space, at))
      s.erase(at, space.size());
  }
  return s;
}

// "\frac{d\phi}{dt}", "\frac{\mathrm{d}\theta_0}{\mathrm{d}t}": a rate in Leibniz's notation,
// as Newton's dot sets it ("\dot{\phi}", "\dot{\theta}_0"), which the reader knows.
std::string leibniz_as_dots(std::string s) {
  for (const std::string frac : {"\\frac", "\\dfrac", "\\tfrac"}) {
    for (auto at = s.find(frac); at != std::string::npos; at = s.find(frac, at + 1)) {
      std::size_t open = at + frac.size();
      while (open < s.size() && s[open] == ' ') ++open;
      const std::size_t top_end = group_end(s, open);
      if (top_end == std::string::npos) continue;
      std::size_t below = top_end;
      while (below < s.size() && s[below] == ' ') ++below;
      const std::size_t below_end = group_end(s, below);
      if (below_end == std::string::npos) continue;
      const std::string top = leibniz_part(s.substr(open + 1, top_end - open - 2));
      if (leibniz_part(s.substr(below + 1, below_end - below - 2)) != "dt" || top.size() < 2 ||
          top[0] != 'd') {
        continue;
      }
      const std::string rate = top.substr(1);
      const std::size_t sub = rate.find('_');
      s.replace(at, below_end - at,
                "\\dot{" + rate.substr(0, sub) + "}" +
                    (sub == std::string::npos ? "" : rate.substr(sub)));
    }
  }
  return s;
}
}  // namespace

std::string without_code_marks(const std::string& s) {
  const std::string t = trim(s);
  // One span: "`a` + `b`" is two, and stays as typed.
  for (const std::string_view code : {"``", "`"}) {
    if (t.size() <= 2 * code.size() || !t.starts_with(code) || !t.ends_with(code)) continue;
    const std::string inside = t.substr(code.size(), t.size() - 2 * code.size());
    if (inside.find('`') == std::string::npos) return trim(inside);
  }
  return t;
}

std::string without_math_delimiters(std::string s) {
  s = without_code_marks(s);  // code marks outside math marks, as a forum's post has them
  for (const auto& [open, close] : std::vector<std::pair<std::string, std::string>>{
           {"$$", "$$"}, {"$", "$"}, {"\\(", "\\)"}, {"\\[", "\\]"}}) {
    if (s.size() >= open.size() + close.size() && s.rfind(open, 0) == 0 &&
        s.compare(s.size() - close.size(), close.size(), close) == 0) {
      return trim(s.substr(open.size(), s.size() - open.size() - close.size()));
    }
  }
  return s;
}

bool looks_like_latex(const std::string& typed) {
  return typed.find('\\') != std::string::npos || typed.find("^{") != std::string::npos ||
         typed.find("_{") != std::string::npos;
}

std::string latex_as_text(const std::string& latex, const sym::SymbolTable& table,
                          const std::string& field) {
  std::string s = sym::to_ascii(without_math_delimiters(latex));
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '\n' || s[i] == '\r' || s[i] == '\t') s[i] = ' ';
    // Named by its code point: a control character printed would garble the terminal's line.
    const auto code = static_cast<unsigned char>(s[i]);
    if (code >= 0x80 || code < 0x20 || code == 0x7f)
      throw InputError(field + ": cannot read " + character_name(s, i) + " in LaTeX");
  }
  return Reader(leibniz_as_dots(siunitx_as_latex(s, field)), table, field).read();
}

std::string latex_assignment_as_text(const std::string& text, const sym::SymbolTable& table) {
  const std::string trimmed = trim(text), math = without_math_delimiters(trimmed);
  if (!looks_like_latex(math) && math == trimmed) return text;
  std::string out, name;
  for (std::size_t start = 0;; out += " = ") {
    const bool is_name = start == 0;
    const std::size_t eq = math.find('=', start);
    const std::string side = trim(math.substr(start, eq == std::string::npos ? eq : eq - start));
    const std::string field = is_name ? "--set" : "--set " + name;
    const std::string plain = looks_like_latex(side) ? latex_as_text(side, table, field) : side;
    if (is_name) name = plain;
    out += plain;
    if (eq == std::string::npos) return out;
    start = eq + 1;
  }
}

}  // namespace wobble::check
