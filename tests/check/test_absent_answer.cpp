// An answer that does not exist at these values (the heavy top's steady precession below the
// least spin): "none", however written, is right for it, and wrong for one that exists.
#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "check/absent_answer.hpp"
#include "check/check_fixture.hpp"
#include "check/submission.hpp"
#include "problem/values.hpp"
#include "problem/variants.hpp"
#include "solvers/catalog.hpp"
#include "solvers/solve.hpp"

using namespace wobble;
using Fixture = wobble::test::CheckFixture;

TEST_CASE("what says there is none, and what does not") {
  for (const std::string none : {"none",
                                 "None.",
                                 "NONE",
                                 "DNE",
                                 "n/a",
                                 "∅",
                                 "nothing",
                                 "undefined",
                                 "impossible",
                                 "does not exist",
                                 "Doesn’t exist",
                                 "doesn't exist!",
                                 "it does not exist",
                                 "they don't exist",
                                 "there is none",
                                 "there are none",
                                 "no solution",
                                 "no real roots",
                                 "no steady precession",
                                 "  no   steady precession ",
                                 "none: the spin is below 688 rad/s",
                                 "none (too slow)",
                                 "none, too slow",
                                 "none since ω3 < 688 rad/s",
                                 "none because the spin is too slow",
                                 "none - too slow",
                                 "none — too slow"}) {
    INFO(none);
    CHECK(check::says_none(none));
  }
  for (const std::string some :
       {"no", "yes", "0", "0 rad/s", "nonexistent", "nothingness", "none of them", "no idea", "n",
        "undefined symbol", "does", "4.76 rad/s", "phidot_slow", ""}) {
    INFO(some);
    CHECK_FALSE(check::says_none(some));
  }
}

TEST_CASE("an answer that does not exist: none is right, a number wrong, the key's reason after") {
  // 10 rad/s is far below the least spin for steady precession at 30°: part d has no answer.
  const Fixture slow("heavy-top", {"psidot0=10"});
  const PartKey& d = slow.key.parts.at(3);
  REQUIRE(d.id == "d");
  REQUIRE(d.answers.empty());
  REQUIRE(d.absent == std::vector<std::string>{"phidot_slow", "phidot_fast"});
  const std::string why = d.absent_why.at(0);
  REQUIRE_THAT(why, Catch::StartsWith("No steady precession at θ0 = "));
  // By the part, by a name (as typed or as the text key prints it), by a line's name given as
  // the part.
  const auto both = check::judge_absent(slow.key, "d", "", "none", true);
  REQUIRE(both);
  CHECK(both->correct);
  CHECK(both->line == "correct: phidot_slow, phidot_fast do not exist at these values");
  CHECK(both->feedback == std::vector<std::string>{why});
  // A graded surface (a submission, the browser's server) withholds the reason, which gives ω3.
  const auto withheld = check::judge_absent(slow.key, "d", "", "none", false);
  REQUIRE(withheld);
  CHECK(withheld->line == both->line);
  CHECK(withheld->feedback.empty());
  for (const auto& [part, name] : {std::pair{"", "phidot_slow"}, std::pair{"d", "phidot_slow"},
                                   std::pair{"phidot_slow", ""}, std::pair{"", "φ̇_slow"}}) {
    INFO(part << " / " << name);
    const auto one = check::judge_absent(slow.key, part, name, "does not exist", true);
    REQUIRE(one);
    CHECK(one->correct);
    CHECK(one->line == "correct: phidot_slow does not exist at these values");
    const auto number = check::judge_absent(slow.key, part, name, "4.76 rad/s", true);
    REQUIRE(number);
    CHECK_FALSE(number->correct);
    CHECK(number->line == "incorrect: phidot_slow does not exist at these values");
    CHECK(number->feedback == std::vector<std::string>{why});
  }
  // Answers that exist are the usual lookup's: nothing here.
  CHECK_FALSE(check::judge_absent(slow.key, "c", "", "none", true));
  CHECK_FALSE(check::judge_absent(slow.key, "", "omega3", "none", true));
  CHECK_FALSE(check::judge_absent(slow.key, "c", "phidot_slow", "none", true));  // not part c's
  CHECK_FALSE(check::judge_absent(slow.key, "", "phidot_slower", "none", true));
}

