#include "export/graded_variants.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <optional>
#include <set>

#include "check/axes_judge.hpp"
#include "core/inertia.hpp"
#include "core/input_error.hpp"
#include "export/message_numbers.hpp"
#include "problem/values.hpp"
#include "solvers/solve.hpp"
#include "symbolic/units.hpp"

namespace wobble::exports {

namespace {
// A mistake's wrong answer is the key turned by an exact operation (a sign, a factor, another
// answer); one within this fraction of the answer's scale of the key is the key itself (the
// reversed sign of a zero), not a slip a student can make here.
constexpr double kSameAsKey = 1e-12;
// Rejected numbers allowed per wanted variant before giving up: a problem whose every tenth
// draw is gradable is not one to export.
constexpr long kDrawsPerVariant = 10;
// Variants drawn at least to find the mistakes no variant can tell apart (graded_variants).
constexpr long kStructuralProbe = 20;
// A mistake within the tolerance in more than this share of those draws refuses no variant:
// refusing would leave fewer than one in four.
constexpr double kUntoldShare = 0.75;

double answer_scale(const Answer& a, double zero) {
  double s = 0.0;
  for (double x : a.value.data) s = std::max(s, std::abs(x));
  return s > 0.0 ? s : zero;
}

bool same_as_key(const std::vector<double>& wrong, const Answer& a, double zero) {
  const double scale = answer_scale(a, zero);
  for (std::size_t i = 0; i < wrong.size(); ++i) {
    if (std::abs(wrong[i] - a.value.data[i]) > kSameAsKey * scale) return false;
  }
  return true;
}

// The largest relative difference of the entries, for the report.
double relative_distance(const std::vector<double>& wrong, const Answer& a, double zero) {
  double d = 0.0;
  for (std::size_t i = 0; i < wrong.size(); ++i) {
    const double k = a.value.data[i];
    d = std::max(d, std::abs(wrong[i] - k) / (k != 0.0 ? std::abs(k) : zero));
  }
  return d;
}

// A mistake's line with its numbers as "…", the same in every variant: "this is the fast-top
// approximation M g l / (I3 ω3), …% below the exact value here", "1/… = … rad/s is the answer".
// A multiple of π is kept: "2π/… = … s", the 2 of a period is no variant's number.
std::string numbers_elided(const std::string& line) {
  const MessageNumbers split = message_numbers(line);
  std::vector<std::string> elided(split.numbers.size(), "…");
  for (std::size_t i = 0; i < elided.size(); ++i) {
    if (split.words[i + 1].rfind("π", 0) == 0) elided[i] = split.numbers[i];
  }
  return with_numbers(split, elided);
}

std::string tolerance_words(const check::Options& o) {
  if (o.sigfigs) return fmt::format("{} significant figures", *o.sigfigs);
  return fmt::format("tolerance {:g}%", 100 * o.rel_tol);
}

std::string number_text(double x) { return fmt::format("{:.17g}", x); }

// The values as a handout shows them: the variant's text, with the parameter's unit.
std::vector<std::pair<std::string, std::string>> shown_values(
    const Key& key, const std::vector<std::string>& assignments) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& p : key.parameters) {
    std::string text;
    for (const auto& a : assignments) {
      const auto eq = a.find('=');
      if (a.substr(0, eq) == p.name) text = a.substr(eq + 1);
    }
    if (text.empty()) {
      text = format_number(p.value) + (p.unit.empty() ? "" : " " + p.unit);
    } else if (text.size() > 3 && text.compare(text.size() - 3, 3, "deg") == 0) {
      text = text.substr(0, text.size() - 3) + "°";
    } else if (!p.unit.empty()) {
      text += " " + p.unit;
    }
    out.emplace_back(p.name, text);
  }
  return out;
}
}  // namespace

std::string answer_text(const Answer& a, const std::vector<double>& values) {
  std::string text;
  if (a.value.shape == Value::Shape::scalar) {
    text = number_text(values.at(0));
  } else if (a.value.shape == Value::Shape::vector) {
    text = "[";
    for (std::size_t i = 0; i < values.size(); ++i) {
      text += (i ? ", " : "") + number_text(values[i]);
    }
    text += "]";
  } else {
    text = "[";
    for (std::size_t r = 0; r < a.value.rows; ++r) {
      text += r ? ", [" : "[";
      for (std::size_t c = 0; c < a.value.cols; ++c) {
        text += (c ? ", " : "") + number_text(values.at(r * a.value.cols + c));
      }
      text += "]";
    }
    text += "]";
  }
  return a.unit.empty() ? text : text + " " + a.unit;
}

