// An answer in LaTeX math: what each construct becomes in plain text, one symbol in its several
// spellings, and the one-line refusals. (That every LaTeX form a key prints reads back as
// correct is tested over the whole catalog in render/test_read_back.cpp.)
#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "check/check_fixture.hpp"
#include "check/latex_answer.hpp"
#include "core/input_error.hpp"

using namespace wobble;
using namespace wobble::check;

namespace {
using Fixture = wobble::test::CheckFixture;

std::string text_of(const Fixture& f, const std::string& latex) {
  return latex_as_text(latex, f.table, "--answer");
}

std::string refusal(const Fixture& f, const std::string& latex) {
  try {
    return "(read as) " + text_of(f, latex);
  } catch (const InputError& e) {
    return e.what();
  }
}
}  // namespace

TEST_CASE("LaTeX is recognised by a backslash or a braced power or subscript") {
  REQUIRE(looks_like_latex("\\frac{m}{2}"));
  REQUIRE(looks_like_latex("m R^{2}/4"));
  REQUIRE(looks_like_latex("I_{1} omega"));
  REQUIRE_FALSE(looks_like_latex("m*R^2/4"));
  REQUIRE_FALSE(looks_like_latex("{{1, 0}, {0, 1}}"));  // Mathematica's lists
  REQUIRE_FALSE(looks_like_latex("psidot_0"));
}

TEST_CASE("math delimiters and Markdown's code marks around it all are taken off") {
  for (const auto& [typed, inside] : std::vector<std::pair<std::string, std::string>>{
           {"$m R^2/4$", "m R^2/4"},
           {" $$\\frac{m}{4}$$ ", "\\frac{m}{4}"},
           {"\\(m\\)", "m"},
           {"`m*R^2/4`", "m*R^2/4"},
           {"``m*R^2/4``", "m*R^2/4"},
           {"` $m R^2$ `", "m R^2"},
           // Not around it all: as typed, for the reader to refuse.
           {"`m*R^2/4", "`m*R^2/4"},
           {"`a` + `b`", "`a` + `b`"},
           {"``", "``"}}) {
    INFO(typed);
    CHECK(without_math_delimiters(typed) == inside);
  }
  CHECK(without_code_marks(" `I0 = 0.00072 kg m^2` ") == "I0 = 0.00072 kg m^2");
  CHECK(without_code_marks("$m$") == "$m$");
  const Fixture plate("flying-plate");
  REQUIRE(plate.check("I0", "`I0 = m*R^2/4`").correct);
  REQUIRE_THROWS_AS(plate.check("I0", "`m*R^2/4"), InputError);
}

