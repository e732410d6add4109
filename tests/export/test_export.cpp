// The exports' gradable variants: what is listed, what refuses a variant, what no variant lists;
// and the text of a problem as a learning system's HTML.
#include <algorithm>
#include <catch2/catch.hpp>

#include "export/graded_variants.hpp"
#include "export/html_text.hpp"
#include "export/message_numbers.hpp"
#include "export/moodle.hpp"
#include "export/prairielearn.hpp"
#include "problem/values.hpp"
#include "solvers/catalog.hpp"
#include "solvers/solve.hpp"
#include "symbolic/units.hpp"

using namespace wobble;
using Catch::Matchers::Contains;

TEST_CASE("every listed mistake is what the judge names for its value, and is judged wrong") {
  const Problem p = find_problem("heavy-top");
  const auto set = exports::graded_variants(p, 1, 10, check::Options{});
  REQUIRE(set.variants.size() == 10);
  const sym::SymbolTable table = p.symbol_table();
  std::size_t listed = 0;
  for (const auto& v : set.variants) {
    const sym::Values values = parameter_values(p, variant_for(p, v.number));
    for (const auto& g : v.answers) {
      for (const auto& m : g.mistakes) {
        const auto verdict = check::judge({v.key, table, values}, g.answer,
                                          exports::answer_text(g.answer, m.values), {});
        INFO("variant " << v.number << " " << g.answer.name << ": " << m.mistake);
        CHECK_FALSE(verdict.correct);
        REQUIRE(verdict.feedback.size() == 1);
        CHECK(verdict.feedback[0] == m.message);
        ++listed;
      }
    }
  }
  CHECK(listed > 100);
}

TEST_CASE("a variant whose mistake lies within the tolerance is drawn again, and says why") {
  // Heavy-top variants 1-50 (drawn in the order of their numbers): variant 21's Lagrangian is
  // within 1% of its energy, and variant 1 is too slow a top to precess steadily.
  const Problem p = find_problem("heavy-top");
  const auto set = exports::graded_variants(p, 1, 20, check::Options{});
  const auto refused = [&](long n) {
    return std::find_if(set.rejected.begin(), set.rejected.end(),
                        [&](const exports::Rejection& r) { return r.number == n; });
  };
  REQUIRE(refused(21) != set.rejected.end());
  CHECK_THAT(refused(21)->reason, Contains("lagrangian0 (part a): another answer of the key") &&
                                      Contains("which the judge accepts (tolerance 1%)"));
  REQUIRE(refused(1) != set.rejected.end());
  CHECK_THAT(refused(1)->reason, Contains("phidot_slow (part d) does not exist"));
  for (const auto& v : set.variants) CHECK(refused(v.number) == set.rejected.end());
  // With a tolerance of 0.1% the Lagrangian is told from the energy.
  check::Options strict;
  strict.rel_tol = 0.001;
  strict.rel_tol_given = true;
  const auto tight = exports::graded_variants(p, 21, 1, strict);
  CHECK(tight.variants.front().number == 21);
}

TEST_CASE("a mistake within the tolerance in every variant is listed in none") {
  // Near the separatrix k and k^2 are both 1 to six digits: no number tells them apart.
  const Problem p = find_problem("tennis-racket");
  const auto set = exports::graded_variants(p, 1, 5, check::Options{});
  REQUIRE(set.variants.size() == 5);
  REQUIRE(set.untold.size() == 2);
  CHECK_THAT(set.untold[0].kind, Contains("k (part c): another answer of the key"));
  // Probed in the first 20 draws, however few are asked for.
  CHECK(set.untold[0].within == 20);
  CHECK(set.untold[0].drawn == 20);
  for (const auto& v : set.variants) {
    for (const auto& g : v.answers) {
      if (g.answer.name != "k") continue;
      for (const auto& m : g.mistakes) CHECK_THAT(m.message, !Contains("this is k2"));
    }
  }
}

TEST_CASE("a mistake equal to the key is no mistake: the frames coincide at t = 0") {
  // rect-solid's L0_body and L0_space are equal at t = 0, and the products of inertia of a
  // diagonal tensor are zero: neither is listed, and no variant is refused for it.
  const Problem p = find_problem("rect-solid");
  const auto set = exports::graded_variants(p, 1, 5, check::Options{});
  CHECK(set.rejected.empty());
  int checked = 0;
  for (const auto& g : set.variants.front().answers) {
    for (const auto& m : g.mistakes) {
      INFO(g.answer.name << ": " << m.message);
      if (g.answer.name == "L0_body" || g.answer.name == "L0_space") {
        // Neither is the other's mistake (another answer may be: "this is Omega_space (part
        // e), not L0_body", the spin's components pasted for the momentum's).
        CHECK_THAT(m.message, !Contains("this is L0_body") && !Contains("this is L0_space"));
        ++checked;
      }
      CHECK(m.mistake != "products of inertia with the wrong sign");
    }
  }
  CHECK(checked > 0);
}