TEST_CASE("an answer that does not exist is asked for as where it exists: by name, in its unit") {
  // Every list of what to give (a handout's, check's), every prompt (the worksheet's, the
  // page's) has it: one without would tell a student that it does not exist.
  const Fixture slow("heavy-top", {"psidot0=10"});
  const Fixture fast("heavy-top", {});
  const PartKey& d = slow.key.parts.at(3);
  const PartKey& exists = fast.key.parts.at(3);
  REQUIRE(exists.answers.size() == 2);
  CHECK(d.asked_names() == exists.asked_names());
  CHECK(d.absent_unit ==
        std::vector<std::string>{asked_unit(exists.answers[0]), asked_unit(exists.answers[1])});
  CHECK_THAT(answers_by_part(slow.key), Catch::EndsWith("(d) phidot_slow, phidot_fast"));
  CHECK(answers_by_part(slow.key) == answers_by_part(fast.key));
}

TEST_CASE("a part with one answer absent: the part alone names the one that exists") {
  // A horizontal axle has the slow (gyroscopic) precession only.
  const Fixture horizontal("heavy-top", {"theta0=90deg"});
  const PartKey& d = horizontal.key.parts.at(3);
  REQUIRE(d.absent == std::vector<std::string>{"phidot_fast"});
  REQUIRE(d.answers.size() == 1);
  CHECK_FALSE(check::judge_absent(horizontal.key, "d", "", "none", true));
  const auto fast = check::judge_absent(horizontal.key, "d", "phidot_fast", "none", true);
  REQUIRE(fast);
  CHECK(fast->correct);
  const check::Verdict slow = horizontal.check("phidot_slow", "none");
  CHECK_FALSE(slow.correct);
  CHECK(slow.line == "incorrect: phidot_slow exists at these values");
  CHECK(horizontal.check("phidot_slow", "phidot_slow = there is none").line ==
        "incorrect: phidot_slow exists at these values");
}

TEST_CASE("a submission asks for an answer that does not exist as for any other") {
  const Fixture slow("heavy-top", {"psidot0=10"});
  const auto part_d = [](const check::SubmissionResult& result) {
    std::vector<std::string> lines;
    for (const auto& a : result.answers) {
      if (a.part != "d") continue;
      // Without the reason, which gives ω3 (part c's answer) away before a resubmission.
      CHECK(a.verdict.feedback.empty());
      lines.push_back(a.verdict.line);
    }
    return lines;
  };
  const check::Context ctx{slow.key, slow.table, slow.values};
  const auto given = check::judge_submission(ctx,
                                             "omega3 = 10 rad/s\n"
                                             "phidot_slow = none\n"
                                             "φ̇_fast = 12 rad/s\n",
                                             {});
  CHECK(given.problems.empty());
  CHECK(part_d(given) ==
        std::vector<std::string>{"correct: phidot_slow does not exist at these values",
                                 "incorrect: phidot_fast does not exist at these values"});
  CHECK_FALSE(given.all_correct());
  // Unanswered, it is not answered, as any other: every variant has the same answers to give.
  const auto left = check::judge_submission(ctx, "omega3 = 10 rad/s\n", {});
  CHECK(part_d(left) == std::vector<std::string>{"incorrect: phidot_slow is not answered",
                                                 "incorrect: phidot_fast is not answered"});
  // Answered twice in two spellings: the first is judged, the second reported.
  const auto twice = check::judge_submission(ctx, "phidot_slow = none\nφ̇_slow = 3 rad/s\n", {});
  CHECK(part_d(twice).at(0) == "correct: phidot_slow does not exist at these values");
  REQUIRE(twice.problems.size() == 1);
  CHECK_THAT(twice.problems[0], Catch::Contains("answers phidot_slow again"));
}

TEST_CASE(
    "over the catalog: none is wrong for every answer that exists, right for every one "
    "that does not in the first variants") {
  constexpr long kVariants = 12;
  int absent_seen = 0;
  for (const auto& p : load_catalog()) {
    const Fixture at_defaults(p.id);
    for (const auto& part : at_defaults.key.parts) {
      for (const auto& a : part.answers) {
        INFO(p.id << " " << a.name);
        const check::Verdict v = at_defaults.check(a.name, "none");
        CHECK_FALSE(v.correct);
        CHECK(v.line == "incorrect: " + a.name + " exists at these values");
      }
    }
    for (long n = 1; n <= kVariants; ++n) {
      const Key key = solve(p, parameter_values(p, variant_for(p, n)));
      for (const auto& part : key.parts) {
        for (const auto& name : part.absent) {
          INFO(p.id << " variant " << n << " " << name);
          ++absent_seen;
          const auto none = check::judge_absent(key, part.id, name, "DNE", true);
          REQUIRE(none);
          CHECK(none->correct);
          const auto number = check::judge_absent(key, "", name, "1", true);
          REQUIRE(number);
          CHECK_FALSE(number->correct);
        }
      }
    }
  }
  CHECK(absent_seen > 0);  // the heavy top's slow variants have no steady precession
}