TEST_CASE("LaTeX constructs become plain text with their products written out") {
  const Fixture plate("flying-plate");  // m, R, omega (\omega), alpha (\alpha)
  const auto text = [&](const std::string& latex) { return text_of(plate, latex); };
  REQUIRE(text("\\frac{m R^{2}}{4}") == "((m*R^(2))/(4))");
  REQUIRE(text("\\frac12 m R^2") == "(1/2)*m*R^2");
  REQUIRE(text("mR^2") == "m*R^2");  // in LaTeX a letter is a symbol
  REQUIRE(text("2\\omega\\cos\\alpha") == "2*omega*cos(alpha)");
  REQUIRE(text("\\sin 2\\alpha") == "sin(2*alpha)");
  REQUIRE(text("\\sin alpha") == "sin(alpha)");  // a name spelled out, whole
  REQUIRE(text("\\cos^{2}\\left(\\alpha\\right)") == "cos(alpha)^(2)");
  REQUIRE(text("\\sqrt{m}\\,R") == "sqrt(m)*R");
  REQUIRE(text("\\sqrt[3]{m}") == "((m)^(1/(3)))");
  // A digit is an argument whole, as TeX reads it: \sqrt2, \sqrt 23 (the 3 a factor after).
  REQUIRE(text("\\sqrt2") == "sqrt(2)");
  REQUIRE(text("\\sqrt 23") == "sqrt(2)*3");
  REQUIRE(text("\\frac1{\\sqrt2}") == "(1/(sqrt(2)))");
  REQUIRE(text("\\left|\\omega\\right| \\cdot R") == "abs(omega)*R");
  REQUIRE(text("|R| \\times m") == "abs(R)*m");
  REQUIRE(text("\\bigl(m + R\\bigr)\\big/ 2") == "(m+R)/2");
  REQUIRE(text("\\operatorname{atan2}\\left(\\sin\\alpha, 2\\right)") == "atan2(sin(alpha), 2)");
  REQUIRE(text("\\arctan(\\tan\\alpha)") == "atan(tan(alpha))");
  REQUIRE(text("\\ln m") == "log(m)");
  REQUIRE(text("\\pi R^2") == "Pi*R^2");
  REQUIRE(text("$$ \\frac{m}{2} $$") == "((m)/(2))");
  REQUIRE(text("\\(m\\)") == "m");
  // Numbers, the times sign before a power of ten, a unit after the value.
  REQUIRE(text("7.2 \\times 10^{-4}") == "7.2*10^(-4)");
  REQUIRE(text("0.00072\\,\\mathrm{kg\\,m^{2}}") == "0.00072 kg m^2");
  REQUIRE(text("118.8~\\text{s}^{-1}") == "118.8 s^-1");
  REQUIRE(text("0.21kg") == "0.21 kg");
  REQUIRE(text("15^\\circ") == "15 deg");
  REQUIRE(text("15^{\\circ}") == "15 deg");
  // A degree sign after each number of a vector or matrix: a unit on each entry.
  REQUIRE(text("(40^\\circ, -30^{\\circ}, 70^\\circ)") == "(40 deg, -30 deg, 70 deg)");
  REQUIRE(text("\\begin{pmatrix} 40^\\circ \\\\ 30^\\circ \\end{pmatrix}") == "[40 deg, 30 deg]");
  // A unit set in \mathrm or \text after each number of a vector or matrix, a zero without.
  REQUIRE(text("(0.5\\,\\mathrm{rad/s}, 0, -2 \\text{rad/s})") == "(0.5 rad/s, 0, -2 rad/s)");
  REQUIRE(text("\\begin{pmatrix} 9.66\\,\\mathrm{kg\\,m^{2}} & 0 \\\\ 0 & 1\\,\\mathrm{kg\\,m^{2}} "
               "\\end{pmatrix}") == "[[9.66 kg m^2, 0], [0, 1 kg m^2]]");
  REQUIRE(text("\\left(1\\ \\mathrm{rad}/\\mathrm{s},\\,2\\ \\mathrm{rad}/\\mathrm{s}\\right)") ==
          "(1 rad/s, 2 rad/s)");
  // Without \mathrm, in an entry, a letter is a symbol: "2\,m" is twice the mass.
  REQUIRE(text("(2\\,m, 3\\,m)") == "(2*m, 3*m)");
  // After an expression too (the answer reader holds it to SI), unless it names a symbol.
  REQUIRE(text("(m\\,\\mathrm{kg}, 0)") == "(m kg, 0)");
  REQUIRE(text("(R\\,\\mathrm{m}, 0)") == "(R*m, 0)");
  // Not after a product or before another factor: there it is no entry's unit.
  REQUIRE_THROWS_WITH(text("(2 \\cdot 20^\\circ, 30^\\circ)"),
                      Catch::Contains("'^\\circ' (degrees) belongs after a number"));
  REQUIRE_THROWS_WITH(text("(40^\\circ m, 30^\\circ)"),
                      Catch::Contains("'^\\circ' (degrees) belongs after a number"));
  // A product sign is no unit's start: "2 \cdot m" is twice the mass, not two metres.
  REQUIRE(text("2 \\cdot m") == "2*m");
  REQUIRE(text("0.5\\,\\mathrm{kg \\cdot m^{2}}") == "0.5 kg m^2");
  // "M g": a product where a symbol came before, never grams.
  const Fixture top("heavy-top");
  REQUIRE(text_of(top, "M g l") == "M*g*l");
  // Matrices; a column or a row is a vector, brackets around a matrix are its own.
  REQUIRE(text("\\begin{pmatrix} 1 & 0 \\\\ 0 & m \\end{pmatrix}") == "[[1, 0], [0, m]]");
  // Rows set apart, as the LaTeX key sets rows of fractions: the space is no entry.
  REQUIRE(text("\\begin{pmatrix} \\dfrac{m}{2} \\\\[2ex] 0 \\\\ [-0.5em] 1 \\end{pmatrix}") ==
          "[((m)/(2)), 0, 1]");
  REQUIRE(text("\\begin{bmatrix} 1 \\\\ 2 \\\\ 3 \\\\ \\end{bmatrix}") == "[1, 2, 3]");
  REQUIRE(text("\\left(\\begin{array}{ccc} 1 & 2 & 3 \\end{array}\\right)") == "[1, 2, 3]");
  REQUIRE(text("\\begin{pmatrix} 0.5 \\\\ 0 \\end{pmatrix}\\,\\mathrm{rad/s}") == "[0.5, 0] rad/s");
}