TEST_CASE("a statement as HTML: math for the system's MathJax, code, escapes, paragraphs") {
  CHECK(exports::statement_html("A $\\theta_0 < 1$ tilt, `heavy-top` & more.\n\nNext", "\\(",
                                "\\)") ==
        "<p>A \\(\\theta_0 &lt; 1\\) tilt, <code>heavy-top</code> &amp; more.</p>\n<p>Next</p>\n");
  CHECK(exports::unit_html("kg m^2/s") == "kg m²/s");
  // A part's question, one line: the same, without the paragraph.
  CHECK(exports::inline_html("the limits $\\theta_\\mathrm{min}$ & $\\theta_\\mathrm{max}$", "$",
                             "$") ==
        "the limits $\\theta_\\mathrm{min}$ &amp; $\\theta_\\mathrm{max}$");
}

TEST_CASE("a problem's double braces never reach PrairieLearn's Mustache as a tag") {
  CHECK(exports::mustache_safe("$\\frac{1}{{2}}$ {{{x}}} {a}") ==
        "$\\frac{1}{&#123;2}}$ {&#123;{x}}} {a}");
  // The template's own tags are all the "{{" a question.html has, whatever the problem says.
  const auto tags = [](Problem p) {
    const auto set = exports::graded_variants(p, 1, 2, check::Options{});
    for (const auto& f : exports::prairielearn_question(p, set, check::Options{})) {
      if (f.path != "question.html") continue;
      std::size_t n = 0;
      for (auto at = f.content.find("{{"); at != std::string::npos;
           at = f.content.find("{{", at + 2))
        ++n;
      return n;
    }
    return std::size_t{0};
  };
  Problem plate = find_problem("flying-plate");
  const std::size_t template_tags = tags(plate);
  REQUIRE(template_tags > 0);
  plate.statement += " $\\frac{1}{{2}}$";
  plate.parts.at(0).question += " $x^{{2}}$";
  plate.parts.at(0).hint += " $y_{{1}}$";
  CHECK(tags(plate) == template_tags);
}

TEST_CASE("Moodle and PrairieLearn ask for a rate in both units where its unit would tell it") {
  // The asymmetric top's growth rate is in 1/s, its frequencies in rad/s; the question asks which
  // axis is unstable, so each rate is asked for "in rad/s or 1/s".
  const Problem p = find_problem("asymmetric-top");
  const auto set = exports::graded_variants(p, 1, 2, check::Options{});
  const std::string xml = exports::moodle_quiz(p, set, check::Options{}).xml;
  std::string html;
  for (const auto& f : exports::prairielearn_question(p, set, check::Options{})) {
    if (f.path == "question.html") html = f.content;
  }
  REQUIRE_FALSE(html.empty());
  for (const std::string name : {"rate_axis1", "rate_axis2", "rate_axis3"}) {
    INFO(name);
    CHECK_THAT(xml, Contains("Give <code>" + name + "</code> in rad/s or 1/s."));
    CHECK_THAT(html, Contains("label=\"<code>" + name + "</code> =\" suffix=\"rad/s or 1/s\""));
  }
  CHECK_THAT(xml, !Contains("</code> in 1/s."));
  CHECK_THAT(html, !Contains("suffix=\"1/s\""));
}

TEST_CASE("a message's numbers apart from its words, names' digits kept as words") {
  using Split = std::pair<std::string, std::vector<std::string>>;
  for (const auto& [message, numbers] : std::vector<Split>{
           {"this is the fast-top approximation M g l / (I3 ω3), 16.2% below", {"16.2"}},
           {"1/0.3333 = 3 rad/s is the answer", {"1", "0.3333", "3"}},
           {"2π/(2.395e-07 rad/s) = 2.623e+07 s", {"2", "2.395e-07", "2.623e+07"}},
           {"this is rate_axis2 (part b), not rate_axis1", {}},
           {"entry (1, 2) is off by 12%", {"1", "2", "12"}},
           {"-308 times the answer; 1e+10 times; 2e a word", {"308", "1e+10", "2"}},
           {"θ0 = 90°: the axle is horizontal", {"90"}},
           {"10⁻⁷ kg m², 1 g cm²", {"10", "1"}},
           {"1/1.001 = 0.9985 1/s is the answer, 1/day", {"1", "1.001", "0.9985"}}}) {
    INFO(message);
    const exports::MessageNumbers split = exports::message_numbers(message);
    CHECK(split.numbers == numbers);
    REQUIRE(split.words.size() == split.numbers.size() + 1);
    CHECK(exports::with_numbers(split, split.numbers) == message);
  }
  CHECK(exports::message_numbers("-308 times").words.front() == "-");
}

