// What a terminal and a Markdown page show: no LaTeX or Markdown syntax in text, tables that
// stay tables, parameters shown as given.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cctype>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "problem/values.hpp"
#include "render/common.hpp"
#include "render/handout.hpp"
#include "render/prose.hpp"
#include "render/render.hpp"
#include "render/simulation_output.hpp"
#include "solvers/catalog.hpp"
#include "solvers/solve.hpp"
#include "symbolic/plain_text.hpp"

using namespace wobble;

TEST_CASE("LaTeX math as terminal text") {
  const std::vector<std::pair<std::string, std::string>> cases{
      {"\\omega(\\sin\\alpha\\, x + \\cos\\alpha\\, z)", "ω(sin α x + cos α z)"},
      {"a \\times a \\times a\\sqrt{3}", "a × a × a√3"},
      {"d(\\cos(\\alpha/2), \\pm\\sin(\\alpha/2), 0)", "d(cos(α/2), ±sin(α/2), 0)"},
      {"V_{body} = R(\\alpha, \\beta, \\gamma)\\, V_{inertial}", "V_body = R(α, β, γ) V_inertial"},
      {"\\dot\\theta(0) = \\dot\\theta_0", "θ̇(0) = θ̇₀"},
      {"I_1 < I_2 < I_3", "I₁ < I₂ < I₃"},
      {"\\frac{m R^2}{4}", "(m R²)/4"},
      {"\\sqrt{a^2 + b^2}", "√(a² + b²)"},
      {"e_2'", "e₂'"},
      {"\\mathbf{1} - r r^T", "1 - r rᵀ"},
      {"\\unknowncommand{x}", "unknowncommandx"},
      // A function or a text word after a letter or digit stays a word of its own.
      {"\\frac{A}{C}\\tan\\alpha", "A/C tan α"},
      {"2\\sin\\theta + x\\mathrm{d}t", "2 sin θ + x dt"},
  };
  for (const auto& [latex, text] : cases) {
    INFO(latex);
    REQUIRE(math_to_unicode(latex) == text);
  }
  REQUIRE(plain_text("the scene `heavy-top`, **bold** and $\\alpha$ \\| a bar") ==
          "the scene heavy-top, bold and α | a bar");
}

namespace {
// LaTeX or Markdown syntax that must never reach a terminal.
void require_plain(const std::string& text) {
  for (const std::string leak : {"\\", "$", "`", "{", "}", "**"}) {
    INFO("leak: " << leak);
    REQUIRE(text.find(leak) == std::string::npos);
  }
}
}  // namespace

TEST_CASE("every text key and worksheet introduction is plain text") {
  int keys = 0;
  for (const auto& p : load_catalog()) {
    const Key key = solve(p, parameter_values(p, {}));
    INFO(p.id);
    // The statement and the parameter line: the part above the first question. Answers are
    // GiNaC text in Unicode, whose vectors use brackets, not braces.
    const std::string text = render_text(key);
    require_plain(text.substr(0, text.find("\n(a)")));
    require_plain(render_handout_text(key, {}, 7, true));
    // Each question line of the key: its math in Unicode, as the statement's.
    for (std::size_t at = text.find("\n("); at != std::string::npos;
         at = text.find("\n(", at + 1)) {
      const std::string line = text.substr(at + 1, text.find('\n', at + 1) - at - 1);
      INFO(line);
      require_plain(line);
    }
    ++keys;
  }
  REQUIRE(keys >= 13);
}

TEST_CASE("a question's math is set as the statement's: Unicode in text, LaTeX math on a page") {
  const Problem& top = find_problem("heavy-top");
  const Key key = solve(top, parameter_values(top, {}));
  const std::string b = "the nutation limits ";
  REQUIRE_THAT(render_text(key), Catch::Contains(b + "θ_min and θ_max") &&
                                     Catch::Contains("(where φ̇ = 0)") &&
                                     Catch::Contains("find the spin ω₃"));
  REQUIRE_THAT(render_handout_latex(key, {}, std::nullopt),
               Catch::Contains(b + "$\\theta_\\mathrm{min}$ and $\\theta_\\mathrm{max}$") &&
                   Catch::Contains("(where $\\dot\\phi = 0$)"));
  REQUIRE_THAT(render_markdown(key), Catch::Contains(b + "$\\theta_\\mathrm{min}$"));
}

