// The expression judge: an answer in the symbols against the key's closed form, proved equal by
// simplification or judged by its values at the set values and three more parameter points;
// where it is wrong, its dimension, or the numbers it has where the key has symbols, say why.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <functional>
#include <optional>
#include <tuple>
#include <utility>

#include "check/brackets.hpp"
#include "check/diagnosis.hpp"
#include "check/expression_dimension.hpp"
#include "check/judge_internal.hpp"
#include "check/latex_answer.hpp"
#include "check/symbol_values.hpp"
#include "check/written_forms.hpp"
#include "core/characters.hpp"
#include "core/input_error.hpp"
#include "symbolic/expression_guard.hpp"
#include "symbolic/unicode_notation.hpp"
#include "symbolic/value_text.hpp"

namespace wobble::check::detail {

namespace {
// Two expressions that agree to this relative difference at four parameter points are taken as
// the same function: 40-digit evaluation leaves ~1e-16, so only a different expression (or one
// that equals the key's at exactly those points, which the point choice makes unlikely) is
// farther off.
constexpr double kIdentityTolerance = 1e-9;
// The parameter points an expression is judged at besides the set values: each parameter
// scaled by these, in an order of its own. Not simple ratios (2, 1/2), so that a look-alike
// that equals the key only at special values is unlikely to agree at all four points; within
// 30% so that every point stays inside the parameters' ranges near the set values.
constexpr std::array<double, 3> kProbeFactors{1.13, 0.87, 1.29};
// Each parameter's order of the factors over the three points (a row: the factor's index at
// each point), then the same twelve with each factor's reciprocal: no two of the first twelve
// parameters scale alike, so that one of them in another's place (the angular rate θ̇ = 0.5 for
// the moment I₃ = 0.5) differs somewhere even where their set values are equal.
constexpr std::array<std::array<std::size_t, 3>, 6> kProbeOrders{
    {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {1, 0, 2}, {2, 1, 0}}};

// The values of the student's and the key's entries at one parameter point; principal moments
// sorted, since they may come in any order.
std::pair<std::vector<double>, std::vector<double>> at_point(const Context& ctx, const Answer& a,
                                                             const sym::ValueText& mine,
                                                             const sym::ValueText& key,
                                                             const sym::Values& point) {
  const GiNaC::lst at = sym::substitution(ctx.table, point);
  std::vector<double> got, want;
  for (const auto& e : mine.entries) got.push_back(sym::evaluate(e, at, kField));
  for (const auto& e : key.entries) want.push_back(sym::evaluate(e, at, "key " + a.name));
  if (a.kind == AnswerKind::principal_moments) {
    std::sort(got.begin(), got.end());
    std::sort(want.begin(), want.end());
  }
  return {got, want};
}

// The set values and three more points, each parameter scaled by the factors in its order (a
// parameter the key's forms are written with, `held`, stays at its value).
// Where the key has no value at a point (a heavy top's steady precession needs a fast enough
// spin, which scaling l up and the spin down can take away), the point is moved halfway back
// to the set values, up to kMostRetreats times, else left out.
constexpr int kMostRetreats = 4;
std::vector<sym::Values> judging_points(const sym::Values& set,
                                        const std::vector<std::string>& held,
                                        const std::function<void(const sym::Values&)>& key_at) {
  std::vector<sym::Values> points{set};
  for (std::size_t f = 0; f < kProbeFactors.size(); ++f) {
    for (int retreat = 0; retreat <= kMostRetreats; ++retreat) {
      sym::Values v = set;
      std::size_t i = 0;
      for (auto& [name, x] : v) {
        const std::size_t pattern = i++ % (2 * kProbeOrders.size());
        const double factor =
            std::pow(kProbeFactors[kProbeOrders[pattern % kProbeOrders.size()][f]],
                     std::ldexp(1.0, -retreat));
        if (std::find(held.begin(), held.end(), name) != held.end()) continue;
        x *= pattern < kProbeOrders.size() ? factor : 1 / factor;
      }
      try {
        key_at(v);
      } catch (const InputError&) {
        continue;
      }
      points.push_back(v);
      break;
    }
  }
  return points;
}

// Axes as expressions: by meaning at the set values, then, where the key has closed forms for
// its axes and moments, at the other points too (an expression right only at the set values
// is wrong).
Verdict judge_symbolic_axes(const Judge& j, const ReadAnswer& p) {
  const Context& ctx = j.ctx;
  const Verdict here = judge_axes_answer(j, at_point(ctx, j.a, p.value, p.value, ctx.values).first);
  if (!here.correct || j.a.symbolic.empty() || j.a.axis_moments_symbolic.empty()) return here;
  const auto key_axes = sym::parse_value_text(j.a.symbolic, ctx.table, "key " + j.a.name);
  const auto key_moments = sym::parse_value_text(j.a.axis_moments_symbolic, ctx.table, "key moments");
  const double tol = j.angle_tolerance();
  const auto key_at = [&](const sym::Values& point) {
    (void)at_point(ctx, j.a, key_axes, key_axes, point);
    (void)at_point(ctx, j.a, key_moments, key_moments, point);
  };
  for (const auto& point : judging_points(ctx.values, ctx.key.held, key_at)) {
    const auto [got, axes_flat] = at_point(ctx, j.a, p.value, key_axes, point);
    const auto lambda = at_point(ctx, j.a, key_moments, key_moments, point).first;  // unsorted
    // Columns with their moments, ascending (the order may change away from the set values).
    std::array<int, 3> order{0, 1, 2};
    std::sort(order.begin(), order.end(), [&](int x, int y) {
      return lambda[static_cast<std::size_t>(x)] < lambda[static_cast<std::size_t>(y)];
    });
    Mat3 axes;
    Vec3 sorted;
    for (int c = 0; c < 3; ++c) {
      const auto k = static_cast<std::size_t>(order[static_cast<std::size_t>(c)]);
      sorted[c] = lambda[k];
      for (int r = 0; r < 3; ++r) axes(r, c) = axes_flat[static_cast<std::size_t>(3 * r) + k];
    }
    if (!judge_axes(got, axes, sorted, tol, j.layout).correct) {
      return {false,
              "incorrect: " + j.a.name +
                  " (your expression gives the axes at the set values, but not at others)",
              {"it is right only for these numbers: check it as a function of the parameters"}};
    }
  }
  return {true, here.line.substr(0, here.line.size() - 1) + ", as functions of the parameters)",
          {}};
}

// Why a wrong expression is wrong, where its dimension says it: "m R/4" is a mass × length, and
// I0 is in kg m^2; "m + R" adds unlike quantities. Told only where the key's own entries scale
// as its unit says (the parameters' units are then trusted), and entry by entry, the first
// entry of another dimension named.
std::optional<Verdict> dimension_verdict(const Context& ctx, const Answer& a,
                                         const sym::ValueText& mine, const sym::ValueText& key,
                                         const Unit& key_unit) {
  // A zero has every dimension.
  for (const auto& e : key.entries) {
    if (e.is_zero()) continue;
    const auto d = expression_dimension(e, ctx.key);
    if (d && (d->mixed || d->dim != key_unit.dim)) return std::nullopt;
  }
  for (std::size_t i = 0; i < mine.entries.size(); ++i) {
    if (mine.entries[i].is_zero()) continue;
    const auto d = expression_dimension(mine.entries[i], ctx.key);
    if (!d || (!d->mixed && d->dim == key_unit.dim)) continue;
    const std::string what = mine.entries.size() == 1 ? "your expression" : entry_name(a, i);
    if (d->mixed) {
      return Verdict{false,
                     "incorrect: " + a.name + " (your expression differs from the key's)",
                     {what + " mixes dimensions: it adds unlike quantities, or takes a function "
                             "such as sin or exp of a quantity with a unit"}};
    }
    const std::string has =
        d->dim == std::array<int, 3>{0, 0, 0} ? " is " + d->words : "'s dimension is " + d->words;
    return Verdict{false,
                   "incorrect: " + a.name + " has the wrong dimension",
                   {what + has + "; the answer is in " +
                    (asked_unit(a).empty() ? "no unit" : sym::to_unicode(asked_unit(a))) + " (" +
                    key_unit.dimension_words() + ")"},
                   true};
  }
  return std::nullopt;
}

// `typed` as plain text: LaTeX read as the reader reads it ("\\cos 15^\\circ" is "cos(15 deg)").
std::string plain_text(const Context& ctx, const std::string& typed) {
  if (!looks_like_latex(typed)) return typed;
  try {
    return latex_as_text(typed, ctx.table, kField);
  } catch (const InputError&) {
    return typed;
  }
}

// What judging_points asks of a point: that the key's entries have values there (throws if not).
std::function<void(const sym::Values&)> key_values(const Context& ctx, const Answer& a,
                                                   const sym::ValueText& key) {
  return [&ctx, &a, &key](const sym::Values& point) { (void)at_point(ctx, a, key, key, point); };
}

// Whether two sets of values agree to kIdentityTolerance relative to the largest of `want`'s
// entries (a vector's zero component against its size), or to `zero_scale` (judge.hpp) where
// every entry is zero. Not absolute below 1: in SI the Earth's wobble rate is 2.4e-7 rad/s and
// its angle 1e-6 rad, where 1e-9 absolute would pass an answer 0.1% off as the key's form.
bool agree(const std::vector<double>& got, const std::vector<double>& want, double zero_scale) {
  double scale = 0.0;
  for (const double w : want) scale = std::max(scale, std::abs(w));
  if (scale == 0.0) scale = zero_scale;
  for (std::size_t i = 0; i < want.size(); ++i) {
    if (std::abs(got[i] - want[i]) > kIdentityTolerance * scale) return false;
  }
  return true;
}

// Whether `value` equals the key's expression at the judging points; not where it has no value
// at one of them.
bool equals_everywhere(const Context& ctx, const Answer& a, const sym::ValueText& value,
                       const sym::ValueText& key, const std::vector<sym::Values>& points) {
  for (const auto& point : points) {
    try {
      const auto [got, want] = at_point(ctx, a, value, key, point);
      if (!agree(got, want, zero_scale(ctx.key, a))) return false;
    } catch (const InputError&) {
      return false;
    }
  }
  return true;
}

// Numbers or symbols in `typed` (`found`, found in sym::to_ascii of `plain`) that stand where
// the key has something else (a symbol of that value, the number in degrees): the choices of
// what to write in their places (one candidate per entry of `found`, or none), tried until the
// reading is the key's (`is_key`: its expression at the judging points, or its values for a
// numeric answer); `told` words one replacement, `whole` the list. Nothing if none is: a
// number that happens to equal a value is not blamed.
struct Replacements {
  std::function<std::string(const NumberForSymbol&, const Candidate&)> told;
  std::function<std::string(const std::vector<std::string>&)> whole;
};
using IsKey = std::function<bool(const ReadAnswer&)>;
std::optional<std::string> replacements_named(const Context& ctx, const std::string& plain,
                                              const std::vector<NumberForSymbol>& found,
                                              const Replacements& say, const IsKey& is_key) {
  // Choices tried at most: two numbers, each one parameter's value or left as it is, are 4;
  // four places, each a parameter's value or not, are 16.
  constexpr std::size_t kMostChoices = 32;
  if (found.empty()) return std::nullopt;
  // The choices in groups (group[k] the group of entry k): one candidate for every entry of a
  // group, or none (it stays as it is: "/12" where ω is 12 rad/s). The first that makes the
  // key's expression names them.
  const auto named = [&](const std::vector<std::size_t>& group) -> std::optional<std::string> {
    std::vector<std::size_t> counts;
    for (std::size_t k = 0; k < found.size(); ++k) {
      if (group[k] >= counts.size()) counts.resize(group[k] + 1);
      counts[group[k]] = found[k].candidates.size() + 1;
    }
    std::size_t choices = 1;
    for (const std::size_t n : counts) choices = std::min(choices * n, kMostChoices + 1);
    if (choices > kMostChoices) return std::nullopt;
    for (std::size_t c = 0; c < choices; ++c) {
      std::vector<std::size_t> pick;  // c in the mixed radix of the counts
      for (std::size_t g = 0, rest = c; g < counts.size(); ++g) {
        pick.push_back(rest % counts[g]);
        rest /= counts[g];
      }
      std::vector<std::size_t> choice;
      for (const std::size_t g : group) choice.push_back(pick[g]);
      try {
        if (!is_key(read_answer(with_symbols(plain, found, choice), ctx.table, kField))) continue;
      } catch (const InputError&) {
        continue;
      }
      std::vector<std::string> told;
      for (std::size_t k = 0; k < found.size(); ++k) {
        if (choice[k] == found[k].candidates.size()) continue;  // left as it is
        const std::string said = say.told(found[k], found[k].candidates[choice[k]]);
        if (std::find(told.begin(), told.end(), said) == told.end()) told.push_back(said);
      }
      if (!told.empty()) return say.whole(told);
    }
    return std::nullopt;
  };
  // First one choice for each entry as written, as a student puts a value in for a symbol
  // wherever it stands ("(0.3 + c)(0.3 - c)/(0.3² + c²)" where a and m are both 0.3); then one
  // for each place ("12" for ω in "(12)²" but not in "/12").
  std::vector<std::string> distinct;
  std::vector<std::size_t> by_entry, by_place;
  for (std::size_t k = 0; k < found.size(); ++k) {
    const auto it = std::find(distinct.begin(), distinct.end(), found[k].number);
    by_entry.push_back(static_cast<std::size_t>(it - distinct.begin()));
    if (it == distinct.end()) distinct.push_back(found[k].number);
    by_place.push_back(k);
  }
  if (auto said = named(by_entry)) return said;
  return distinct.size() == found.size() ? std::nullopt : named(by_place);
}

// Whether a reading is the key's expression at the judging points.
IsKey equals_key(const Context& ctx, const Answer& a, const sym::ValueText& key,
                 const std::vector<sym::Values>& points) {
  return [&ctx, &a, &key, &points](const ReadAnswer& fixed) {
    return fixed.value.entries.size() == key.entries.size() &&
           equals_everywhere(ctx, a, fixed.value, key, points);
  };
}

// "0.12 is the value of R: write the symbol": the numbers in `typed` that are parameters'
// values, where writing their symbols in their place makes it the key's expression (each
// choice tried where parameters share a value).
std::optional<std::string> numbers_named(const Context& ctx, const Answer& a,
                                         const std::string& typed, const sym::ValueText& key,
                                         const std::vector<sym::Values>& points) {
  const std::string plain = plain_text(ctx, typed);
  const Replacements say{[](const NumberForSymbol& n, const Candidate& c) {
                           return n.number + " is the value of " + c.shown +
                                  (c.in_degrees ? " in degrees" : "") +
                                  (n.rounded ? ", rounded" : "");
                         },
                         [](const std::vector<std::string>& told) {
                           return fmt::format("{}: write the symbol{}", fmt::join(told, ", "),
                                              told.size() == 1 ? "" : "s");
                         }};
  return replacements_named(ctx, plain, numbers_for_symbols(ctx.key, plain), say,
                            equals_key(ctx, a, key, points));
}

// The length of the number `s` starts with, a sign included ("10" of "10 ma^2", "-2.5e-3" of
// "-2.5e-3*m"), 0 if none.
std::size_t leading_number(const std::string& s) {
  const std::size_t sign = !s.empty() && (s[0] == '-' || s[0] == '+') ? 1 : 0;
  const std::size_t end = number_end(s, sign);
  return end == sign ? 0 : end;
}

// "5, 7, 10 ma²" for the moments (5, 7, 10) m a²: a factor after the last of a list's numbers
// multiplies that entry alone, as it reads. Where multiplying each makes the key's, the line
// says how to write that; nullopt otherwise.
std::optional<std::string> factor_after_last_entry(const Context& ctx, const Answer& a,
                                                   const std::string& typed,
                                                   const sym::ValueText& key,
                                                   const std::vector<sym::Values>& points) {
  const ListItems list = list_items(plain_text(ctx, typed));
  if (list.bracketed || list.items.size() < 2 || list.items.size() != key.entries.size())
    return std::nullopt;
  std::vector<std::string> numbers;  // as typed, but for a minus sign
  std::string factor;                // as typed: "ma²"
  for (std::size_t k = 0; k < list.items.size(); ++k) {
    const std::string item = trim(list.items[k]);
    const std::string ascii = sym::to_ascii(item);
    const std::size_t n = leading_number(ascii);
    if (n == 0 || (n != ascii.size() && k + 1 != list.items.size())) return std::nullopt;
    numbers.push_back(ascii.substr(0, n));
    // The number's end in `item`: its characters are ASCII but for a leading "−" (3 bytes).
    const std::size_t minus = item.rfind("−", 0) == 0 ? std::string("−").size() - 1 : 0;
    if (k + 1 == list.items.size()) factor = trim(item.substr(std::min(n + minus, item.size())));
  }
  if (!factor.empty() &&
      (factor[0] == '*' || factor.rfind("·", 0) == 0 || factor.rfind("×", 0) == 0))
    factor = trim(factor.substr(factor[0] == '*' ? 1 : std::string("·").size()));
  if (factor.empty() || std::isdigit(static_cast<unsigned char>(factor[0]))) return std::nullopt;
  const std::string each = fmt::format("({}) {}", fmt::join(numbers, ", "), factor);
  try {
    if (!equals_key(ctx, a, key, points)(read_answer(each, ctx.table, kField))) return std::nullopt;
  } catch (const InputError&) {
    return std::nullopt;
  }
  return fmt::format(
      "{} after the last number multiplies that entry alone; for it to multiply each, write {}",
      factor, each);
}

// "θ̇ (thetadot) where the key has I₃ (I3)": a symbol in the place of another of the same set
// value, where writing the other there makes the key's expression.
std::optional<std::string> symbols_named(const Context& ctx, const Answer& a,
                                         const std::string& typed, const sym::ValueText& key,
                                         const std::vector<sym::Values>& points) {
  const std::string plain = plain_text(ctx, typed);
  const Replacements say{[](const NumberForSymbol& n, const Candidate& c) {
                           return n.number + " where the key has " + c.shown;
                         },
                         [](const std::vector<std::string>& told) {
                           return fmt::format("{}? (the same value here, not the same quantity)",
                                              fmt::join(told, ", "));
                         }};
  return replacements_named(ctx, plain, symbols_sharing_values(ctx.key, plain), say,
                            equals_key(ctx, a, key, points));
}
}  // namespace

// "90 is in degrees: write 90°": a number in an expression that, read in degrees, makes the key's
// expression ("φ + 90" for φ + π/2); a plain number in an expression is in radians.
// How a number read in degrees is told: "90 is in degrees: write 90°".
const Replacements kDegreesSaid{[](const NumberForSymbol& n, const Candidate& c) {
                                  return n.number + " is in degrees: write " + c.shown;
                                },
                                [](const std::vector<std::string>& told) {
                                  return fmt::format("{} (a number without a unit is in radians)",
                                                     fmt::join(told, "; "));
                                }};

std::optional<std::string> degrees_named(const Context& ctx, const Answer& a,
                                         const std::string& typed, const sym::ValueText& key,
                                         const std::vector<sym::Values>& points) {
  const std::string plain = plain_text(ctx, typed);
  return replacements_named(ctx, plain, numbers_as_degrees(plain), kDegreesSaid,
                            equals_key(ctx, a, key, points));
}

std::optional<std::string> degrees_in_numbers(const Judge& j, const std::string& typed,
                                              double to_key) {
  const std::string plain = plain_text(j.ctx, typed);
  const std::string ascii = sym::to_ascii(plain);
  bool calls = false;
  for (std::size_t i = 0; i < ascii.size() && !calls;) {
    std::size_t end = i;
    while (end < ascii.size() && std::isalpha(static_cast<unsigned char>(ascii[end]))) ++end;
    calls = end > i && sym::is_function_name(ascii.substr(i, end - i));
    i = std::max(end, i + 1);
  }
  if (!calls) return std::nullopt;
  // The numbers' values, read with some in degrees, are the key's to the answer's tolerance.
  const auto is_key = [&j, to_key](const ReadAnswer& fixed) {
    if (fixed.symbolic || fixed.value.entries.size() != j.a.value.data.size()) return false;
    std::vector<double> got;
    for (const auto& e : fixed.value.entries)
      got.push_back(sym::evaluate(e, GiNaC::lst{}, kField) * to_key);
    if (j.a.kind == AnswerKind::principal_moments) std::sort(got.begin(), got.end());
    return j.all_close(got, j.a.value.data);
  };
  return replacements_named(j.ctx, plain, numbers_as_degrees(plain), kDegreesSaid, is_key);
}

namespace {
// The entries of `mine` that are the key's plus 2π k, k a nonzero whole number (k from the set
// values, the identity proved), named; none unless every other entry is proved the key's.
std::vector<std::string> turned_entries(const Context& ctx, const Answer& a,
                                        const sym::ValueText& mine, const sym::ValueText& key) {
  std::vector<double> got, want;
  try {
    std::tie(got, want) = at_point(ctx, a, mine, key, ctx.values);
  } catch (const InputError&) {
    return {};
  }
  std::vector<std::string> moved;
  for (std::size_t i = 0; i < key.entries.size(); ++i) {
    const double turns = std::round((got[i] - want[i]) / (2 * M_PI));
    constexpr double kMostTurns = 1e6;  // a whole number in a long, far past any answer's
    if (!(std::abs(turns) <= kMostTurns)) return {};
    const GiNaC::ex two_pi_k = GiNaC::numeric(2 * static_cast<long>(turns)) * GiNaC::Pi;
    if (!sym::is_identically_zero(mine.entries[i] - key.entries[i] - two_pi_k)) return {};
    if (turns != 0.0) moved.push_back(entry_name(a, i));
  }
  return moved;
}
}  // namespace

Verdict judge_symbolic(const Context& ctx, const Answer& a, const std::string& typed,
                       const ReadAnswer& p, const Options& opt, AxesLayout layout) {
  const Judge j{ctx, a, opt, zero_scale(ctx.key, a), layout};
  if (a.kind == AnswerKind::principal_axes) return judge_symbolic_axes(j, p);
  if (a.symbolic.empty()) {
    throw InputError(kField + ": " + a.name + " has no closed form in the key; give a number");
  }
  const sym::ValueText key = sym::parse_value_text(a.symbolic, ctx.table, "key " + a.name);
  // First by simplification: a rational rearrangement of the key's form is proved equal. It
  // cannot prove trigonometric or radical identities (2*atan(2*tan(a)) in another form), so an
  // unproved answer is then judged by evaluation.
  bool proved = true;
  for (std::size_t i = 0; i < key.entries.size() && proved; ++i) {
    proved = sym::is_identically_zero(p.value.entries[i] - key.entries[i]);
  }
  if (proved)
    return {true, "correct: " + a.name + " (your expression simplifies to the key's)", {}};
  // Euler angles up to whole turns: an entry proved to be the key's plus 2π k.
  if (angles_up_to_turns(a)) {
    if (const auto moved = turned_entries(ctx, a, p.value, key); !moved.empty()) {
      return {true, "correct: " + a.name + whole_turns_note(moved), {}};
    }
  }
  // The set values first.
  const std::vector<sym::Values> points =
      judging_points(ctx.values, ctx.key.held, key_values(ctx, a, key));
  for (std::size_t n = 0; n < points.size(); ++n) {
    std::vector<double> got, want;
    try {
      std::tie(got, want) = at_point(ctx, a, p.value, key, points[n]);
    } catch (const InputError&) {
      // No value away from the set values where the key has one (the root of a negative, once a
      // number stands for a symbol): it differs from the key's. One at the set values is said
      // as it is.
      if (n == 0) throw;
      got.clear();
    }
    if (!got.empty() && agree(got, want, j.scale)) continue;
    const Unit key_unit = a.unit.empty() ? Unit{} : parse_unit(a.unit, "key unit of " + a.name);
    const auto dimension =
        p.unit_on_numbers ? std::nullopt : dimension_verdict(ctx, a, p.value, key, key_unit);
    const std::string differs =
        "incorrect: " + a.name + " (your expression differs from the key's)";
    if (const auto factor = factor_after_last_entry(ctx, a, typed, key, points))
      return {false, differs, {*factor}};
    // Right at the set values but not here: a number where the key has a symbol ("(φ, 30°, ψ)"
    // for (φ, θ, ψ) with θ set to 30°, "m 0.12²/4" for m R²/4), or a symbol where it has none
    // (m² a²/6 for m a²/6 at m = 1 kg): another dimension, if it has one, is said too.
    if (n > 0) {
      auto named = numbers_named(ctx, a, typed, key, points);
      if (!named) named = symbols_named(ctx, a, typed, key, points);
      Verdict v{
          false,
          differs,
          {"it gives the key's value at the set values but not at others: " +
           named.value_or("a number, or a symbol of the same value, where the key has a symbol?")}};
      if (dimension) v.feedback.push_back(dimension->feedback.at(0));
      return v;
    }
    // At the set values right as a number would be, not to the digits an expression is held
    // to: a number rounded where the key has a symbol (cos(0.2618) for cos α), if writing the
    // symbol makes it the key's.
    if (j.all_close(got, want)) {
      if (const auto named = numbers_named(ctx, a, typed, key, points)) {
        return {false,
                differs,
                {"it gives the key's value at the set values only as a number rounded would, "
                 "not as the key's expression does: " +
                 *named}};
      }
      // Within a number's tolerance, which an expression is not judged by: "off by 0.5%" would
      // read as right.
      if (!dimension) {
        return {false,
                differs,
                {"it comes close to the key's value at the set values, but an expression is "
                 "right only when it is the key's: a small term left out, or a number rounded?"}};
      }
    }
    // Wrong at the set values: its dimension, or degrees written as radians ("φ + 90"), else
    // why as for a number.
    if (dimension) return *dimension;
    if (const auto degrees = degrees_named(ctx, a, typed, key, points))
      return {false, differs, {*degrees}};
    // "ω cos 15" for ω cos α, α = 15°: an angle's value in degrees without its mark, where its
    // symbol makes the key's expression.
    if (const auto named = numbers_named(ctx, a, typed, key, points))
      return {false, differs, {*named}};
    // "[φ + π, −θ, ψ + π]": Euler angles on the other branch.
    if (const auto branch = other_branch(j, got)) return {false, differs, {*branch}};
    return {false, differs, diagnose(j, key_unit, got, a.value.data)};
  }
  return {true,
          "correct: " + a.name +
              " (your expression equals the key's at the set values and three more points" +
              (a.kind == AnswerKind::principal_moments ? ", in any order)" : ")"),
          {}};
}

}  // namespace wobble::check::detail