TEST_CASE("Moodle: a mistake whose line differs between variants only in numbers is one answer") {
  // The fast-top approximation is 13.8% below the slow rate in one variant, 10.3% in another:
  // one answer, its percentage a wildcard Moodle puts in, not an answer per variant.
  const Problem p = find_problem("heavy-top");
  const auto set = exports::graded_variants(p, 1, 20, check::Options{});
  const std::string said = "this is the fast-top approximation M g l / (I3 ω3), ";
  std::vector<std::string> lines;
  for (const auto& v : set.variants) {
    for (const auto& g : v.answers) {
      for (const auto& m : g.mistakes) {
        if (g.answer.name == "phidot_slow" && m.message.rfind(said, 0) == 0 &&
            std::find(lines.begin(), lines.end(), m.message) == lines.end())
          lines.push_back(m.message);
      }
    }
  }
  REQUIRE(lines.size() > 1);
  const std::string xml = exports::moodle_quiz(p, set, check::Options{}).xml;
  const std::string question = xml.substr(xml.find("heavy-top (d) phidot_slow"));
  const std::string feedback = "<feedback format=\"html\"><text><![CDATA[incorrect: " + said;
  const std::size_t first = question.find(feedback);
  REQUIRE(first != std::string::npos);
  CHECK(question.find(feedback, first + 1) > question.find("</question>"));
  CHECK(question.compare(first + feedback.size(), 2, "{m") == 0);
}

TEST_CASE("a mistake within the tolerance in nearly all variants refuses none, listed elsewhere") {
  // Near an axis the asymmetric top's small-oscillation period is its exact period within 1% in
  // most variants, not in all: refusing those would refuse most draws (the export of 100
  // stopped, 42 of 1000 gradable). None is refused for it; where told apart it is listed.
  const Problem p = find_problem("asymmetric-top");
  const auto set = exports::graded_variants(p, 1, 100, check::Options{});
  REQUIRE(set.variants.size() == 100);
  const auto period = std::find_if(set.untold.begin(), set.untold.end(), [](const auto& u) {
    return u.kind.rfind("period (part c): another answer of the key", 0) == 0;
  });
  REQUIRE(period != set.untold.end());
  CHECK(period->drawn == 100);
  CHECK(4 * period->within > 3 * period->drawn);
  CHECK(period->within < period->drawn);
  long listed = 0;
  for (const auto& v : set.variants) {
    for (const auto& g : v.answers) {
      for (const auto& m : g.mistakes)
        listed += g.answer.name == "period" && m.message.rfind("this is period_small", 0) == 0;
    }
  }
  CHECK(listed == period->drawn - period->within);  // the first draws are the variants here
  for (const auto& r : set.rejected) CHECK(r.kind != period->kind);
}

TEST_CASE("a refusal's kind is the same in every variant: its numbers are elided") {
  // The heavy top's slow rate is within 1% of its fast-top approximation in variants 29 (0.85%)
  // and 72 (0.547%): two reasons, one kind, counted together (and by the three-quarters rule).
  const Problem p = find_problem("heavy-top");
  const auto set = exports::graded_variants(p, 1, 40, check::Options{});
  std::vector<const exports::Rejection*> approximations;
  for (const auto& r : set.rejected) {
    if (r.kind.find("an approximation for the exact answer") != std::string::npos)
      approximations.push_back(&r);
  }
  REQUIRE(approximations.size() == 2);
  CHECK(approximations[0]->kind == approximations[1]->kind);
  CHECK(approximations[0]->reason != approximations[1]->reason);
  CHECK_THAT(approximations[0]->kind, Contains("(I3 ω3), …% below the exact value here"));
  CHECK_THAT(approximations[0]->reason, Contains("(I3 ω3), 0.85% below the exact value here"));
}

TEST_CASE("a refusal's kind keeps a multiple of π: a period's 2 is no variant's number") {
  // The tennis racket's period is within 1% of 2π over another of its numbers in variant 92 (of
  // the first 100 drawn): "2π/… = … s is the answer", not "…π/…".
  const auto set = exports::graded_variants(find_problem("tennis-racket"), 1, 60, check::Options{});
  const auto reciprocal = std::find_if(set.rejected.begin(), set.rejected.end(), [](const auto& r) {
    return r.kind.find("a period for a rate") != std::string::npos;
  });
  REQUIRE(reciprocal != set.rejected.end());
  CHECK_THAT(reciprocal->kind, Contains("(\"2π/… = … s is the answer\")"));
  CHECK_THAT(reciprocal->reason, Contains("2π/") && !Contains("…"));
}