TEST_CASE("Markdown tables keep their columns; angles are shown in degrees as given") {
  for (const auto& p : load_catalog()) {
    const Key key = solve(p, parameter_values(p, {}));
    for (const std::string& md : {render_markdown(key), render_handout(key, {}, std::nullopt)}) {
      std::size_t pos = md.find("| Parameter |");
      REQUIRE(pos != std::string::npos);
      // Every row of the table: five unescaped bars.
      for (std::size_t line = pos; line < md.size() && md[line] == '|';) {
        const std::size_t end = md.find('\n', line);
        const std::string row = md.substr(line, end - line);
        int bars = 0;
        for (std::size_t i = 0; i < row.size(); ++i) {
          bars += row[i] == '|' && (i == 0 || row[i - 1] != '\\');
        }
        INFO(p.id << ": " << row);
        REQUIRE(bars == 5);
        line = end + 1;
      }
    }
  }
  const Problem plate = find_problem("flying-plate");
  const Key key = solve(plate, parameter_values(plate, {}));
  REQUIRE_THAT(render_text(key), Catch::Contains("α = 15° = 0.2617993878 rad"));
  // A parameter's description takes math as a statement does: Markdown and LaTeX keep it, the
  // terminal prints it in Unicode. \lvert, not |, so a table's bars stay the table's.
  REQUIRE_THAT(render_markdown(key), Catch::Contains("| spin rate $\\lvert\\omega(0)\\rvert$ |"));
  REQUIRE_THAT(render_handout_text(key, {}, 7, true), Catch::Contains("   (spin rate |ω(0)|)"));
  REQUIRE_THAT(render_handout_latex(key, {}, 7),
               Catch::Contains("& angle between $\\omega(0)$ and the symmetry axis \\\\"));
}

TEST_CASE("a handout's values name a parameter as typed and, where it differs, as printed") {
  // The asymmetric top's w1 is \omega_1: its statement says ω₁, so the values say both.
  const Problem top = find_problem("asymmetric-top");
  const std::string asymmetric =
      render_handout_text(solve(top, parameter_values(top, {})), {}, std::nullopt, false);
  REQUIRE_THAT(asymmetric,
               Catch::Contains("  w1 (ω₁) = 0.3 rad/s") && Catch::Contains("  I1      = 2 kg m²"));
  // The heavy top's theta0 is \theta_0, which reads as theta0 too: one name.
  const Problem heavy = find_problem("heavy-top");
  const std::string heavy_text =
      render_handout_text(solve(heavy, parameter_values(heavy, {})), {}, std::nullopt, false);
  REQUIRE_THAT(heavy_text, Catch::Contains("  θ0 = 30°") && !Catch::Contains("θ0 ("));
}

