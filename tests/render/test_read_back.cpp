// Whatever a key prints, `check` reads back and judges right: generated over the whole catalog,
// every answer in every printed form. And the verdicts that were wrong: Hz on a rate, radians
// against 1/s, a signed rate given as its size, principal axes judged by meaning.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <boost/locale/utf.hpp>
#include <catch2/catch.hpp>
#include <cctype>
#include <cmath>
#include <functional>
#include <iterator>
#include <limits>
#include <optional>
#include <set>
#include <sstream>

#include "check/absent_answer.hpp"
#include "check/answer_choice.hpp"
#include "check/answer_reading.hpp"
#include "check/check_fixture.hpp"
#include "check/judge.hpp"
#include "check/latex_answer.hpp"
#include "check/submission.hpp"
#include "check/worksheet.hpp"
#include "core/characters.hpp"
#include "problem/values.hpp"
#include "problem/variants.hpp"
#include "render/common.hpp"
#include "render/handout.hpp"
#include "render/prose.hpp"
#include "render/render.hpp"
#include "solvers/catalog.hpp"
#include "solvers/solve.hpp"
#include "symbolic/plain_text.hpp"
#include "symbolic/unicode_notation.hpp"
#include "temp_files.hpp"

using namespace wobble;
using namespace wobble::check;

namespace {
using Fixture = wobble::test::CheckFixture;

// The message `check` refuses the answer with, or "(no error)".
std::string error_of(const Fixture& f, const std::string& name, const std::string& text) {
  try {
    (void)f.check(name, text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

// The numeric line exactly as the text key prints it (matrices on several lines, indented).
std::string printed_value(const Answer& a) {
  return detail::value_text(a.value, "        ") + detail::unit_text(a.unit);
}

// Vectors and matrices as rows of numbers with spaces, "[x y z]": how a student copies a row.
std::string spaced_rows(const Answer& a) {
  const auto& v = a.value;
  const auto row = [&](std::size_t r) {
    std::string s = "[";
    for (std::size_t c = 0; c < v.cols; ++c) s += (c ? " " : "") + format_number(v.at(r, c));
    return s + "]";
  };
  if (v.shape == Value::Shape::vector) {
    std::string s = "[";
    for (std::size_t i = 0; i < v.data.size(); ++i) s += (i ? " " : "") + format_number(v.data[i]);
    return s + "] " + a.unit;
  }
  std::string s;
  for (std::size_t r = 0; r < v.rows; ++r) s += (r ? " " : "") + row(r);
  return s + " " + a.unit;
}

// The same in MATLAB's notation, "[a b c; d e f; ...]" (a vector as a column, "[x; y; z]"), and
// in Mathematica's, "{{a, b, c}, {d, e, f}, ...}".
std::string matlab_rows(const Answer& a) {
  const auto& v = a.value;
  std::string s = "[";
  for (std::size_t i = 0; i < v.data.size(); ++i) {
    const bool new_row = v.shape == Value::Shape::vector || i % v.cols == 0;
    s += (i == 0 ? "" : new_row ? "; " : " ") + format_number(v.data[i]);
  }
  return s + "] " + a.unit;
}

std::string mathematica_lists(const Answer& a) {
  const auto& v = a.value;
  const auto list = [&](std::size_t from, std::size_t n) {
    std::string s = "{";
    for (std::size_t c = 0; c < n; ++c) s += (c ? ", " : "") + format_number(v.data[from + c]);
    return s + "}";
  };
  if (v.shape == Value::Shape::vector) return list(0, v.data.size()) + " " + a.unit;
  std::string s = "{";
  for (std::size_t r = 0; r < v.rows; ++r) s += (r ? ", " : "") + list(r * v.cols, v.cols);
  return s + "} " + a.unit;
}

// As Python shows a result, no unit (SI): NumPy's "array([[10.0, 0.0, ...],\n       [...]])"
// with its line breaks, or SymPy's "Matrix([[10, 0, 0], [0, 6, 1], [0, 1, 6]])".
std::string python_array(const Answer& a, const std::string& wrapper) {
  const auto& v = a.value;
  const std::size_t rows = v.shape == Value::Shape::vector ? 1 : v.rows;
  const std::size_t cols = v.data.size() / rows;
  std::string s = wrapper + "(" + (rows > 1 ? "[" : "");
  for (std::size_t r = 0; r < rows; ++r) {
    s += r ? ",\n       [" : "[";
    for (std::size_t c = 0; c < cols; ++c)
      s += (c ? ", " : "") + format_number(v.data[r * cols + c]);
    s += "]";
  }
  return s + (rows > 1 ? "])" : ")");
}

// Every answer of every problem, typed in each of forms_of(answer): each must be judged right
// (or, with `right` false, wrong). Returns how many were judged.
int forms_judged(const std::function<std::vector<std::string>(const Answer&)>& forms_of,
                 bool right = true) {
  int forms = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        for (const auto& text : forms_of(a)) {
          INFO(p.id << " " << a.name << ": " << text);
          const Verdict v = f.check(a.name, text);
          INFO(v.line);
          REQUIRE(v.correct == right);
          ++forms;
        }
      }
    }
  }
  return forms;
}

// The text key's "Parameters:" line as (name, value) pairs, each as printed: "θ0" and
// "30° = 0.5235987756 rad", "g" and "9.81 m/s²".
std::vector<std::pair<std::string, std::string>> printed_parameters(const Key& key) {
  const std::string text = render_text(key), lead = "\nParameters: ";
  const auto from = text.find(lead) + lead.size();
  const std::string line = text.substr(from, text.find('\n', from) - from);
  std::vector<std::pair<std::string, std::string>> out;
  for (std::size_t at = 0; at <= line.size();) {
    const auto end = std::min(line.find("; ", at), line.size());
    const std::string piece = line.substr(at, end - at), eq = " = ";
    const auto split = piece.find(eq);
    out.emplace_back(piece.substr(0, split), piece.substr(split + eq.size()));
    at = end + 2;
  }
  return out;
}

// Every problem's key at its default values (variant 0) and at variants 1 and 2.
void for_each_key(const std::function<void(const Problem&, long variant, const Key&)>& f) {
  for (const auto& p : load_catalog()) {
    for (const long variant : {0L, 1L, 2L}) {
      const std::vector<std::string> drawn =
          variant ? variant_for(p, variant) : std::vector<std::string>{};
      f(p, variant, solve(p, parameter_values(p, drawn)));
    }
  }
}
}  // namespace

TEST_CASE("every parameter value a key prints reads back through --set, every problem") {
  // Printed with ten significant digits: within half a unit of the tenth, 5e-10 of the value.
  constexpr double kTenDigits = 5e-10;
  int read = 0;
  for_each_key([&](const Problem& p, long variant, const Key& key) {
    const auto printed = printed_parameters(key);
    REQUIRE(printed.size() == key.parameters.size());
    for (std::size_t i = 0; i < printed.size(); ++i) {
      const auto& [name, value] = printed[i];
      const ParameterValue& want = key.parameters[i];
      std::vector<std::string> values{value};
      if (const auto eq = value.find(" = "); eq != std::string::npos) {
        values.push_back(value.substr(0, eq));   // "30°"
        values.push_back(value.substr(eq + 3));  // "0.5235987756 rad"
      }
      // Also as the statement prints the symbol ("ω₁"), and as it sounds ("omega1").
      for (const std::string& as : {name, want.name, want.latex, "$" + want.latex + "$",
                                    math_to_unicode(want.latex), sym::typed_spelling(want.latex)}) {
        for (const auto& v : values) {
          INFO(p.id << " variant " << variant << ": --set " << as << "=" << v);
          const sym::Values got = parameter_values(p, {as + "=" + v});
          REQUIRE_THAT(got.at(want.name), Catch::Matchers::WithinRel(want.value, kTenDigits));
          ++read;
        }
      }
    }
  });
  REQUIRE(read > 750);  // 15 problems, three sets of values, 3 to 10 parameters, 6 names each
}

namespace {
// The LaTeX key's "Parameters:" line, each parameter's math as printed:
// "$\theta_0 = 30^\circ = 0.5235987756\,\mathrm{rad}$".
std::vector<std::string> printed_latex_parameters(const Key& key) {
  const std::string latex = render_latex(key), lead = "Parameters: ";
  const auto from = latex.find(lead) + lead.size();
  const std::string line = latex.substr(from, latex.find('\n', from) - from);
  std::vector<std::string> out;
  for (auto open = line.find('$'); open != std::string::npos; open = line.find('$', open)) {
    const auto close = line.find('$', open + 1);
    out.push_back(line.substr(open, close + 1 - open));
    open = close + 1;
  }
  return out;
}
}  // namespace

TEST_CASE("every parameter a LaTeX key prints reads back through --set, name and value") {
  constexpr double kTenDigits = 5e-10;  // as for the text key's line, above
  int read = 0;
  for_each_key([&](const Problem& p, long variant, const Key& key) {
    const sym::SymbolTable table = p.symbol_table();
    const auto printed = printed_latex_parameters(key);
    REQUIRE(printed.size() == key.parameters.size());
    for (std::size_t i = 0; i < printed.size(); ++i) {
      // Whole, with its delimiters, as copied from the source; a key's both sides must agree.
      INFO(p.id << " variant " << variant << ": --set '" << printed[i] << "'");
      const sym::Values got = parameter_values(p, {latex_assignment_as_text(printed[i], table)});
      const ParameterValue& want = key.parameters[i];
      REQUIRE_THAT(got.at(want.name), Catch::Matchers::WithinRel(want.value, kTenDigits));
      ++read;
    }
  });
  REQUIRE(read > 120);  // 15 problems, three sets of values, 3 to 10 parameters each
}

TEST_CASE("every printed form of every answer of every problem reads back as correct") {
  const int forms = forms_judged([](const Answer& a) {
    // In a Markdown code span too, as a forum's or a chat's post sets an answer apart.
    std::vector<std::string> texts{printed_value(a), "`" + a.name + " = " + printed_value(a) + "`"};
    if (!a.symbolic.empty()) {
      texts.push_back(a.symbolic);                   // the JSON's and Markdown's symbolic text
      texts.push_back(sym::to_unicode(a.symbolic));  // the text key's line
      texts.push_back("`" + a.symbolic + "`");       // the Markdown key's, copied from its source
    }
    if (a.value.shape != Value::Shape::scalar) {
      texts.push_back(spaced_rows(a));
      texts.push_back(matlab_rows(a));
      texts.push_back(mathematica_lists(a));
      texts.push_back(python_array(a, "array"));
      texts.push_back(python_array(a, "Matrix"));
    }
    return texts;
  });
  REQUIRE(forms > 300);  // the catalog has over 100 answers, each in two to eight forms
}