std::pair<std::vector<GradedAnswer>, std::vector<Rejection>> grade_rules(
    const Problem& problem, const Key& key, const sym::Values& values,
    const check::Options& options) {
  const sym::SymbolTable table = problem.symbol_table();
  const check::Context ctx{key, table, values};
  std::vector<GradedAnswer> out;
  std::vector<Rejection> refusals;
  for (const auto& part : key.parts) {
    if (!part.absent.empty()) {
      // The variants of one export must ask the same questions.
      const std::string kind =
          fmt::format("{} (part {}) does not exist at these values", part.absent.front(), part.id);
      return {{}, {{0, kind, kind}}};
    }
    for (const auto& a : part.answers) {
      const check::Options opt = check::options_for(a, options);
      GradedAnswer g{part.id, a, opt.rel_tol, check::zero_scale(key, a), {}, {}};
      if (a.kind == AnswerKind::principal_axes) {
        g.eigenspaces = check::eigenspace_columns(
            Vec3(a.axis_moments.at(0), a.axis_moments.at(1), a.axis_moments.at(2)));
      }
      const Unit unit = a.unit.empty() ? Unit{} : parse_unit(a.unit, "key unit of " + a.name);
      for (const auto& wrong : check::wrong_answers(a, key, unit)) {
        if (same_as_key(wrong.values, a, g.zero_scale)) continue;
        const check::Verdict v = check::judge(ctx, a, answer_text(a, wrong.values), options);
        if (v.correct) {
          const std::string clause = wrong.message.substr(0, wrong.message.find_first_of(":;"));
          const auto what = [&](const std::string& said) {
            return fmt::format("{} (part {}): {} (\"{}\")", a.name, part.id, wrong.mistake, said);
          };
          refusals.push_back(
              {0,
               fmt::format("{} gives a value {:.2g}% from the answer, which the judge accepts ({})",
                           what(clause), 100 * relative_distance(wrong.values, a, g.zero_scale),
                           tolerance_words(opt)),
               fmt::format("{} lies within the {}", what(numbers_elided(clause)),
                           tolerance_words(opt))});
          continue;
        }
        // Named as an earlier mistake: that one covers it.
        if (v.feedback.empty() || v.feedback.front() != wrong.message) continue;
        g.mistakes.push_back(wrong);
      }
      out.push_back(std::move(g));
    }
  }
  return {out, refusals};
}

namespace {
struct Draw {
  GradedVariant variant;
  std::vector<Rejection> refusals;
};

Draw draw_variant(const Problem& problem, long n, const check::Options& options) {
  const auto assignments = variant_for(problem, n);
  const sym::Values values = parameter_values(problem, assignments);
  Key key = solve(problem, values);
  key.variant = n;
  auto [answers, refusals] = grade_rules(problem, key, values, options);
  for (auto& r : refusals) r.number = n;
  auto shown = shown_values(key, assignments);
  return {{n, std::move(shown), std::move(key), std::move(answers)}, std::move(refusals)};
}

bool absent(const Draw& d) { return !d.refusals.empty() && d.variant.answers.empty(); }
}  // namespace

VariantSet graded_variants(const Problem& problem, long first, long count,
                           const check::Options& options) {
  // A mistake within the tolerance in more than kUntoldShare of the first draws (k for k2 near
  // the separatrix, where both are 1 to six digits, in all; the asymmetric top's
  // small-oscillation period for the exact one, near an axis, in 94 of 100) is one no number
  // tells in this problem: refusing each variant where it is within would refuse nearly all,
  // so none is refused for it (it is listed where it is told apart). Any other mistake within
  // the tolerance refuses its variant (the tennis racket's two rates, alike in half the draws). The
  // first draws are as many as asked, at least kStructuralProbe, whatever the count, so a mistake
  // told apart rarely is found so in any export.
  const long probe = std::max(count, kStructuralProbe);
  std::vector<Draw> draws;
  for (long n = first; n < first + probe; ++n) draws.push_back(draw_variant(problem, n, options));
  std::map<std::string, long> within;  // kind -> draws it is within the tolerance in
  long drawn = 0;
  for (const auto& d : draws) {
    if (absent(d)) continue;
    ++drawn;
    std::set<std::string> kinds;
    for (const auto& r : d.refusals) kinds.insert(r.kind);
    for (const auto& k : kinds) ++within[k];
  }
  VariantSet set;
  for (const auto& [kind, times] : within) {
    if (static_cast<double>(times) > kUntoldShare * static_cast<double>(drawn))
      set.untold.push_back({kind, times, drawn});
  }
  const auto untold = [&](const std::string& kind) {
    return std::any_of(set.untold.begin(), set.untold.end(),
                       [&](const UntoldMistake& u) { return u.kind == kind; });
  };
  for (long n = first; static_cast<long>(set.variants.size()) < count; ++n) {
    if (n - first >= kDrawsPerVariant * probe) {
      std::map<std::string, int> kinds;
      for (const auto& r : set.rejected) ++kinds[r.kind];
      std::string why;
      for (const auto& [kind, times] : kinds) {
        why += fmt::format("{}{} ({} times)", why.empty() ? "" : "; ", kind, times);
      }
      throw InputError(fmt::format(
          "--variants: {}: only {} of {} variants drawn from {} can be graded: {}. A smaller "
          "--tolerance tells a mistake from the answer where they lie close",
          problem.id, set.variants.size(), n - first, first, why));
    }
    Draw d = n - first < probe ? std::move(draws[static_cast<std::size_t>(n - first)])
                               : draw_variant(problem, n, options);
    const auto refused = std::find_if(d.refusals.begin(), d.refusals.end(),
                                      [&](const Rejection& r) { return !untold(r.kind); });
    if (refused != d.refusals.end()) {
      set.rejected.push_back(*refused);
      continue;
    }
    set.variants.push_back(std::move(d.variant));
  }
  return set;
}

}  // namespace wobble::exports