TEST_CASE("prose on a LaTeX page sets names as the formulas beside it do") {
  detail::ProseNames names;
  names.parameter_latex = {{"alpha", "\\alpha"}, {"a", "a"}, {"theta0", "\\theta_0"}};
  names.answers = {"k2", "angles_zxz", "period"};
  const std::vector<std::pair<std::string, std::string>> cases{
      // wobble's ASCII ω, indexed letters, a derivative in d/dt.
      {"dw1/dt = c1 w2 w3",
       "$\\mathrm{d}\\omega_{1}/\\mathrm{d}t$ = $c_{1}$ $\\omega_{2}$ $\\omega_{3}$"},
      {"s = |w(0)| about e3, I1 < I2", "$s$ = |$\\omega$(0)| about $e_{3}$, $I_{1}$ < $I_{2}$"},
      // A lone letter is a variable, in italic; not the article a, a unit after a number or a
      // unit's '/', a possessive's s, a hyphenated axis, a part's label or a derivative's d.
      {"at t = 0, z = 2 s, in rad/s, Euler's, z-y-z, part (b), K(k), d²w1/dt², c2 d",
       "at $t$ = 0, $z$ = 2 s, in rad/s, Euler's, z-y-z, part (b), $K$($k$), "
       "d$^2$$\\omega_{1}$/dt$^2$, "
       "$c_{2}$ $d$"},
      // Subscripted names, in ASCII or with a Greek letter (as the text key prints them).
      {"Ω_space / ω = 1.003", "$\\Omega_{\\mathrm{space}}$ / $\\omega$ = 1.003"},
      {"Ω_i Ω_j > 0: w_i, w_j", "$\\Omega_{i}$ $\\Omega_{j}$ > 0: $\\omega_{i}$, $\\omega_{j}$"},
      {"(p_φ − p_ψ u)", "($p_{\\phi}$ $-$ $p_{\\psi}$ $u$)"},
      // Parameters by their LaTeX; a one-letter parameter is also the article "a".
      {"d2 sin alpha at theta0, a top", "$d_{2}$ sin $\\alpha$ at $\\theta_0$, a top"},
      // An answer's name as `check --name` takes it; one that is a word stays a word.
      {"k² is k2 below; see angles_zxz; the period",
       "$k$$^2$ is \\texttt{k2} below; see \\texttt{angles\\_zxz}; the period"},
      // A turned axis keeps its prime in math; a negative number has a minus, not a hyphen.
      {"e2' = (0, 1, 0), off by -0.03%", "$e_{2}'$ = (0, 1, 0), off by $-$0.03\\%"},
      // What is not a name stays: words, z-y-z, e-notation, the dotted Greek.
      {"z-y-z, 4.4e-16, θ̇0 = 0, 2pi",
       "z-y-z, 4.4$\\times 10^{-16}$, $\\dot{\\theta}_{0}$ = 0, 2pi"},
  };
  for (const auto& [prose, latex] : cases) {
    INFO(prose);
    REQUIRE(detail::latex_text(prose, names) == latex);
  }
}

TEST_CASE("an answer's name on a LaTeX key is the symbol books write for it") {
  const std::vector<std::pair<std::string, std::optional<std::string>>> cases{
      {"Omega_body", "\\Omega_{\\mathrm{body}}"},
      {"L0_space", "L_{0,\\mathrm{space}}"},
      {"p_phi", "p_{\\phi}"},
      // A vector's size between bars, a rate at t = 0 with its dot (dω/dt at t = 0).
      {"L_magnitude", "\\lvert L\\rvert"},
      {"dw_dt0", "\\dot{\\omega}(0)"},
      {"dw_dt", "\\dot{\\omega}"},
      // Words stay words: no symbol.
      {"principal_axes", std::nullopt},
      {"energy_magnitude", std::nullopt},
      {"max_angle", std::nullopt},
  };
  for (const auto& [name, latex] : cases) {
    INFO(name);
    REQUIRE(detail::name_latex(name) == latex);
  }
  // A heading's symbol: also a letter and its index, not a square's name (k2 is k²).
  for (const auto& [name, latex] : std::vector<std::pair<std::string, std::optional<std::string>>>{
           {"I0", "I_0"},
           {"omega3", "\\omega_3"},
           {"I", "I"},
           {"k", "k"},
           {"k2", std::nullopt},
           {"kc2", std::nullopt},
           {"energy", std::nullopt},
           {"lagrangian0", std::nullopt},
           {"Omega_body", "\\Omega_{\\mathrm{body}}"}}) {
    INFO(name);
    REQUIRE(detail::answer_symbol_latex(name) == latex);
  }
  const Problem racket = find_problem("tennis-racket");
  const std::string tex = render_latex(solve(racket, parameter_values(racket, {})));
  REQUIRE_THAT(tex, Catch::Contains("$\\lvert L\\rvert$\\quad{\\small\\texttt{L\\_magnitude}}") &&
                        Catch::Contains("$\\dot{\\omega}(0)$\\quad{\\small\\texttt{dw\\_dt0}}"));
}