TEST_CASE("every printed answer after its name and a space reads back, alone, by part, handed in") {
  // "omega3_min 118.8 rad/s", as a student lists answers: the name labels the value, as "NAME =
  // VALUE" does, where it goes (wobble check's part), in a part of several answers, and as a
  // submission's line.
  int read = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    const check::Context ctx{f.key, f.table, f.values};
    std::string submission;
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        std::vector<std::string> texts{a.name + " " + printed_value(a)};
        if (!a.symbolic.empty()) texts.push_back(a.name + " " + sym::to_unicode(a.symbolic));
        for (const auto& text : texts) {
          INFO(p.id << ": " << text);
          const Verdict v = f.check(a.name, text);
          INFO(v.line);
          REQUIRE(v.correct);
          ++read;
        }
        // Wrong, in a part of several: judged as the answer its name labels, not asked for one.
        Answer off = a;
        for (double& x : off.value.data) x *= 1.05;
        const std::string wrong = a.name + " " + printed_value(off);
        INFO(p.id << " part " << part.id << ": " << wrong);
        REQUIRE(check::answer_for(ctx, part.id, "", wrong, {}, "part", "--name").name == a.name);
        submission += texts.front() + "\n";
      }
    }
    const check::SubmissionResult handed_in = check::judge_submission(ctx, submission, {});
    INFO(p.id << ":\n" << submission);
    REQUIRE(handed_in.problems.empty());
    std::size_t answered = 0, answers = 0;
    for (const auto& part : f.key.parts) answers += part.answers.size();
    for (const auto& s : handed_in.answers) {
      INFO(s.name << ": " << s.verdict.line);
      if (!s.answered) continue;  // one that does not exist at these values, asked all the same
      REQUIRE(s.verdict.correct);
      ++answered;
    }
    REQUIRE(answered == answers);
  }
  REQUIRE(read > 200);  // the catalog has over 100 answers, most with a closed form
}

TEST_CASE("the text key's answer lines pasted into an answers file read back, every problem") {
  // As a student copies them from `wobble solve`: each answer's line, its value on the line under
  // it ("   = 0.00072 kg m²"), a matrix's rows one a line with the unit after the last; the notes,
  // steps and prose left out.
  // No std::regex: GCC 12 warns inside it under the sanitizers' build.
  const auto answer_line = [](const std::string& line) {  // "    I0 = m·R²/4"
    if (line.compare(0, 4, "    ") != 0 || line.size() < 5 ||
        !(is_letter(line[4]) || line[4] == '_'))
      return false;
    std::size_t end = 4;
    while (end < line.size() && (is_letter(line[end]) || is_digit(line[end]) || line[end] == '_'))
      ++end;
    return line.compare(end, 3, " = ") == 0;
  };
  const auto under_it = [](const std::string& line) {  // "       = 0.00072 kg m²", "  [ 0 .. ]"
    const std::size_t text = line.find_first_not_of(' ');
    return text != std::string::npos && text > 0 &&
           (line.compare(text, 2, "= ") == 0 || line.compare(text, 2, "[ ") == 0);
  };
  int read = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    std::istringstream key(render_text(f.key));
    std::string pasted;
    for (std::string line; std::getline(key, line);) {
      if (answer_line(line) || under_it(line)) pasted += line + "\n";
    }
    const check::SubmissionResult r =
        check::judge_submission({f.key, f.table, f.values}, pasted, {});
    INFO(p.id << ":\n" << pasted);
    INFO(fmt::format("{}", fmt::join(r.problems, "\n")));
    REQUIRE(r.problems.empty());
    for (const auto& a : r.answers) {
      INFO(a.name << ": " << a.verdict.line);
      if (!a.answered) continue;  // one that does not exist at these values prints no line
      REQUIRE(a.verdict.correct);
      ++read;
    }
  }
  REQUIRE(read > 100);  // every answer of the catalog that exists at its defaults
}

TEST_CASE("every printed answer reads back as correct at the tightest tolerance allowed") {
  // kMinRelativeTolerance is the floor of a problem file's and --tolerance's tolerance: the ten
  // digits a key prints must pass there, each entry of a vector or matrix too.
  check::Options tightest;
  tightest.rel_tol = kMinRelativeTolerance;
  tightest.rel_tol_given = true;
  int judged = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        std::vector<std::string> texts{printed_value(a)};
        if (a.value.shape != Value::Shape::scalar) texts.push_back(matlab_rows(a));
        for (const std::string& text : texts) {
          INFO(p.id << " " << a.name << ": " << text);
          const check::Verdict v = f.check(a.name, text, tightest);
          INFO(v.line);
          CHECK(v.correct);
          ++judged;
        }
      }
    }
  }
  REQUIRE(judged > 200);
}

namespace {
// GiNaC text with each of the problem's symbols spelled by `spelling` (its name in, the
// replacement out); functions and numbers as they were.
std::string symbols_respelled(const std::string& ginac_text, const sym::SymbolTable& table,
                              const std::function<std::string(const std::string&)>& spelling) {
  const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  std::string out;
  for (std::size_t i = 0; i < ginac_text.size();) {
    if (!std::isalpha(static_cast<unsigned char>(ginac_text[i]))) {
      // A number runs on through its digits, so "2e" is never read as a symbol e.
      const bool number = std::isdigit(static_cast<unsigned char>(ginac_text[i])) != 0;
      do {
        out += ginac_text[i++];
      } while (number && i < ginac_text.size() && word(ginac_text[i]));
      continue;
    }
    std::size_t end = i;
    while (end < ginac_text.size() && word(ginac_text[end])) ++end;
    const std::string id = ginac_text.substr(i, end - i);
    out += table.contains(id) ? spelling(id) : id;
    i = end;
  }
  return out;
}

// Each Latin and Greek letter of `text` in mathematical italic, as a word processor's equation
// sets a symbol: "I₁" -> "𝐼₁", "ω" -> "𝜔"; anything else as it was.
std::string in_math_italic(const std::string& text) {
  using Utf8 = boost::locale::utf::utf_traits<char>;
  std::string out;
  for (auto it = text.begin(); it != text.end();) {
    const auto start = it;
    const boost::locale::utf::code_point c = Utf8::decode(it, text.end());
    boost::locale::utf::code_point italic = 0;
    if (c >= 'A' && c <= 'Z') italic = 0x1D434 + (c - 'A');
    if (c >= 'a' && c <= 'z') italic = c == 'h' ? 0x210E : 0x1D44E + (c - 'a');
    if (c >= 0x391 && c <= 0x3A9) italic = 0x1D6E2 + (c - 0x391);  // Α..Ω
    if (c >= 0x3B1 && c <= 0x3C9) italic = 0x1D6FC + (c - 0x3B1);  // α..ω
    if (italic != 0) {
      Utf8::encode(italic, std::back_inserter(out));
    } else {
      out.append(start, it);
    }
  }
  return out;
}
}  // namespace

TEST_CASE("every closed form with its symbols as the question prints them reads back") {
  // The statement and questions print each symbol from its LaTeX: w1 as "ω₁", I1 as "I₁",
  // theta0 as "θ₀". A student copies those, types them as they sound ("omega1"), or copies
  // them from an equation editor, in italic ("𝜔₁").
  int forms = 0, respelled = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    const auto as_printed = [&](const std::string& name) {
      return math_to_unicode(f.table.latex_of(name));
    };
    const auto as_typed = [&](const std::string& name) {
      return sym::typed_spelling(f.table.latex_of(name));
    };
    const auto in_italic = [&](const std::string& name) {
      return in_math_italic(as_printed(name));
    };
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        if (a.symbolic.empty()) continue;
        for (const std::string& text :
             {sym::to_unicode(symbols_respelled(a.symbolic, f.table, as_printed)),
              symbols_respelled(a.symbolic, f.table, as_typed),
              sym::to_unicode(symbols_respelled(a.symbolic, f.table, in_italic))}) {
          INFO(p.id << " " << a.name << ": " << text);
          const Verdict v = f.check(a.name, text);
          INFO(v.line);
          REQUIRE(v.correct);
          ++forms;
          respelled += text != sym::to_unicode(a.symbolic) && text != a.symbolic;
        }
      }
    }
  }
  REQUIRE(forms > 225);      // the catalog's closed forms, three spellings each
  REQUIRE(respelled > 125);  // I₁, θ₀, ω₁, 𝑚 and the rest: most forms are not the key's own
}

namespace {
// A rate symbol's parts: "phidot" -> {"phi", ""}, "psidot0" -> {"psi", "0"}; nullopt for a name
// that is no rate.
std::optional<std::pair<std::string, std::string>> rate_parts(const std::string& name) {
  std::size_t digits = name.size();
  while (digits > 0 && std::isdigit(static_cast<unsigned char>(name[digits - 1]))) --digits;
  if (digits <= 3 || name.compare(digits - 3, 3, "dot") != 0) return std::nullopt;
  return std::pair{name.substr(0, digits - 3), name.substr(digits)};
}

// `text` with each occurrence of `from` replaced by `to`.
std::string replaced_all(std::string text, const std::string& from, const std::string& to) {
  for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}
}  // namespace

TEST_CASE("every closed form with its rates in Leibniz's notation reads back, every problem") {
  // φ̇ as a student writes it without Newton's dot: "dphi/dt", "dφ/dt", \frac{d\phi}{dt},
  // "phi'", "phi′".
  int forms = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    std::vector<std::string> rates;  // the rate symbols, their LaTeX longest first
    for (const auto& name : f.table.names()) {
      if (rate_parts(name)) rates.push_back(name);
    }
    std::sort(rates.begin(), rates.end(), [&](const std::string& a, const std::string& b) {
      return f.table.latex_of(a).size() > f.table.latex_of(b).size();
    });
    const auto leibniz = [&](const std::string& name) {
      const auto parts = rate_parts(name);
      return parts ? "(d" + parts->first + parts->second + "/dt)" : name;
    };
    // And in Lagrange's, a prime after the angle, as typed and as a page sets it: "psi0'".
    const auto lagrange = [](const char* prime) {
      return [prime](const std::string& name) {
        const auto parts = rate_parts(name);
        return parts ? "(" + parts->first + parts->second + prime + ")" : name;
      };
    };
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        const bool has_rate = std::any_of(rates.begin(), rates.end(), [&](const std::string& r) {
          return a.latex.find(f.table.latex_of(r)) != std::string::npos;
        });
        if (a.symbolic.empty() || !has_rate) continue;
        std::string latex = a.latex, upright = a.latex;
        for (const auto& r : rates) {
          const std::string dotted = f.table.latex_of(r);  // "\dot\psi_0"
          REQUIRE(dotted.compare(0, 4, "\\dot") == 0);
          const std::string rest = dotted.substr(4);
          latex = replaced_all(latex, dotted, "\\frac{d" + rest + "}{dt}");
          upright = replaced_all(upright, dotted, "\\frac{\\mathrm{d}" + rest + "}{\\mathrm{d}t}");
        }
        for (const std::string& text :
             {symbols_respelled(a.symbolic, f.table, leibniz), latex, upright,
              symbols_respelled(a.symbolic, f.table, lagrange("'")),
              symbols_respelled(a.symbolic, f.table, lagrange("\u2032"))}) {
          INFO(p.id << " " << a.name << ": " << text);
          REQUIRE((text != a.latex && text != a.symbolic));  // a rate was respelled
          const Verdict v = f.check(a.name, text);
          INFO(v.line);
          REQUIRE(v.correct);
          ++forms;
        }
      }
    }
  }
  REQUIRE(forms > 70);  // the Euler angles' rates, twice, and the heavy top's, five forms each
}