TEST_CASE("a symbol in any of its LaTeX spellings is the problem's symbol") {
  const Fixture top("heavy-top");  // psidot0 is \dot\psi_0, theta0 is \theta_0
  for (const std::string spelling :
       {"\\dot\\psi_0", "\\dot{\\psi}_{0}", "\\dot{\\psi_0}", "\\dot {\\psi} _ 0", "psidot0",
        "psidot_0", "\\dot\\psi_{\\mathrm{0}}"}) {
    INFO(spelling);
    REQUIRE(text_of(top, spelling) == "psidot0");
  }
  REQUIRE(text_of(top, "\\cos\\theta_0") == "cos(theta0)");
  REQUIRE(text_of(top, "\\cos\\vartheta_0") == "cos(theta0)");
  const Fixture plate("flying-plate");
  REQUIRE(text_of(plate, "omega\\alpha") == "omega*alpha");  // a name spelled out, then \alpha
}

TEST_CASE("what LaTeX reading refuses, it names in one line") {
  const Fixture plate("flying-plate");
  const auto refused = [&](const std::string& latex) { return refusal(plate, latex); };
  REQUIRE_THAT(refused("\\frac{m}{2"), Catch::Equals("--answer: '}' missing"));
  REQUIRE_THAT(refused("m}"), Catch::Equals("--answer: a '}' without its '{'"));
  REQUIRE_THAT(refused("\\pm m"), Catch::Contains("'\\pm' gives two answers"));
  REQUIRE_THAT(refused("\\int m"), Catch::StartsWith("--answer: \\int is not read"));
  REQUIRE_THAT(refused("1 & 2"), Catch::Contains("'&' outside a matrix"));
  REQUIRE_THAT(refused("1 \\\\ 2"), Catch::Contains("(a new row) outside a matrix"));
  REQUIRE_THAT(refused("\\sin^{-1}(m)"), Catch::Contains("write \\arcsin"));
  REQUIRE_THAT(refused("\\sin"), Catch::Contains("\\sin needs its argument"));
  REQUIRE_THAT(refused("\\beta m"), Catch::Equals("--answer: \\beta is not one of this "
                                                  "problem's symbols (m, R, \\omega, \\alpha)"));
  REQUIRE_THAT(refused("\\begin{pmatrix} 1 & 2 \\\\ 3 \\end{pmatrix}"),
               Catch::Contains("rows of different lengths"));
  REQUIRE_THAT(refused("\\begin{pmatrix} 1 \\end{bmatrix}"), Catch::Contains("closed by another"));
  REQUIRE_THAT(refused("\\begin{cases} 1 \\end{cases}"), Catch::Contains("is not read"));
  REQUIRE_THAT(refused("\\left\\langle m \\right\\rangle"), Catch::Contains("is not read"));
  REQUIRE_THAT(refused("\\left( m"), Catch::Contains("without its \\right"));
  REQUIRE_THAT(refused("^2"), Catch::Contains("needs something before it"));
  REQUIRE_THAT(refused("m_1"), Catch::Contains("m_{1} is not one of this problem's symbols"));
  REQUIRE_THAT(refused("\\dot{m R}"), Catch::Contains("a mark over more than one letter"));
  REQUIRE_THAT(refused("m ω"), Catch::Equals("(read as) m*omega"));  // Unicode is read too
  // Deep nesting is refused, not recursed into without end.
  REQUIRE_THAT(refused(std::string(300, '{') + "m" + std::string(300, '}')),
               Catch::Contains("nested deeper than"));
  // Nesting without a brace too: each \frac's arguments are single tokens here.
  std::string fractions;
  for (int k = 0; k < 14000; ++k) fractions += "\\frac";
  REQUIRE_THAT(refused(fractions + std::string(14001, '1')), Catch::Contains("nested deeper than"));
  // A long run of letters is read in time linear in its length (it took cubic: 20000 letters ran
  // for minutes); each letter is a symbol, R here, and the product is refused by the expression
  // reader's length limit, not here.
  REQUIRE(text_of(plate, "\\alpha " + std::string(20000, 'R')).size() == 6 + 2 * 20000 - 1);
  std::string roots;
  for (int k = 0; k < 14000; ++k) roots += "\\sqrt";
  REQUIRE_THAT(refused(roots + "m"), Catch::Contains("nested deeper than"));
}

