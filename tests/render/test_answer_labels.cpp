// What a question shows beside an answer's name. Its unit: where the key's unit would tell the
// answer (the asymmetric top's growth rate is in 1/s, its frequencies in rad/s, and the question
// asks which axis is unstable), every surface that asks shows the units it may be in, and the
// judge takes each of them. Its form: how a vector or a matrix is typed, the same words on the
// handout, in the worksheet and on the page.
#include <algorithm>
#include <catch2/catch.hpp>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "check/check_fixture.hpp"
#include "check/worksheet.hpp"
#include "render/handout.hpp"
#include "solvers/catalog.hpp"
#include "solvers/quantity_table.hpp"
#include "symbolic/unicode_notation.hpp"

using namespace wobble;
using Catch::Matchers::Contains;
using Fixture = wobble::test::CheckFixture;

namespace {
// The problems that ask which principal axis is stable, and the unit they show for the rates.
const std::vector<std::string> kStabilityProblems{"asymmetric-top", "tennis-racket"};
const std::string kRateUnits = "rad/s or 1/s";
const std::vector<std::string> kRates{"rate_axis1", "rate_axis2", "rate_axis3"};
}  // namespace

TEST_CASE("the stable and unstable axes' rates are in two units, asked in the same words") {
  for (const auto& id : kStabilityProblems) {
    INFO(id);
    const Fixture f(id);
    std::set<std::string> units, asked;
    for (const auto& name : kRates) {
      units.insert(f.answer(name).unit);
      asked.insert(asked_unit(f.answer(name)));
    }
    // The keys differ (so a label in the key's unit would tell which axis is unstable) ..
    REQUIRE(units == std::set<std::string>{"rad/s", "1/s"});
    // .. and the question's words do not.
    REQUIRE(asked == std::set<std::string>{kRateUnits});
  }
}

TEST_CASE("the handout, its Markdown and the worksheet's prompts show a rate's units as asked") {
  for (const auto& id : kStabilityProblems) {
    INFO(id);
    const Fixture f(id);
    const std::string text = render_handout_text(f.key, {}, std::nullopt, true);
    const std::string markdown = render_handout(f.key, {}, std::nullopt);
    for (const auto& name : kRates) {
      CHECK_THAT(text, Contains(name + " [" + kRateUnits + "]"));
      CHECK_THAT(markdown, Contains("`" + name + "` [" + kRateUnits + "]"));
    }
    CHECK_THAT(text + markdown, !Contains("[1/s]"));
    std::vector<std::string> prompts;
    // '!' at every prompt: each answer revealed in turn, and the next one asked.
    const check::ReadLine reveal_all = [&](const std::string& prompt, std::string& line) {
      prompts.push_back(prompt);
      line = "!";
      return prompts.size() < 100;
    };
    std::ostringstream out;
    (void)check::run_worksheet(reveal_all, out, "", f.problem, {f.key, f.table, f.values}, {});
    for (const auto& name : kRates) {
      INFO(name);
      CHECK(std::count(prompts.begin(), prompts.end(), "  " + name + " [" + kRateUnits + "] = ") ==
            1);
    }
  }
}

TEST_CASE(
    "every answer's unit is among those asked, and each asked reads back right, every "
    "problem") {
  int alternatives_read = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        INFO(p.id << " " << a.name << " asked in '" << asked_unit(a) << "'");
        REQUIRE(registered_unit(asked_unit(a), a.unit));
        const auto units = unit_alternatives(asked_unit(a));
        if (units.size() < 2 || a.value.shape != Value::Shape::scalar) continue;
        for (const auto& unit : units) {
          const std::string typed = format_number(a.value.data[0]) + " " + unit;
          INFO(typed);
          CHECK(f.check(a.name, typed).correct);
          ++alternatives_read;
        }
      }
    }
  }
  // Two units for each of three rates in two problems.
  REQUIRE(alternatives_read >= 12);
}