namespace {
// Where the unit goes: "(0.0019 e₁ + 0.014 e₃) kg m²/s", "0.0019 e₁ + 0.014 e₃ kg m²/s" or
// "0.0019 e₁ kg m²/s + 0.014 e₃ kg m²/s".
enum class UnitPlace { bracketed, after_last, after_each, before_each };

// A 3-vector answer as a student writes it along unit vectors, spelled by `unit_vector` (its
// axis 0, 1, 2 in, the text out), the unit placed by `place`, the zero components left out as
// people leave them; with `flip`, the largest component's sign turned. Empty for any other
// answer, and for the zero vector.
std::string along_unit_vectors(const Answer& a,
                               const std::function<std::string(std::size_t)>& unit_vector,
                               bool flip = false, UnitPlace place = UnitPlace::bracketed) {
  const auto& d = a.value.data;
  if (a.value.shape != Value::Shape::vector || d.size() != 3) return "";
  std::size_t largest = 0;
  for (std::size_t k = 1; k < 3; ++k) largest = std::abs(d[k]) > std::abs(d[largest]) ? k : largest;
  if (d[largest] == 0.0) return "";
  std::string sum;
  for (std::size_t k = 0; k < 3; ++k) {
    const double x = flip && k == largest ? -d[k] : d[k];
    if (x == 0.0) continue;
    const std::string unit = a.unit.empty() ? "" : " " + a.unit;
    const std::string size = place == UnitPlace::before_each
                                 ? format_number(std::abs(x)) + unit + " " + unit_vector(k)
                                 : format_number(std::abs(x)) + " " + unit_vector(k) +
                                       (place == UnitPlace::after_each ? unit : "");
    sum += sum.empty() ? (x < 0 ? "-" : "") + size : (x < 0 ? " - " : " + ") + size;
  }
  if (a.unit.empty() || place == UnitPlace::after_each || place == UnitPlace::before_each)
    return sum;
  return place == UnitPlace::bracketed ? "(" + sum + ") " + a.unit : sum + " " + a.unit;
}
}  // namespace

TEST_CASE("every vector answer as components along unit vectors reads back, every problem") {
  // The statements name the body's axes e₁, e₂, e₃; books write the space basis x̂, î or, in
  // LaTeX, \hat{x}, \mathbf{i}. A vector's components read the same along either.
  const std::vector<std::function<std::string(std::size_t)>> spellings{
      [](std::size_t k) { return "e" + std::string("₁₂₃").substr(3 * k, 3); },
      [](std::size_t k) { return "e" + std::to_string(k + 1); },
      [](std::size_t k) { return "e_" + std::to_string(k + 1); },
      [](std::size_t k) { return "e_" + std::to_string(k + 1) + "'"; },
      [](std::size_t k) { return "\\hat{e}_{" + std::to_string(k + 1) + "}"; },
      [](std::size_t k) { return "\\mathbf{e}_" + std::to_string(k + 1); },
      [](std::size_t k) { return "\\hat{" + std::string(1, "xyz"[k]) + "}"; },
      [](std::size_t k) { return "\\mathbf{" + std::string(1, "ijk"[k]) + "}"; },
      [](std::size_t k) { return k == 0   ? "\\hat\\imath"
                                 : k == 1 ? "\\hat\\jmath"
                                          : "\\hat{k}"; }};
  int right = 0, wrong = 0;
  for (const auto& spelling : spellings) {
    right += forms_judged([&](const Answer& a) {
      const std::string text = along_unit_vectors(a, spelling);
      return text.empty() ? std::vector<std::string>{} : std::vector<std::string>{text};
    });
    wrong += forms_judged(
        [&](const Answer& a) {
          const std::string text = along_unit_vectors(a, spelling, true);
          return text.empty() ? std::vector<std::string>{} : std::vector<std::string>{text};
        },
        false);
  }
  REQUIRE(right > 9 * 30);  // the catalog's nonzero 3-vectors, in nine spellings
  REQUIRE(wrong == right);
}

TEST_CASE("every vector answer along bare x, y, z, as the statements write ω(0), reads back") {
  // "ω(0) = ω(sin α x + cos α z)": the statements' own unit vectors, no hat. Read so only as a
  // sum of two terms or more (one term, "19.3 z", is refused), so vectors with two nonzero
  // components or three.
  const auto bare = [](std::size_t k) { return std::string(1, "xyz"[k]); };
  const auto two_terms = [](const Answer& a) {
    return std::count_if(a.value.data.begin(), a.value.data.end(),
                         [](double x) { return x != 0.0; }) >= 2;
  };
  const auto forms = [&](bool flip) {
    return [&, flip](const Answer& a) {
      std::vector<std::string> out;
      if (a.value.shape != Value::Shape::vector || a.value.data.size() != 3 || !two_terms(a))
        return out;
      for (const UnitPlace place : {UnitPlace::bracketed, UnitPlace::after_last})
        out.push_back(along_unit_vectors(a, bare, flip, place));
      return out;
    };
  };
  const int right = forms_judged(forms(false));
  REQUIRE(forms_judged(forms(true), false) == right);
  REQUIRE(right > 2 * 10);  // the catalog's 3-vectors with two nonzero components or three
}

TEST_CASE("every vector answer as a factor times a bracketed sum along unit vectors reads back") {
  // "ω(sin α x̂ + 2 cos α ẑ)" as a statement writes ω(0): here the factor 2 before the halves.
  const auto forms = [](bool flip) {
    return [flip](const Answer& a) {
      std::vector<std::string> out;
      if (a.value.shape != Value::Shape::vector || a.value.data.size() != 3) return out;
      Answer half = a;
      for (auto& x : half.value.data) x /= 2;
      half.unit.clear();
      const std::string sum = along_unit_vectors(
          half,
          [](std::size_t k) { return std::string("îĵk̂").substr(k < 2 ? 2 * k : 4, k < 2 ? 2 : 3); },
          flip);
      if (!sum.empty()) out.push_back("2(" + sum + ")" + (a.unit.empty() ? "" : " " + a.unit));
      return out;
    };
  };
  const int right = forms_judged(forms(false));
  REQUIRE(forms_judged(forms(true), false) == right);
  REQUIRE(right > 30);  // the catalog's nonzero 3-vectors
}

TEST_CASE("every problem's principal axes listed one by one read back, with a factor or along x̂") {
  // The key's axes are its matrix's columns; a student lists them, each scaled as books write a
  // normalised axis, "(a, b, c)/2, ..", or along unit vectors. (That a list is not read across,
  // its vectors as a matrix's columns, check's notation tests show on the four masses.)
  const auto listed = [](const Answer& a, bool with_factor) {
    std::vector<std::string> out;
    if (a.kind != AnswerKind::principal_axes) return out;
    const auto& d = a.value.data;  // row-major, axes as columns
    std::string text;
    for (std::size_t c = 0; c < 3; ++c) {
      const std::string x = format_number(2 * d[c]), y = format_number(2 * d[3 + c]),
                        z = format_number(2 * d[6 + c]);
      text += (c ? ", " : "") + (with_factor ? "(" + x + ", " + y + ", " + z + ")/2"
                                             : "(" + x + ") x̂ + (" + y + ") ŷ + (" + z + ") ẑ");
    }
    out.push_back(text);
    return out;
  };
  const int right = forms_judged([&](const Answer& a) { return listed(a, true); }) +
                    forms_judged([&](const Answer& a) { return listed(a, false); });
  REQUIRE(right >= 2 * 7);  // the catalog's principal axes (7 today), two ways each
}

TEST_CASE("every vector answer along unit vectors with its unit after the last term or each") {
  // "2.59 î + 19.3 k̂ rad/s" as people write it without the brackets; the unit after each term
  // as a component's, or before each unit vector ("2.59 rad/s î + 19.3 rad/s k̂", as "5 N x̂").
  const std::vector<std::function<std::string(std::size_t)>> spellings{
      [](std::size_t k) { return "e" + std::string("₁₂₃").substr(3 * k, 3); },
      [](std::size_t k) { return std::string("îĵk̂").substr(k < 2 ? 2 * k : 4, k < 2 ? 2 : 3); }};
  int right = 0, wrong = 0;
  for (const auto& spelling : spellings) {
    for (const UnitPlace place :
         {UnitPlace::after_last, UnitPlace::after_each, UnitPlace::before_each}) {
      right += forms_judged([&](const Answer& a) {
        const std::string text = along_unit_vectors(a, spelling, false, place);
        return text.empty() ? std::vector<std::string>{} : std::vector<std::string>{text};
      });
      wrong += forms_judged(
          [&](const Answer& a) {
            const std::string text = along_unit_vectors(a, spelling, true, place);
            return text.empty() ? std::vector<std::string>{} : std::vector<std::string>{text};
          },
          false);
    }
  }
  REQUIRE(right > 6 * 30);  // the catalog's nonzero 3-vectors, two spellings, three places
  REQUIRE(wrong == right);
}

TEST_CASE("every number with its unit in siunitx's LaTeX reads back, every answer") {
  // \qty{0.00072}{kg.m^2}, \SI{..}{..}, \num{..}: how a student who writes LaTeX sets a
  // quantity. The unit as text, its spaces as siunitx's dots.
  const auto siunitx = [](const Answer& a, double factor) {
    std::vector<std::string> texts;
    // A zero doubled is zero: no wrong twin, so no right one either.
    if (a.value.shape != Value::Shape::scalar || a.value.data[0] == 0.0) return texts;
    const std::string n = format_number(a.value.data[0] * factor);
    if (a.unit.empty()) return std::vector<std::string>{"\\num{" + n + "}"};
    std::string dotted = a.unit;
    std::replace(dotted.begin(), dotted.end(), ' ', '.');
    return std::vector<std::string>{"\\qty{" + n + "}{" + dotted + "}",
                                    "\\SI[per-mode=symbol]{" + n + "}{" + a.unit + "}"};
  };
  const int right = forms_judged([&](const Answer& a) { return siunitx(a, 1.0); });
  const int wrong = forms_judged([&](const Answer& a) { return siunitx(a, 2.0); }, false);
  REQUIRE(right > 60);  // the catalog's scalar answers, one or two forms each
  REQUIRE(wrong == right);
}