TEST_CASE("siunitx's quantities read as the number with its unit") {
  const Fixture plate("flying-plate");  // I0 = 0.00072 kg m^2, alpha = 15 deg
  for (const std::string& same : std::vector<std::string>{
           "\\SI{7.2e-4}{\\kilo\\gram\\metre\\squared}",
           "\\qty{7.2e-4}{\\kilo\\gram\\square\\metre}", "\\SI{7.2x10^-4}{kg.m^2}",
           "\\num{7.2 x 10^{-4}}\\,\\si{kg.m^2}", "\\num{7.2d-4}", "\\num{7.2 \\cdot 10^{-4}}",
           "\\SI{7200}{\\gram\\centi\\metre\\tothe{2}}"}) {
    INFO(same);
    REQUIRE(plate.check("I0", same).correct);
  }
  REQUIRE_FALSE(plate.check("I0", "\\SI{720}{\\gram\\centi\\metre\\squared}").correct);  // a tenth
  const auto wrong_dimension =
      plate.check("I0", "\\SI{7.2e-4}{\\kilo\\gram\\metre\\squared\\per\\second}");
  REQUIRE_FALSE(wrong_dimension.correct);
  REQUIRE_THAT(wrong_dimension.line, Catch::Contains("wrong dimension"));
  // Degrees, minutes and seconds of arc, below 60 each.
  REQUIRE(plate.check("angle_omega_e3", "\\ang{14;59;59.9}").correct);
  REQUIRE(plate.check("angle_omega_e3", "\\qty{15}{\\degree}").correct);
  REQUIRE_THROWS_WITH(plate.check("angle_omega_e3", "\\ang{14;75}"), Catch::Contains("carry the"));
  // What is not read is named.
  REQUIRE_THROWS_WITH(plate.check("I0", "\\SI{7.2e-4}{\\foo}"),
                      Catch::Contains("\\foo in a siunitx unit"));
  REQUIRE_THROWS_WITH(plate.check("I0", "\\SI{7.2e-4}"), Catch::Contains("\\SI without its {..}"));
}