TEST_CASE("a LaTeX key's step without a label has its formula beside its number") {
  // A centred display right after \item sets the number in the middle of the line, beside the
  // formula: no step of the catalog's keys starts so.
  for (const auto& problem : load_catalog()) {
    INFO(problem.id);
    const std::string tex = render_latex(solve(problem, parameter_values(problem, {})));
    REQUIRE_THAT(tex, !Catch::Contains("\\item \\fit{") && !Catch::Contains("\\item \\fitor{"));
  }
  const Problem box = find_problem("box-corner");
  Key key = solve(box, parameter_values(box, {}));
  REQUIRE_THAT(render_latex(key),
               Catch::Contains("\\item \\fitbeside{I = \\operatorname{tr}(S)\\,\\mathbf{1} - S}"));
  // A vector or matrix is a display of its own, on the line below its number.
  key.parts.front().steps.push_back(
      Step{"R = [[1, 0], [0, 1]]", "R = \\begin{pmatrix} 1 & 0 \\\\ 0 & 1 \\end{pmatrix}", ""});
  REQUIRE_THAT(render_latex(key), Catch::Contains("\\item \\leavevmode\\fitor{R = "));
}

TEST_CASE("a shape's step names its size as the problem does, not twice") {
  // "M = M, a = a" said nothing where the problem's names are the shape's: a name alone, and
  // "= value" where they differ (the square plate's b = a).
  const Problem box = find_problem("box-corner"), square = find_problem("flying-square-plate");
  const Key box_key = solve(box, parameter_values(box, {}));
  const Key square_key = solve(square, parameter_values(square, {}));
  REQUIRE(box_key.parts.front().steps.front().latex.rfind("M,\\quad a,\\quad b,\\quad c,", 0) == 0);
  REQUIRE(square_key.parts.front().steps.front().latex.rfind("M = m,\\quad a,\\quad b = a,", 0) ==
          0);
  REQUIRE_THAT(box_key.parts.front().steps.front().label,
               Catch::StartsWith("A uniform box with its edges along x, y, z;"));
}

namespace {
// The text of a LaTeX page outside math ($..$, \fit{..}, \fitor{..}{..}) and typewriter type.
std::string latex_prose(const std::string& tex) {
  std::string out;
  const auto skip_group = [&](std::size_t open) {  // index after the group opening at `open`
    int depth = 0;
    for (std::size_t k = open; k < tex.size(); ++k) {
      if (tex[k] == '\\') {
        ++k;
      } else if (tex[k] == '{') {
        ++depth;
      } else if (tex[k] == '}' && --depth == 0) {
        return k + 1;
      }
    }
    return tex.size();
  };
  for (std::size_t i = tex.find("\\begin{document}"); i < tex.size();) {
    if (tex[i] == '$') {
      const auto close = tex.find('$', i + 1);
      i = close == std::string::npos ? tex.size() : close + 1;
    } else if (tex.compare(i, 5, "\\fit{") == 0 || tex.compare(i, 11, "\\fitbeside{") == 0 ||
               tex.compare(i, 8, "\\texttt{") == 0 ||
               tex.compare(i, 16, "\\includegraphics") == 0) {
      i = skip_group(tex.find('{', i));
    } else if (tex.compare(i, 7, "\\fitor{") == 0) {
      i = skip_group(skip_group(tex.find('{', i)));
    } else {
      out += tex[i++];
    }
  }
  return out;
}
}  // namespace