TEST_CASE("every answer the worksheet reveals reads back as correct, every problem") {
  int revealed = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    // '!' at every prompt: each answer revealed in turn, in the key's order.
    std::vector<std::string> names;
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) names.push_back(a.name);
    }
    std::size_t asked = 0;
    const ReadLine reveal_all = [&](const std::string&, std::string& line) {
      line = "!";
      return asked++ < names.size();
    };
    std::ostringstream out;
    (void)run_worksheet(reveal_all, out, "", f.problem, {f.key, f.table, f.values}, {});
    std::istringstream lines(out.str());
    std::size_t k = 0;
    const std::string lead = "  answer: ";
    for (std::string line; std::getline(lines, line);) {
      // A part's question: its math in Unicode, as the statement's ("θ_min", not "$\theta..$").
      if (line.rfind("(", 0) == 0) {
        INFO(line);
        REQUIRE(line.find_first_of("$\\{}") == std::string::npos);
      }
      if (line.rfind(lead, 0) != 0) continue;
      REQUIRE(k < names.size());
      const std::string text = line.substr(lead.size());
      INFO(p.id << " " << names[k] << ": " << text);
      // In the terminal's notation, as the statement is printed.
      if (!f.answer(names[k]).symbolic.empty())
        REQUIRE(text.rfind(sym::to_unicode(f.answer(names[k]).symbolic) + " = ", 0) == 0);
      const Verdict v = f.check(names[k], text);
      INFO(v.line);
      REQUIRE(v.correct);
      ++k;
      ++revealed;
    }
  }
  REQUIRE(revealed > 100);  // every answer the catalog asks for in a worksheet
}

namespace {
// The words of a text, whatever spaces and line ends lie between them: what breaking its lines
// at spaces must keep.
std::vector<std::string> words(const std::string& text) {
  std::istringstream in(text);
  return std::vector<std::string>(std::istream_iterator<std::string>(in), {});
}
}  // namespace

TEST_CASE("the worksheet at a terminal's width breaks its lines at spaces, losing no word") {
  constexpr std::size_t kWidth = 64;  // narrower than any statement's lines in the catalog
  int broken = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    const std::string intro = render_handout_text(f.key, {}, std::nullopt, false);
    // At each prompt a wrong number, the hint, then the answer: verdicts, feedback, hints.
    const auto run = [&](std::size_t width) {
      std::size_t asked = 0;
      const ReadLine tries = [&](const std::string&, std::string& line) {
        line = std::array<const char*, 4>{"1", "1e9", "?", "!"}[asked % 4];
        return asked++ < 400;
      };
      std::ostringstream out;
      (void)run_worksheet(tries, out, intro, f.problem, {f.key, f.table, f.values}, {}, width);
      return out.str();
    };
    const std::string whole = run(0), wrapped = run(kWidth);
    INFO(p.id << ":\n" << wrapped);
    REQUIRE(words(wrapped) == words(whole));
    std::istringstream lines(wrapped);
    for (std::string line; std::getline(lines, line);) {
      if (columns(line) <= kWidth) continue;
      INFO(line);
      // Only a revealed answer (kept whole, to be copied) or one word too wide for any line.
      const std::size_t indent = line.find_first_not_of(' ');
      REQUIRE((line.rfind("  answer: ", 0) == 0 ||
               line.find(' ', indent == std::string::npos ? 0 : indent) == std::string::npos));
    }
    broken += static_cast<int>(std::count(wrapped.begin(), wrapped.end(), '\n') -
                               std::count(whole.begin(), whole.end(), '\n'));
  }
  REQUIRE(broken > 100);  // the catalog's statements, verdicts and hints do break
}

TEST_CASE("the text key at a terminal's width breaks its prose, never an answer's line") {
  constexpr std::size_t kWidth = 72;
  int long_answers = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    const std::string whole = render_text(f.key), wrapped = render_text(f.key, kWidth);
    INFO(p.id << ":\n" << wrapped);
    REQUIRE(words(wrapped) == words(whole));
    std::set<std::string> whole_lines;
    std::istringstream in(whole);
    for (std::string line; std::getline(in, line);) whole_lines.insert(line);
    // Every answer's lines as they were: what a student copies into check.
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        if (a.symbolic.empty()) continue;
        REQUIRE(wrapped.find("    " + a.name + " = " + detail::pretty(a.symbolic) + "\n") !=
                std::string::npos);
      }
    }
    std::istringstream lines(wrapped);
    for (std::string line; std::getline(lines, line);) {
      if (columns(line) <= kWidth) continue;
      INFO(line);
      // Wider only where it is an answer's line, kept whole (a step, a note or a question
      // would have been broken), or a word wider than any line.
      const std::size_t indent = line.find_first_not_of(' ');
      const bool one_word = line.find(' ', indent) == std::string::npos;
      REQUIRE((one_word ||
               (whole_lines.count(line) == 1 && line.rfind("      note: ", 0) != 0 &&
                line.find(". ") != 4 && line.rfind("  - ", 0) != 0 && line.rfind("(", 0) != 0)));
      long_answers += one_word ? 0 : 1;
    }
  }
  REQUIRE(long_answers > 5);  // the heavy top's nutation limit and steady rates at least
}

TEST_CASE("every part's hint prints in the worksheet as plain text, every problem") {
  int hints = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    std::size_t prompts = 0;
    for (const auto& part : f.key.parts) prompts += part.answers.size();
    // At every prompt '?' (the hint), then '!' (the answer), so each part's hint is asked for.
    std::size_t asked = 0;
    const ReadLine hint_then_reveal = [&](const std::string&, std::string& line) {
      line = asked % 2 == 0 ? "?" : "!";
      return asked++ < 2 * prompts;
    };
    std::ostringstream out;
    (void)run_worksheet(hint_then_reveal, out, "", f.problem, {f.key, f.table, f.values}, {});
    std::set<std::string> shown;
    std::istringstream lines(out.str());
    std::string part_id;
    for (std::string line; std::getline(lines, line);) {
      if (line.rfind("(", 0) == 0) part_id = line.substr(1, line.find(')') - 1);
      const std::string lead = "  hint: ";
      if (line.rfind(lead, 0) != 0) continue;
      // Its math in Unicode, as the question's: "I₁ ω̇₁", not "$I_1 \dot\omega_1$".
      INFO(p.id << " (" << part_id << "): " << line);
      CHECK(line.find_first_of("$\\{}") == std::string::npos);
      CHECK(line.size() > lead.size() + 10);
      shown.insert(part_id);
    }
    for (const auto& spec : f.problem.parts) {
      INFO(p.id << " (" << spec.id << ")");
      CHECK(shown.count(spec.id) == (spec.hint.empty() ? 0U : 1U));
      hints += spec.hint.empty() ? 0 : 1;
    }
  }
  CHECK(hints > 50);  // the catalog's hints, each seen
}

// The LaTeX a key prints for an answer: the closed form, the value with its unit as the LaTeX key
// sets it, the Markdown key's whole display "closed form = value" (what the browser's copy of
// typeset math gives), and the closed form after the answer's own name.
std::vector<std::string> latex_forms(const Answer& a) {
  const std::string value = value_latex(a.value) + detail::unit_latex(a.unit);
  std::vector<std::string> texts{value, "$" + value + "$", a.latex};
  // A vector or matrix of fractions as the LaTeX key displays it: \dfrac, rows set apart.
  if (const std::string shown = detail::matrix_fractions_displayed(a.latex); shown != a.latex)
    texts.push_back(shown);
  if (!a.symbolic.empty()) {
    texts.push_back("$$\n" + a.latex + " = " + value + "\n$$");
    if (const auto name = detail::answer_symbol_latex(a.name))
      texts.push_back(*name + " = " + a.latex);
  }
  return texts;
}

// The key's LaTeX as a student may type it instead: \dfrac, plain brackets for \left( \right),
// braces around each subscript and marked letter ("\dot{\psi}_{0}").
std::string respelled(const std::string& latex) {
  std::string out;
  for (std::size_t i = 0; i < latex.size(); ++i) {
    if (latex.compare(i, 6, "\\frac") == 0) {
      out += "\\dfrac";
      i += 4;
    } else if (latex.compare(i, 6, "\\left(") == 0 || latex.compare(i, 7, "\\right)") == 0) {
      out += latex[i + 1] == 'l' ? "(" : ")";
      i += latex[i + 1] == 'l' ? 5 : 6;
    } else if (latex.compare(i, 4, "\\dot") == 0 && i + 4 < latex.size() && latex[i + 4] == '\\') {
      std::size_t end = i + 5;
      while (end < latex.size() && std::isalpha(static_cast<unsigned char>(latex[end]))) ++end;
      out += "\\dot{" + latex.substr(i + 4, end - i - 4) + "}";
      i = end - 1;
    } else if (latex[i] == '_' && i + 1 < latex.size() && latex[i + 1] != '{') {
      out += "_{" + latex.substr(i + 1, 1) + "}";
      ++i;
    } else {
      out += latex[i];
    }
  }
  return out;
}

TEST_CASE("a line's closing ';' (MATLAB's) or full stop is no part of the answer, every answer") {
  const int forms = forms_judged([](const Answer& a) {
    std::vector<std::string> texts{printed_value(a) + ".", printed_value(a) + ";"};
    if (!a.symbolic.empty()) {
      texts.push_back(sym::to_unicode(a.symbolic) + ".");
      texts.push_back(a.latex + ".");  // a displayed equation ends its sentence
    }
    if (a.value.shape != Value::Shape::scalar) texts.push_back(matlab_rows(a) + ";");
    return texts;
  });
  REQUIRE(forms > 300);  // over 100 answers, each in two to five forms
  // The punctuation is dropped, not the judging: a wrong value with it is still wrong.
  const Fixture plate("flying-plate");
  REQUIRE(plate.check("I0", "0.00072 kg m^2.").correct);
  REQUIRE_FALSE(plate.check("I0", "0.00073 kg m^2.").correct);
  REQUIRE_FALSE(plate.check("I0", "0.00073;").correct);
  // One full stop only: "0.333..." is no number wobble reads.
  REQUIRE_THROWS_AS(plate.check("I0", "0.00072..."), InputError);
}