TEST_CASE("the judge's words on a rate's unit are the same for a stable and an unstable axis") {
  const Fixture f("asymmetric-top");
  for (const auto& name : kRates) {
    INFO(name);
    const auto v = f.check(name, format_number(f.answer(name).value.data[0]) + " s");
    REQUIRE_FALSE(v.correct);
    REQUIRE(v.feedback.size() >= 2);
    CHECK(v.feedback[0] == "you gave s (time); the answer is in " + kRateUnits + " (1 / time)");
    CHECK(v.feedback[1] == "in " + kRateUnits + " the number would be right");
  }
  // The growth rate given for a frequency, in its own unit: the other axis's answer, named.
  const Answer& growth = f.answer("rate_axis2");
  REQUIRE(growth.unit == "1/s");
  const auto v = f.check("rate_axis1", format_number(growth.value.data[0]) + " 1/s");
  REQUIRE_FALSE(v.correct);
  REQUIRE(v.feedback.size() == 1);
  CHECK(v.feedback[0] == "this is rate_axis2 (part b), not rate_axis1");
}

TEST_CASE("an answer's form names the entries as its question does, or the frame's axes") {
  const Fixture racket("tennis-racket"), plate("flying-plate"), box("box-corner");
  CHECK(answer_form(racket.answer("Omega_axis1")) == "a vector [Ω₂, Ω₃]");
  CHECK(answer_form(racket.answer("Omega_axis2")) == "a vector [Ω₃, Ω₁]");
  CHECK(answer_form(racket.answer("euler_coefficients")) == "a vector [c₁, c₂, c₃]");
  CHECK(answer_form(racket.answer("dw_dt0")) == "a vector [.., .., ..] along e₁, e₂, e₃");
  CHECK(answer_form(plate.answer("L0_space")) == "a vector [x, y, z]");
  CHECK(answer_form(plate.answer("I")) == "a matrix [[..], [..], [..]]");
  CHECK(answer_form(box.answer("principal_moments_corner")) ==
        "three moments [.., .., ..], in any order");
  CHECK(answer_form(plate.answer("I0")).empty());
}

TEST_CASE(
    "every vector and matrix answer's form is on the handout and above its worksheet "
    "prompt, every problem") {
  int forms = 0;
  for (const auto& p : load_catalog()) {
    INFO(p.id);
    const Fixture f(p.id);
    const std::string text = render_handout_text(f.key, {}, std::nullopt, true);
    const std::string markdown = render_handout(f.key, {}, std::nullopt);
    // Each prompt, with what the worksheet had printed before it.
    std::vector<std::pair<std::string, std::string>> prompts;
    std::ostringstream out;
    const check::ReadLine reveal_all = [&](const std::string& prompt, std::string& line) {
      prompts.emplace_back(prompt, out.str());
      line = "!";
      return prompts.size() < 200;
    };
    (void)check::run_worksheet(reveal_all, out, "", f.problem, {f.key, f.table, f.values}, {});
    std::size_t asked = 0;
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        INFO(a.name);
        REQUIRE(asked < prompts.size());
        const auto& [prompt, before] = prompts[asked++];
        REQUIRE(prompt.rfind("  " + a.name + " ", 0) == 0);
        const std::string unit = asked_unit(a).empty() ? "" : " [" + asked_unit(a) + "]";
        const std::string form = answer_form(a);
        // Scalars have none; every vector and matrix has one.
        REQUIRE(form.empty() ==
                (a.value.shape == Value::Shape::scalar && a.kind != AnswerKind::principal_moments));
        if (form.empty()) continue;
        CHECK_THAT(text, Contains(a.name + sym::to_unicode(unit) + " (" + form + ")"));
        CHECK_THAT(markdown,
                   Contains("`" + a.name + "`" + sym::to_unicode(unit) + " (" + form + ")"));
        // The line just above the answer's first prompt.
        CHECK_THAT(before, Catch::EndsWith("  (" + form + ")\n"));
        ++forms;
      }
    }
  }
  REQUIRE(forms > 30);
}