TEST_CASE("prose in a terminal or Markdown key names things as its questions print them") {
  detail::ProseNames names;
  names.parameter_latex = {{"alpha", "\\alpha"}, {"a", "a"}, {"theta0", "\\theta_0"}};
  names.answers = {"k2", "angles_zxz", "period"};
  using detail::AnswerNameStyle;
  const std::vector<std::pair<std::string, std::string>> cases{
      {"dw1/dt = c1 w2 w3", "dω₁/dt = c₁ ω₂ ω₃"},
      {"s = |w(0)| about e3, I1 < I2", "s = |ω(0)| about e₃, I₁ < I₂"},
      {"Ω2 Ω3 > 0: w_i, w_j grow", "Ω₂ Ω₃ > 0: ω_i, ω_j grow"},
      {"Omega_space / w = 1.003, (p_phi − p_ψ u)", "Ω_space / ω = 1.003, (p_φ − p_ψ u)"},
      {"d2 sin alpha at theta0, a top", "d₂ sin α at θ₀, a top"},
      {"e2' = (0, 1, 0), off by -0.03%", "e₂' = (0, 1, 0), off by -0.03%"},
      {"z-y-z, 4.4e-16, θ̇0 = 0, 2pi, 2TI3, L0_space",
       "z-y-z, 4.4e-16, θ̇₀ = 0, 2pi, 2TI3, L0_space"},
      {"k² is k2 below; see angles_zxz; the period", "k² is k2 below; see angles_zxz; the period"},
  };
  for (const auto& [prose, text] : cases) {
    INFO(prose);
    REQUIRE(detail::unicode_text(prose, names, AnswerNameStyle::plain) == text);
  }
  // Markdown shows an answer's name in prose as its heading does: as code.
  REQUIRE(detail::unicode_text("k² is k2 below; see angles_zxz; the period", names,
                               AnswerNameStyle::code) ==
          "k² is `k2` below; see `angles_zxz`; the period");
}

namespace {
// The words of `prose` that are one ASCII letter and digits ("I1", "w2"), a "w_" name ("w_i") or
// a time derivative in ASCII ("dw1"): names a key sets as its formulas do. An answer's name
// (`answers`) is shown as typed; a word glued to a digit before it ("2TI3") is a product.
std::vector<std::string> bare_names(const std::string& prose,
                                    const std::vector<std::string>& answers) {
  std::vector<std::string> bare;
  const auto at = [&](std::size_t k) { return static_cast<unsigned char>(prose[k]); };
  for (std::size_t i = 0; i < prose.size(); ++i) {
    if (!std::isalpha(at(i)) ||
        (i > 0 && (std::isalnum(at(i - 1)) || prose[i - 1] == '\\' || prose[i - 1] == '_'))) {
      continue;
    }
    std::size_t j = i;
    while (j < prose.size() && (std::isalnum(at(j)) || prose[j] == '_')) ++j;
    const std::string word = prose.substr(i, j - i);
    const bool letter_digits =
        word.size() >= 2 && std::all_of(word.begin() + 1, word.end(), [](char c) {
          return std::isdigit(static_cast<unsigned char>(c));
        });
    const bool derivative = word.size() >= 3 && word[0] == 'd' && word[1] == 'w' &&
                            std::isdigit(static_cast<unsigned char>(word[2]));
    if ((letter_digits || derivative || word.compare(0, 2, "w_") == 0) &&
        std::find(answers.begin(), answers.end(), word) == answers.end()) {
      bare.push_back(word);
    }
  }
  return bare;
}

// The prose lines of a terminal key: its notes, steps and conventions.
std::string text_prose(const std::string& text) {
  std::string prose;
  std::size_t at = 0;
  for (std::size_t end; (end = text.find('\n', at)) != std::string::npos; at = end + 1) {
    const std::string line = text.substr(at, end - at);
    const bool step = line.size() > 4 && line.compare(0, 3, "   ") == 0 &&
                      std::isdigit(static_cast<unsigned char>(line[3]));
    if (line.compare(0, 12, "      note: ") == 0 || line.compare(0, 4, "  - ") == 0 || step) {
      prose += line + "\n";
    }
  }
  return prose;
}

// The prose of a Markdown key outside math ($..$, $$..$$) and code (`..`): its quoted notes,
// numbered steps and listed conventions.
std::string markdown_prose(const std::string& md) {
  std::string prose;
  std::size_t at = 0;
  for (std::size_t end; (end = md.find('\n', at)) != std::string::npos; at = end + 1) {
    const std::string line = md.substr(at, end - at);
    const bool step = !line.empty() && std::isdigit(static_cast<unsigned char>(line[0]));
    if (line.compare(0, 2, "> ") != 0 && line.compare(0, 2, "- ") != 0 && !step) continue;
    for (std::size_t i = 0; i < line.size();) {
      if (line[i] == '$' || line[i] == '`') {
        const auto close = line.find(line[i], i + 1);
        i = close == std::string::npos ? line.size() : close + 1;
      } else {
        prose += line[i++];
      }
    }
    prose += "\n";
  }
  return prose;
}
}  // namespace