TEST_CASE("every vector answer as a list in words, its last entry after 'and', reads back") {
  // "0.569, 4.209 and 4.556 kg m²", with the list's comma before "and" or not.
  int vectors = 0;
  const int forms = forms_judged([&](const Answer& a) -> std::vector<std::string> {
    if (a.value.shape != Value::Shape::vector) return {};
    ++vectors;
    std::string list;
    for (std::size_t i = 0; i + 1 < a.value.data.size(); ++i)
      list += (i ? ", " : "") + format_number(a.value.data[i]);
    const std::string last = format_number(a.value.data.back()) + " " + a.unit;
    if (a.value.data.size() == 2) return {list + " and " + last};
    return {list + " and " + last, list + ", and " + last};
  });
  REQUIRE(vectors > 30);
  REQUIRE(forms > 50);
  // The word makes the list, not the judging: an entry off is named.
  const Fixture box("box-corner");
  const auto& moments = box.answer("principal_moments_corner").value.data;
  const Verdict off = box.check(
      "principal_moments_corner",
      fmt::format("{:.6g}, {:.6g} and {:.6g}", moments[0], moments[1], moments[2] * 1.05));
  REQUIRE_FALSE(off.correct);
  REQUIRE_THAT(off.feedback.at(0), Catch::Contains("off by 5%"));
}

TEST_CASE("every LaTeX form of every answer of every problem reads back as correct") {
  const int forms = forms_judged(latex_forms);
  REQUIRE(forms > 3 * 100);  // over 100 answers, each in three to five forms
  const int respelt = forms_judged([](const Answer& a) {
    return a.symbolic.empty() ? std::vector<std::string>{}
                              : std::vector<std::string>{respelled(a.latex)};
  });
  REQUIRE(respelt > 50);
}

TEST_CASE("every closed form in LaTeX, doubled, is judged wrong: the LaTeX is read, not waved by") {
  const int judged = forms_judged(
      [](const Answer& a) {
        const bool nonzero_number = a.value.shape == Value::Shape::scalar && a.value.data[0] != 0.0;
        return a.symbolic.empty() || !nonzero_number
                   ? std::vector<std::string>{}
                   : std::vector<std::string>{"2\\left(" + a.latex + "\\right)"};
      },
      false);
  REQUIRE(judged > 40);
}

TEST_CASE("a key line with '=' is judged side by side, the answer's name or a label dropped") {
  const Fixture plate("flying-plate");
  const Answer& i0 = plate.answer("I0");
  // The text key's two lines as copied together.
  const std::string line =
      "I0 = " + sym::to_unicode(i0.symbolic) + "\n       = " + printed_value(i0);
  REQUIRE(plate.check("I0", line).correct);
  REQUIRE(plate.check("I0", "       = " + printed_value(i0)).correct);  // its second line alone
  // More sides than a key's line has are refused, not each simplified in turn.
  REQUIRE_THAT(error_of(plate, "I0", "m*R^2/4 = m*R^2/4 = " + printed_value(i0)),
               Catch::Equals("--answer: 3 sides of '='; give the answer, or a key's line: its "
                             "closed form = its value"));
  // A label of the student's own on the left, a name that is no symbol of the problem, is
  // dropped: the answer is the side after it.
  REQUIRE(plate.check("I0", "I = " + i0.symbolic).correct);
  REQUIRE(plate.check("angle_L_e3", "θ_L = 7.631°").correct);
  REQUIRE(plate.check("angle_L_e3", "\\theta_{L} = 7.631^\\circ").correct);
  REQUIRE_FALSE(plate.check("angle_L_e3", "θ_L = 8.2°").correct);
  const Fixture top("heavy-top");  // a primed name, as the heavy top's E′ is written
  const std::string e_prime = printed_value(top.answer("energy_prime"));
  REQUIRE(top.check("energy_prime", "E′ = " + e_prime).correct);
  REQUIRE(top.check("energy_prime", "E' = " + e_prime).correct);
  // An expression in a name the problem lacks (2x) labels the value too, but that side is said
  // to be unjudged; one of the problem's symbols is judged as a side.
  REQUIRE_THAT(plate.check("angle_L_e3", "2x = 7.631°").feedback,
               Catch::Equals(std::vector<std::string>{
                   "the side \"2x\" of your '=' is taken as a label, not judged: x is no symbol "
                   "here"}));
  const Verdict symbol_side = plate.check("angle_omega_e3", "m = 0.2618 rad");
  REQUIRE_FALSE(symbol_side.correct);
  REQUIRE_THAT(symbol_side.feedback.at(0), Catch::StartsWith("the side \"m\""));
  // The label before a whole key's line, "E = closed form = value", as a derivation ends: dropped
  // as before one side, and the two sides after it judged. A formula of the student's own
  // between them ("E = T + V = ..") is a label too, said unjudged; a symbol of the problem first
  // is no label, and the line stays three sides.
  const Answer& energy = top.answer("energy");
  const std::string energy_value = printed_value(energy);
  REQUIRE(top.check("energy", "E = " + energy.symbolic + " = " + energy_value).correct);
  REQUIRE(top.check("energy", "E = " + energy_value + " = " + energy.symbolic).correct);
  REQUIRE(top.check("energy", "E = MR²ψ̇₀²/4 + Mgl cos θ₀ = " + energy_value).correct);
  const Verdict labelled = top.check("energy", "E = T + V = " + energy_value);
  REQUIRE(labelled.correct);
  REQUIRE(labelled.feedback == std::vector<std::string>{"the side \"T + V\" of your '=' is taken "
                                                        "as a label, not judged: T is no symbol "
                                                        "here"});
  const Verdict wrong_side = top.check(
      "energy", "E = " + energy.symbolic + " = " + format_number(energy.value.data[0] * 1.05));
  REQUIRE_FALSE(wrong_side.correct);
  REQUIRE_THAT(wrong_side.feedback.at(0),
               Catch::StartsWith("the side \"" + format_number(energy.value.data[0] * 1.05)));
  REQUIRE_FALSE(top.check("energy", "E = MR²ψ̇₀²/4 − Mgl cos θ₀ = " + energy_value).correct);
  REQUIRE_THAT(error_of(top, "energy", "M = " + energy.symbolic + " = " + energy_value),
               Catch::Contains("3 sides of '='"));
  REQUIRE_THAT(error_of(top, "energy", "E = T + V = " + energy.symbolic + " = " + energy_value),
               Catch::Contains("3 sides of '='"));
  // Every side must be right; the wrong one is named.
  const Verdict v = plate.check("I0", i0.symbolic + " = " + format_number(i0.value.data[0] * 1.05));
  REQUIRE_FALSE(v.correct);
  REQUIRE_THAT(v.feedback.at(0),
               Catch::StartsWith("the side \"" + format_number(i0.value.data[0] * 1.05)));
}

// A unit with a denominator, "kg m^2/s", as a student may write it instead: with negative powers,
// "kg m^2 s^-1", "kg m^2 s^(-1)" or "kg m² s⁻¹"; {} for a unit without one.
std::vector<std::string> negative_power_forms(const std::string& unit) {
  const auto slash = unit.find('/');
  if (slash == std::string::npos) return {};
  std::string den = unit.substr(slash + 1), power = "1";
  if (const auto caret = den.find('^'); caret != std::string::npos) {
    power = den.substr(caret + 1);
    den = den.substr(0, caret);
  }
  const std::string num = unit.substr(0, slash) == "1" ? "" : unit.substr(0, slash) + " ";
  const auto superscript = [](const std::string& digit) {
    return digit == "1" ? std::string("¹") : digit == "2" ? std::string("²") : std::string("³");
  };
  std::string num_unicode = num;
  if (const auto sq = num_unicode.find("^2"); sq != std::string::npos)
    num_unicode.replace(sq, 2, "²");
  return {num + den + "^-" + power, num + den + "^(-" + power + ")",
          num_unicode + den + "⁻" + superscript(power)};
}

// The key's "cos(alpha)^2" in the textbook's notation "cos^2(alpha)"; "" when it has none.
std::string textbook_powers(const std::string& text) {
  std::string out = text;
  bool any = false;
  for (const std::string f : {"sin(", "cos(", "tan(", "sinh(", "cosh(", "tanh("}) {
    for (std::size_t at = out.find(f); at != std::string::npos; at = out.find(f, at + 1)) {
      if (at > 0 && std::isalpha(static_cast<unsigned char>(out[at - 1]))) continue;  // asin(
      std::size_t close = at + f.size(), depth = 1;
      for (; close < out.size() && depth > 0; ++close)
        depth += out[close] == '(' ? 1 : out[close] == ')' ? -1 : 0;
      if (close + 1 >= out.size() || out[close] != '^' ||
          !std::isdigit(static_cast<unsigned char>(out[close + 1])))
        continue;
      const std::string power(1, out[close + 1]);
      out = out.substr(0, at + f.size() - 1) + "^" + power +
            out.substr(at + f.size() - 1, close - (at + f.size() - 1)) + out.substr(close + 2);
      any = true;
    }
  }
  return any ? out : "";
}

TEST_CASE("a trigonometric power as textbooks write it, cos^2(x), reads back, every answer") {
  const int forms = forms_judged([](const Answer& a) {
    const std::string text = textbook_powers(a.symbolic);
    return text.empty() ? std::vector<std::string>{}
                        : std::vector<std::string>{text, sym::to_unicode(text)};
  });
  REQUIRE(forms >= 2 * 20);  // 23 closed forms with a power of a sine or cosine today
}

TEST_CASE("units written out, and degree signs from keyboards without one") {
  const Fixture top("heavy-top");
  const double theta = top.answer("theta_max").value.data[0];
  const double w3 = top.answer("omega3_min").value.data[0];
  const std::string degrees = fmt::format("{:.6g}", theta * 180 / M_PI);
  for (const std::string& typed :
       {degrees + " degrees", degrees + "º", degrees + "˚", degrees + " degree",
        fmt::format("{:.6g} radians", theta), fmt::format("{:.6g} rads", theta)}) {
    INFO(typed);
    REQUIRE(top.check("theta_max", typed).correct);
  }
  REQUIRE_FALSE(top.check("theta_max", fmt::format("{:.6g} degrees", theta)).correct);
  REQUIRE(top.check("omega3_min", fmt::format("{:.6g} radians per second", w3)).correct);
  REQUIRE(top.check("omega3_min", fmt::format("{:.6g} per second", w3)).correct);
  REQUIRE_FALSE(top.check("omega3_min", fmt::format("{:.6g} per minute", w3)).correct);
  // Glued to the number, as --set takes an angle: where no symbol has the unit's letters.
  REQUIRE(top.check("theta_max", degrees + "deg").correct);
  REQUIRE(top.check("omega3_min", fmt::format("{:.6g}rad/s", w3)).correct);
  REQUIRE_FALSE(top.check("omega3_min", fmt::format("{:.6g}rpm", w3)).correct);
  const Fixture three("taylor-10-35");  // m is a mass there: 2m is refused, not read as metres
  REQUIRE_THROWS_AS(three.check("I", "10m"), InputError);
  REQUIRE(
      top.check("omega3_min", fmt::format("{:.6g} revolutions per minute", w3 * 60 / (2 * M_PI)))
          .correct);
  REQUIRE_FALSE(
      top.check("omega3_min", fmt::format("{:.6g} revolutions per second", w3 * 60 / (2 * M_PI)))
          .correct);
}

// A vector or matrix with a unit after each number, "(2.588 rad/s, 0, 19.32 rad/s)", zeros
// without one; each number divided by `per_unit` (the unit's size in the key's) and followed by
// `unit` ("" for the key's), with `separator` between the entries of a row.
std::string unit_on_each(const Answer& a, const std::string& separator, double per_unit = 1.0,
                         std::string unit = "") {
  if (unit.empty()) unit = " " + a.unit;
  const auto& v = a.value;
  const std::size_t cols = v.shape == Value::Shape::vector ? v.data.size() : v.cols;
  std::string s = v.shape == Value::Shape::vector ? "(" : "[[";
  for (std::size_t i = 0; i < v.data.size(); ++i) {
    if (i > 0) s += i % cols == 0 ? "], [" : separator;
    s += v.data[i] == 0.0 ? "0" : fmt::format("{:.12g}", v.data[i] / per_unit) + unit;
  }
  return s + (v.shape == Value::Shape::vector ? ")" : "]]");
}

// The same in a LaTeX pmatrix, each number followed by `unit`: a vector as a column, a matrix's
// rows ended by "\\".
std::string pmatrix_on_each(const Answer& a, const std::string& unit) {
  const auto& v = a.value;
  const std::size_t cols = v.shape == Value::Shape::vector ? 1 : v.cols;
  std::string s = "\\begin{pmatrix} ";
  for (std::size_t i = 0; i < v.data.size(); ++i) {
    if (i > 0) s += i % cols == 0 ? " \\\\ " : " & ";
    s += v.data[i] == 0.0 ? "0" : fmt::format("{:.12g}", v.data[i]) + unit;
  }
  return s + " \\end{pmatrix}";
}

TEST_CASE("a unit after each number of a vector or matrix reads back, every answer") {
  const auto with_units = [](const Answer& a) {
    return a.value.shape != Value::Shape::scalar && !a.unit.empty() &&
           std::any_of(a.value.data.begin(), a.value.data.end(), [](double x) { return x != 0; });
  };
  const int forms = forms_judged([&](const Answer& a) {
    std::vector<std::string> texts;
    if (!with_units(a)) return texts;
    texts.push_back(unit_on_each(a, ", "));
    // In LaTeX, each unit as a LaTeX key sets it ("\,\mathrm{kg\,m^{2}}"): in parentheses
    // and in a pmatrix's cells.
    if (a.value.shape == Value::Shape::vector)
      texts.push_back(unit_on_each(a, ", ", 1.0, detail::unit_latex(a.unit)));
    texts.push_back(pmatrix_on_each(a, detail::unit_latex(a.unit)));
    if (a.unit == "rad" &&
        a.value.shape == Value::Shape::vector) {  // angles in degrees, the sign glued on, rows
                                                  // spaced: "[40° 30° 70°]"
      texts.push_back(unit_on_each(a, ", ", M_PI / 180, "°"));
      texts.push_back("[" + unit_on_each(a, " ", M_PI / 180, "°").substr(1));
      // And in LaTeX: "(40^\circ, 30^\circ, 70^\circ)", a pmatrix's cells (rows as "\\").
      texts.push_back(unit_on_each(a, ", ", M_PI / 180, "^\\circ"));
      std::string cells = unit_on_each(a, " \\\\ ", M_PI / 180, "^\\circ");
      texts.push_back("\\begin{pmatrix} " + cells.substr(1, cells.size() - 2) + " \\end{pmatrix}");
    }
    return texts;
  });
  REQUIRE(forms > 50);  // every vector and matrix with a unit (about 35 today), angles 4 more
  // Each number is read with its own unit: one of them off is wrong.
  const Fixture euler("euler-angles");
  REQUIRE(euler.check("angles_phy711", "(40°, 30°, 70°)").correct);
  REQUIRE(euler.check("angles_phy711", "(40°, 0.5235987756 rad, 70°)").correct);
  REQUIRE_FALSE(euler.check("angles_phy711", "(40°, 30°, 71°)").correct);
  REQUIRE_FALSE(euler.check("angles_phy711", "(40°, 30 rad, 70°)").correct);
  // One unit after the whole is still the whole's.
  REQUIRE(euler.check("angles_phy711", "40, 30, 70 deg").correct);
  // Some numbers with a unit, some without; units of different kinds: said so.
  REQUIRE_THAT(error_of(euler, "angles_phy711", "(40°, 30, 70°)"),
               Catch::Equals("--answer: the entry \"30\" has no unit where another has deg: give "
                             "each number its unit (a zero may go without), or one unit after "
                             "the whole"));
  REQUIRE_THAT(error_of(euler, "angles_phy711", "(φ, θ deg, ψ)"),
               Catch::Contains("an expression in the problem's symbols, in SI already"));
  // Degrees among the symbols are radians: (φ, 30°, ψ) reads, and is right where θ is 30° only.
  const auto thirty = euler.check("angles_phy711", "(φ, 30°, ψ)");
  REQUIRE_FALSE(thirty.correct);
  REQUIRE_THAT(thirty.feedback.at(0),
               Catch::Equals("it gives the key's value at the set values but not at others: "
                             "30° is the value of θ (theta): write the symbol"));
  REQUIRE_THAT(error_of(euler, "angles_phy711", "(40°, 30 kg, 70°)"),
               Catch::Contains("units deg and kg measure different things"));
  // An expression may carry its SI unit too, as a whole expression may; in LaTeX likewise. The
  // unit is held to the answer's dimension, and one not SI is refused: the expression is in SI.
  const std::string body_rate =
      "(-(φ̇ cos(ψ) sin(θ) - θ̇ sin(ψ)) rad/s, φ̇ sin(ψ) sin(θ) + "
      "θ̇ cos(ψ) rad/s, φ̇ cos(θ) + ψ̇ rad/s)";
  REQUIRE(euler.check("omega_body", body_rate).correct);
  REQUIRE_FALSE(euler
                    .check("omega_body",
                           "(-(φ̇ cos(ψ) sin(θ) - θ̇ sin(ψ)) rad/s, φ̇ sin(ψ) "
                           "sin(θ) - θ̇ cos(ψ) rad/s, φ̇ cos(θ) + ψ̇ rad/s)")
                    .correct);
  REQUIRE(euler
              .check("omega_body",
                     "\\begin{pmatrix} \\dot\\theta \\sin\\psi - \\dot\\phi \\cos\\psi "
                     "\\sin\\theta\\,\\mathrm{rad/s} \\\\ \\dot\\phi \\sin\\psi \\sin\\theta + "
                     "\\dot\\theta\\cos\\psi\\,\\mathrm{rad/s} \\\\ \\dot\\phi\\cos\\theta + "
                     "\\dot\\psi\\,\\mathrm{rad/s} \\end{pmatrix}")
              .correct);
  REQUIRE_FALSE(
      euler.check("omega_body", "(0.1278261671 J, 1.110702692 J, 11.73205081 J)").correct);
  REQUIRE_THAT(error_of(euler, "omega_body", "(φ̇ rpm, 1.110702692 rad/s, 11.73205081 rad/s)"),
               Catch::Equals("--answer: the entry \"phidot rpm\" is an expression in the problem's "
                             "symbols, in SI already; drop its unit 'rpm'"));
  REQUIRE_THAT(error_of(euler, "omega_body", "(φ̇, 1.110702692 rad/s, 11.73205081 rad/s)"),
               Catch::Contains("an expression in the symbols is in SI; write its SI unit after "
                               "it too, or give the numbers in SI without units"));
}

TEST_CASE("a unit's powers written negative or without a caret read back, every answer") {
  const int forms = forms_judged([](const Answer& a) {
    std::vector<std::string> texts;
    std::vector<std::string> units = negative_power_forms(a.unit);
    // Powers without a caret, "kg m2/s": a PDF key's "kg m²/s" as it pastes.
    if (std::string bare = a.unit; bare.find('^') != std::string::npos) {
      bare.erase(std::remove(bare.begin(), bare.end(), '^'), bare.end());
      units.push_back(bare);
    }
    // In brackets, as the worksheet's prompt writes it ("I0 [kg m²] =") and tables head columns.
    if (!a.unit.empty()) {
      units.insert(units.end(),
                   {"[" + sym::to_unicode(a.unit) + "]", "[" + a.unit + "]", "(" + a.unit + ")"});
    }
    for (const auto& unit : units)
      texts.push_back(detail::value_text(a.value, "        ") + " " + unit);
    return texts;
  });
  // rad/s, kg m^2/s, 1/s, rad/s^2, m/s^2 (53 answers today), kg m^2 without a caret, and every
  // unit in either bracket
  REQUIRE(forms >= 3 * 50 + 30 + 3 * 80);
  // And the power's sign is read: s^-1 is not s^1.
  const Fixture top("heavy-top");
  const double w3 = top.answer("omega3_min").value.data[0];
  REQUIRE_FALSE(top.check("omega3_min", fmt::format("{:.10g} s", w3)).correct);
  REQUIRE(top.check("omega3_min", fmt::format("{:.10g} s⁻¹", w3)).correct);
  // Typed without × or ·: the letter x for times, a dot between the units.
  const double p_phi = top.answer("p_phi").value.data[0];
  REQUIRE(top.check("p_phi", fmt::format("{:.6g}x10^-2 kg.m^2/s", p_phi * 100)).correct);
  REQUIRE_FALSE(top.check("p_phi", fmt::format("{:.6g}x10^-3 kg.m^2/s", p_phi * 100)).correct);
}