TEST_CASE("every terminal and Markdown key's prose has no bare index, as its questions have none") {
  int keys = 0;
  for (const auto& p : load_catalog()) {
    const Key key = solve(p, parameter_values(p, {}));
    std::vector<std::string> answers;
    for (const auto& part : key.parts) {
      for (const auto& a : part.answers) answers.push_back(a.name);
    }
    INFO(p.id);
    const std::string text = text_prose(render_text(key));
    const std::string markdown = markdown_prose(render_markdown(key));
    REQUIRE(text.find("note: ") != std::string::npos);
    INFO(text);
    REQUIRE(bare_names(text, answers).empty());
    INFO(markdown);
    // Markdown shows an answer's name as code, so no name is left in its prose.
    REQUIRE(bare_names(markdown, {}).empty());
    ++keys;
  }
  REQUIRE(keys >= 15);
}

TEST_CASE("every LaTeX key's prose has no raw name: no escaped underscore, no bare index") {
  int keys = 0;
  for (const auto& p : load_catalog()) {
    const std::string tex = render_latex(solve(p, parameter_values(p, {})));
    const std::string prose = latex_prose(tex);
    INFO(p.id);
    // wobble's ASCII ω in a name ("w_i") is ω on a page, as "w1" is.
    REQUIRE(tex.find("$w_{") == std::string::npos);
    // "Omega\_space", "p\_phi": a name the page shows as typed outside typewriter type.
    const auto underscore = prose.find("\\_");
    INFO(prose.substr(
        underscore == std::string::npos ? 0 : underscore - std::min<std::size_t>(underscore, 40),
        80));
    REQUIRE(underscore == std::string::npos);
    // "I1", "w2", "e3": one letter and digits, which the formulas set as I₁, ω₂, e₃.
    const auto bare = bare_names(prose, {});
    INFO((bare.empty() ? "" : bare.front()));
    REQUIRE(bare.empty());
    ++keys;
  }
  REQUIRE(keys >= 15);
}

TEST_CASE("a measured time is printed to three figures in the unit it reaches") {
  // Rounded before the unit is chosen: just under a millisecond is 1 ms, not "1e+03 us".
  const auto cost_line = [](double simulation_time_s) {
    CrossCheck c;
    c.method = "Fehlberg 7(8)";
    c.rhs_evals = 52000;
    c.simulation_time_s = simulation_time_s;
    const std::string text = cross_check_text(c, 0.5);
    return text.substr(text.find("cost of the simulation"));
  };
  for (const auto& [t, printed] :
       std::vector<std::pair<double, std::string>>{{0.0009996, "1 ms"},
                                                   {0.000999, "999 us"},
                                                   {0.0123456, "12.3 ms"},
                                                   {0.9996, "1 s"},
                                                   {999.6, "1000 s"},
                                                   {12345.0, "12300 s"}}) {
    INFO(t);
    REQUIRE(cost_line(t) == "cost of the simulation: 52000 right-hand-side evaluations, " +
                                printed + " (Fehlberg 7(8))\n");
  }
}