TEST_CASE("the terminal's notation and a student's variants of it read as wobble's form") {
  const std::vector<std::pair<std::string, std::string>> cases{
      {"(2.588, 0, 19.32)", "[2.588, 0, 19.32]"},
      {"[2.588 0 19.32]", "[2.588, 0, 19.32]"},
      {"(0, 0, 9.66) rad/s", "[0, 0, 9.66] rad/s"},
      {"0.00072 kg m²", "0.00072 kg m^2"},
      {"15°", "15 deg"},
      {"α", "alpha"},
      {"m·R²/4", "m*R^2/4"},
      {"7.2*10^-4", "7.2*10^(-4)"},
      {"7.2×10⁻⁴", "7.2*10^(-4)"},
      {"7.2x10^-4", "7.2*10^(-4)"},
      {"m*R**2/4", "m*R^2/4"},
      {"¼·m·R²", "(1/4)*m*R^2"},
      {"$m*R^2/4$", "m*R^2/4"},
      {"$$ [1, 2, 3] $$", "[1, 2, 3]"},
      {"$$", ""},
      {"$", "$"},
      {"½ m", "(1/2) m"},
      {"ω·√(3·cos²(α) + 1)", "omega*sqrt(3*cos(alpha)^2 + 1)"},
      {"sin^2 (theta)+cos^(3)(2*(a+b))", "sin(theta)^2+cos(2*(a+b))^3"},
      {"cos^2(cos^2(x))", "cos(cos(x)^2)^2"},
      {"cos^-1(x)", "cos^(-1)(x)"},
      {"arccos^2(x)", "arccos^2(x)"},
      {"7.2 X 10^-4 rad", "7.2*10^(-4) rad"},
      {"[1 x 10^2, 0, 2]", "[1*10^2, 0, 2]"},
      {"0.08 kg.m^2/s", "0.08 kg.m^2/s"},
      {"[10 0 0; 0 6 1; 0 1 6]", "[[10, 0, 0], [0, 6, 1], [0, 1, 6]]"},
      {"10 0 0; 0 6 1; 0 1 6 kg m^2", "[[10, 0, 0], [0, 6, 1], [0, 1, 6]] kg m^2"},
      {"[1, 0, 0; 0, 1, 0; 0, 0, 1;]", "[[1, 0, 0], [0, 1, 0], [0, 0, 1]]"},
      {"[5; 7; 10]", "[5, 7, 10]"},
      {"{{10, 0, 0}, {0, 6, 1}, {0, 1, 6}}", "[[10, 0, 0], [0, 6, 1], [0, 1, 6]]"},
      {"{5, 7, 10} kg m^2", "[5, 7, 10] kg m^2"},
      {"5, 7, 10", "[5, 7, 10]"},
      {"ω·√(3·cos(α)² + 1)/2", "omega*sqrt(3*cos(alpha)^2 + 1)/2"},
      {"√2/2", "sqrt(2)/2"},
      {"θ̇0", "thetadot0"},
      {"φ̇", "phidot"},
      {"I₁", "I1"},
      {"−4.83", "-4.83"},
      {"[ 10 0 0 ]\n  [  0 6 1 ]\n  [  0 1 6 ] kg m²", "[[10, 0, 0], [0, 6, 1], [0, 1, 6]] kg m^2"},
      {"[[1 0 0] [0 1 0] [0 0 1]]", "[[1, 0, 0], [0, 1, 0], [0, 0, 1]]"},
      {"[1 - 2 0 m * a]", "[1 - 2, 0, m * a]"},
      {"[0.7 0 -0.7]", "[0.7, 0, -0.7]"},
      {"π/6", "pi/6"},
      {"m·R²÷4", "m*R^2/4"},
      {"1⁄4 m", "1/4 m"},
      // A line's closing ';' (MATLAB's) and a sentence's full stop are no part of it.
      {"0.00072;", "0.00072"},
      {"[1 0; 0 1];", "[[1, 0], [0, 1]]"},
      {"0.00072 kg m².", "0.00072 kg m^2"},
      {"0.333...", "0.333..."},
  };
  for (const auto& [typed, form] : cases) {
    INFO(typed);
    REQUIRE(reading_form(typed) == form);
  }
}

TEST_CASE("messages speak to a student: no parser jargon, the symbols that exist") {
  const Fixture plate("flying-plate");
  const auto message = [&](const std::string& text) { return error_of(plate, "I0", text); };
  for (const std::string bad : {"(m+R, 2", "m*R^2)", "2 m R (", "m*R^^2", "[1, 2"}) {
    INFO(bad);
    const std::string m = message(bad);
    REQUIRE_THAT(m, !Catch::Contains("expected") && !Catch::Contains("got:") &&
                        !Catch::Contains("line 0") && Catch::StartsWith("--answer"));
  }
  // Factors side by side, as LaTeX sets them and a student writes them, read as a product
  // (a '*' for each space between two factors); where that does not read either, the answer
  // with its '*' written in, to paste.
  const Fixture top("heavy-top");
  const auto top_message = [&](const std::string& text) { return error_of(top, "p_psi", text); };
  REQUIRE(top.check("p_psi", "M R^2 psidot0/2").correct);
  REQUIRE(top.check("p_psi", "1/2 M R^2 ψ̇0").correct);
  REQUIRE_FALSE(top.check("p_psi", "M R^2 (psidot0 + 1)/2").correct);
  REQUIRE_THAT(top_message("1 2 M R^2 psidot0"),
               Catch::Contains("products need '*' (1*2*M*R^2*psidot0, not"));
  // Where the stars would not make it read either, what is wrong is named instead.
  REQUIRE_THAT(top_message("M R^2 (psidot0 + 1/2"), Catch::Contains("a '(' is not closed"));
  REQUIRE_THAT(top_message("M R^2 psidot0/2 + q"), Catch::Contains("undefined symbol 'q'"));
  // A power of a power reads two ways; zero to the power zero is no number.
  REQUIRE_THAT(top_message("M R^2^1 psidot0/2"),
               Catch::EndsWith("a power of a power needs brackets, (a^b)^c, or its exponent "
                               "worked out"));
  REQUIRE(top.check("p_psi", "M (R^2)^1 psidot0/2").correct);
  REQUIRE_THAT(top_message("0^0 M R^2 psidot0/2"),
               Catch::EndsWith("it raises zero to the power zero"));
  // A function's one-factor argument without parentheses, as books write it; not with a power,
  // which books read two ways.
  REQUIRE(top.check("energy_prime", "M l g cos θ0").correct);
  REQUIRE(top.check("energy_prime", "M g l cos(theta0)").correct);
  REQUIRE_THAT(error_of(top, "energy_prime", "M l g cos θ0^2"),
               Catch::Contains("products need '*' and a function's argument parentheses"));
  // A symbol that also spells a unit (g, gram) is a factor after an expression in the symbols,
  // which is in SI already; after a plain number it is the unit.
  REQUIRE_FALSE(top.check("energy_prime", "M g").correct);
  const Fixture plate_m("flying-plate");
  REQUIRE(plate_m.check("I0", "m R R/4").correct);
  REQUIRE(plate_m.check("I0", "0.00072 kg m^2").correct);
  // A vector's components, commas between them, may be products side by side too.
  REQUIRE(plate_m.check("L0_body", "[m R^2 ω sin(α)/4, 0, m R^2 ω cos(α)/2]").correct);
  REQUIRE(plate_m.check("L0_body", "(m R^2 ω sin α/4, 0, m R^2 ω cos α/2)").correct);
  // Side by side with a unit: an expression is in SI, so its SI unit may follow, as the key's
  // value line shows it, and is held to the answer's dimension; any other unit is refused as
  // such, not for a missing '*'.
  REQUIRE(plate_m.check("I0", "m R^2/4 kg m^2").correct);
  REQUIRE(plate_m.check("angle_L_e3", "atan(tan(α)/2) rad").correct);
  REQUIRE(plate_m.check("Omega_body", "[0, 0, ω·cos(α)] rad/s").correct);
  const auto wrong_unit = plate_m.check("I0", "m R^2/4 rad/s");
  REQUIRE_FALSE(wrong_unit.correct);
  REQUIRE_THAT(wrong_unit.line, Catch::Contains("wrong dimension"));
  REQUIRE_FALSE(plate_m.check("angle_L_e3", "2*atan(tan(α)/2) rad").correct);
  REQUIRE_THAT(error_of(plate_m, "I0", "m R^2/4 g cm^2"),
               Catch::Contains("in SI already; drop the unit 'g cm^2'"));
  REQUIRE_THAT(error_of(plate_m, "angle_L_e3", "atan(tan(α)/2) deg"),
               Catch::Contains("in SI already; drop the unit 'deg'"));
  // Two numbers side by side are never a product: "1 4" is no 4.
  REQUIRE_THAT(error_of(plate_m, "I0", "m R^2 1 4"), Catch::Contains("products need '*'"));
  // A subscript written as LaTeX does, psidot_0 for psidot0, is the problem's symbol.
  REQUIRE(top.check("p_psi", "M*R^2*psidot_0/2").correct);
  // Factors run together are their product; a symbol in the other case is told what was
  // probably meant, alone or run together.
  REQUIRE(top.check("p_psi", "MR^2*psidot0/2").correct);
  REQUIRE_THAT(error_of(top, "p_psi", "m*R^2*psidot0/2"), Catch::Contains("case-sensitive: M?"));
  REQUIRE_THAT(error_of(top, "p_psi", "mR^2*psidot0/2"), Catch::Contains("case-sensitive: M*R?"));
  REQUIRE(top.check("p_psi", "½·M·R²·ψ̇0").correct);
  // LaTeX is read as LaTeX sets it: factors side by side, the symbol as the file spells it.
  REQUIRE(top.check("p_psi", "\\frac{M R^2 \\dot\\psi_0}{2}").correct);
  REQUIRE_THAT(
      error_of(top, "p_psi", "\\frac{M R^2 \\dot\\phi_1}{2}"),
      Catch::StartsWith("--answer: \\dot \\phi_{1} is not one of this problem's symbols ("));
  REQUIRE_FALSE(top.check("p_psi", "M*R^2*psidot_0/3").correct);
  REQUIRE_THAT(top_message("M*R^2*psidot_1/2"), Catch::Contains("undefined symbol 'psidot_1'"));
  // An undefined symbol names the ones that exist, with their letters.
  REQUIRE_THAT(message("w*R"), Catch::Contains("undefined symbol 'w'") &&
                                   Catch::Contains("omega (ω)") && Catch::Contains("alpha (α)"));
}

TEST_CASE("Hz, rev/s and rpm on an angular rate count turns: 1 Hz = 2π rad/s, every rate") {
  int rates = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        if (a.unit != "rad/s" && a.unit != "1/s") continue;
        if (a.value.shape != Value::Shape::scalar || a.value.data[0] == 0.0) continue;
        const double w = a.value.data[0];
        INFO(p.id << " " << a.name << " = " << w << " " << a.unit);
        REQUIRE(f.check(a.name, fmt::format("{:.10g} Hz", w / (2 * M_PI))).correct);
        REQUIRE(f.check(a.name, fmt::format("{:.10g} rev/s", w / (2 * M_PI))).correct);
        REQUIRE(f.check(a.name, fmt::format("{:.10g} rpm", w * 60 / (2 * M_PI))).correct);
        // rad/s and 1/s are one unit (a radian is a pure number).
        REQUIRE(f.check(a.name, fmt::format("{:.10g} rad/s", w)).correct);
        REQUIRE(f.check(a.name, fmt::format("{:.10g} 1/s", w)).correct);
        // The number in rad/s labelled Hz: wrong, and said why.
        const Verdict v = f.check(a.name, fmt::format("{:.10g} Hz", w));
        REQUIRE_FALSE(v.correct);
        REQUIRE_THAT(v.feedback.at(0), Catch::Contains("1 Hz = 2π rad/s"));
        ++rates;
      }
    }
  }
  REQUIRE(rates >= 15);  // the catalog has 16 nonzero scalar rates
  // A rate in Hz (turns per second) to the digits a student would quote.
  const Fixture plate("flying-plate");
  REQUIRE(plate.check("Omega_body_rate", "1.5373 Hz").correct);
  REQUIRE_FALSE(plate.check("Omega_body_rate", "9.659 Hz").correct);
  // An angle unit where the key is a pure number that is no angle: the wrong dimension.
  const Fixture top("asymmetric-top");
  const Verdict k = top.check("k2", fmt::format("{} deg", top.answer("k2").value.data[0]));
  REQUIRE_FALSE(k.correct);
  REQUIRE_THAT(k.line, Catch::Contains("wrong dimension"));
}

TEST_CASE("a signed rate given as its size: the sign is named, with what it means") {
  const Fixture rect("rect-solid");
  const double rate = rect.answer("Omega_body_rate").value.data[0];
  REQUIRE(rate < 0);  // a prolate solid precesses against the spin
  const Verdict v = rect.check("Omega_body_rate", fmt::format("{:.3g}", -rate));
  REQUIRE_FALSE(v.correct);
  REQUIRE_THAT(v.feedback.at(0), Catch::Contains("the size is right but not the sign") &&
                                     Catch::Contains("against the spin"));
  const Fixture plate("flying-plate");
  const double up = plate.answer("Omega_body_rate").value.data[0];
  REQUIRE_THAT(plate.check("Omega_body_rate", fmt::format("{:.4g}", -up)).feedback.at(0),
               Catch::Contains("with the spin"));
}

TEST_CASE("asymmetric tops: the key holds the modulus k the question asks for, k^2 = k2") {
  for (const std::string id : {"asymmetric-top", "tennis-racket"}) {
    const Fixture f(id);
    const double k = f.answer("k").value.data[0], k2 = f.answer("k2").value.data[0];
    INFO(id);
    // k is sqrt(k2) evaluated once from the exact form: within an ulp or two of the sqrt.
    REQUIRE_THAT(k, Catch::Matchers::WithinULP(std::sqrt(k2), 2));
    REQUIRE(f.check("k", fmt::format("{:.6g}", k)).correct);
  }
}

namespace {
// Every principal-axes answer in the catalog, as a 3x3 row-major list whose columns are axes.
std::vector<double> turned(const std::vector<double>& m, const std::array<int, 3>& order,
                           const std::array<double, 3>& scale, bool transpose) {
  std::vector<double> out(9);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      const auto src = static_cast<std::size_t>(3 * r + order[static_cast<std::size_t>(c)]);
      const double x = m[src] * scale[static_cast<std::size_t>(c)];
      out[static_cast<std::size_t>(transpose ? 3 * c + r : 3 * r + c)] = x;
    }
  }
  return out;
}
std::string matrix_text(const std::vector<double>& m) {
  return fmt::format(
      "[[{:.12g}, {:.12g}, {:.12g}], [{:.12g}, {:.12g}, {:.12g}], [{:.12g}, "
      "{:.12g}, {:.12g}]]",
      m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8]);
}
}  // namespace

TEST_CASE("principal axes by meaning: rows or columns, any order, any length, each up to sign") {
  int seen = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        if (a.name.rfind("principal_axes", 0) != 0) continue;
        for (const bool transpose : {false, true}) {
          const auto m = turned(a.value.data, {2, 0, 1}, {-3.0, 0.5, 7.0}, transpose);
          INFO(p.id << " " << a.name << " " << matrix_text(m));
          REQUIRE(f.check(a.name, matrix_text(m)).correct);
        }
        ++seen;
      }
    }
  }
  REQUIRE(seen >= 6);
  // What is wrong, in words. four-masses: e1 = (1, 1, 0)/√2, e2 = z, e3 = (1, −1, 0)/√2.
  const Fixture four("four-masses");
  const Verdict rows = four.check("principal_axes", "[0, 0, 1], [1, 1, 0], [1, -1, 0]");
  REQUIRE(rows.correct);
  REQUIRE_THAT(rows.line, Catch::Contains("each of your vectors an axis"));
  // Not unit vectors: right as directions, and the verdict says the key's are unit.
  REQUIRE_THAT(rows.line, Catch::Contains("up to sign and length; the key's axes are unit"));
  const Verdict unit_rows = four.check("principal_axes", "[0, 0, 1], [1, 1, 0]/√2, [1, -1, 0]/√2");
  REQUIRE(unit_rows.correct);
  REQUIRE_THAT(unit_rows.line, Catch::EndsWith("each up to sign)"));
  const Verdict columns = four.check("principal_axes", "[[0, 1, 1], [0, 1, -1], [5, 0, 0]]");
  REQUIRE(columns.correct);
  REQUIRE_THAT(columns.line, Catch::Contains("as columns"));
  const Verdict not_axis = four.check("principal_axes", "[[1, 0, 1], [0, 0, -1], [0, 1, 0]]");
  REQUIRE_FALSE(not_axis.correct);
  REQUIRE_THAT(not_axis.feedback.at(0),
               Catch::Contains("is not a principal axis") && Catch::Contains("45°"));
  const Verdict twice = four.check("principal_axes", "[0, 0, 1], [1, 1, 0], [2, 2, 0]");
  REQUIRE_FALSE(twice.correct);
  REQUIRE_THAT(twice.feedback.at(0), Catch::Contains("same axis") && Catch::Contains("missing"));
}

namespace {
std::string tensor_problem(const std::string& id, const std::string& tensor) {
  return wobble::test::write_file("read_back/" + id + ".toml", "id = \"" + id + R"TOML("
title = "t"
solver = "inertia"
statement = "s"

[[parameters]]
name = "k"
unit = "kg m^2"
default = 1
range = "(0, inf)"

[body]
tensor = )TOML" + tensor + R"TOML(

[[parts]]
id = "a"
question = "q"
answers = ["principal_moments", "principal_axes"]
)TOML")
      .string();
}
}  // namespace

TEST_CASE("degenerate or not is the key's own decision, whatever the tolerance") {
  // A turn by 45 degrees in the x-y plane: principal only when the x-y moments are equal.
  const std::string turned45 = "[[1, 1, 0], [1, -1, 0], [0, 0, 1]]";
  const Fixture exact(
      tensor_problem("pair-exact", R"([["2*k", "0", "0"], ["0", "2*k", "0"], ["0", "0", "3*k"]])"));
  REQUIRE(exact.check("principal_axes", turned45).correct);
  for (const std::string gap : {"1e-12", "1e-9"}) {
    const Fixture near(tensor_problem("pair-" + gap, "[[\"2*k\", \"0\", \"0\"], [\"0\", \"2*k*(1+" +
                                                         gap +
                                                         ")\", \"0\"], [\"0\", \"0\", \"3*k\"]]"));
    for (const double tolerance : {1e-9, 1e-2}) {
      INFO("gap " << gap << ", tolerance " << tolerance);
      Options o;
      o.rel_tol = tolerance;
      o.rel_tol_given = true;
      const Verdict v = near.check("principal_axes", turned45, o);
      REQUIRE_FALSE(v.correct);
      REQUIRE_THAT(v.feedback.at(0), Catch::Contains("not a principal axis"));
    }
  }
}

TEST_CASE("a period the key's note gives in days reads back in days, and in years; arcseconds") {
  const Fixture earth("earth-free-precession");
  const Answer& T = earth.answer("precession_period_body");
  // The note, as printed: "303.6241743 days; ...": its number with the unit as written.
  const std::string note = T.notes.at(0);
  const std::string days = note.substr(0, note.find(';'));
  REQUIRE_THAT(days, Catch::EndsWith(" days"));
  INFO(days);
  REQUIRE(earth.check("precession_period_body", days).correct);
  REQUIRE(earth.check("precession_period_body", "1 day").correct == false);
  // The Chandler period (433 days, in the problem's notes) is not Euler's: it is judged wrong.
  REQUIRE_FALSE(earth.check("precession_period_body", "433 days").correct);
  // In years, and the angle of L from the figure axis in seconds of arc, as astronomers give
  // them: converted from the key's values, the same number in the wrong unit judged wrong.
  const double years = T.value.data[0] / (365.25 * 86400);
  REQUIRE(earth.check("precession_period_body", fmt::format("{:.6g} yr", years)).correct);
  REQUIRE(earth.check("precession_period_body", fmt::format("{:.6g} years", years)).correct);
  const double angle = earth.answer("angle_L_e3").value.data[0];
  const std::string arcsec = fmt::format("{:.6g}", angle * 180 / M_PI * 3600);
  REQUIRE(earth.check("angle_L_e3", arcsec + " arcsec").correct);
  REQUIRE(earth.check("angle_L_e3", arcsec + "arcsec").correct);
  REQUIRE(earth.check("angle_L_e3", arcsec + "″").correct);  // the double prime
  REQUIRE_FALSE(earth.check("angle_L_e3", arcsec + "′").correct);
  REQUIRE_FALSE(earth.check("angle_L_e3", arcsec + " arcmin").correct);
}

TEST_CASE("every answer a key prints as none at these values reads back as right, every problem") {
  // The first variants of the catalog: the heavy top's slow ones have no steady precession.
  // Each key's line for such an answer, in the text key, the Markdown key and the LaTeX key's
  // page (its text as a PDF viewer copies it), judged as `check` and a submission read a line.
  constexpr long kVariants = 12;
  int lines = 0;
  for (const auto& p : load_catalog()) {
    for (long n = 1; n <= kVariants; ++n) {
      const Key key = solve(p, parameter_values(p, variant_for(p, n)));
      const std::string text = render_text(key), markdown = render_markdown(key),
                        latex = render_latex(key);
      for (const auto& part : key.parts) {
        for (std::size_t i = 0; i < part.absent.size(); ++i) {
          const std::string& name = part.absent[i];
          const std::string said = detail::absent_answer_text(part, i);
          INFO(p.id << " variant " << n << ": " << name << " " << said);
          CHECK_THAT(said, Catch::Matches("none at these values \\(step [0-9]+ says why\\)"));
          std::string escaped = name;
          for (std::size_t at = escaped.find('_'); at != std::string::npos;
               at = escaped.find('_', at + 2))
            escaped.replace(at, 1, "\\_");
          const std::string text_line = "    " + name + " = " + said + "\n",
                            markdown_line = "**`" + name + "`** = " + said + "\n",
                            latex_line = "{\\small\\texttt{" + escaped + "}}: " + said + "\n";
          CHECK_THAT(text, Catch::Contains(text_line));
          CHECK_THAT(markdown, Catch::Contains(markdown_line));
          CHECK_THAT(latex, Catch::Contains(latex_line));
          for (const std::string& line : {text_line, markdown_line, name + ": " + said}) {
            INFO(line);
            const auto read = answer_line(line);
            REQUIRE(read);
            const auto v = judge_absent(key, "", read->name, read->answer, true);
            REQUIRE(v);
            CHECK(v->correct);
            ++lines;
          }
        }
      }
    }
  }
  CHECK(lines > 0);
}
