#include "check/diagnosis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <optional>
#include <utility>

#include "check/judge.hpp"
#include "symbolic/expression.hpp"
#include "symbolic/unicode_notation.hpp"
#include "symbolic/value_text.hpp"

namespace wobble::check {

bool Finding::all_close(const std::vector<double>& v, const std::vector<double>& k) const {
  if (v.size() != k.size()) return false;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!close(v[i], k[i])) return false;
  }
  return true;
}

std::string entry_name(const Answer& a, std::size_t i) {
  if (a.value.shape == Value::Shape::vector) {
    if (a.kind == AnswerKind::principal_moments && a.value.data.size() == 3) {
      return std::string("the ") + std::array<const char*, 3>{"smallest", "middle", "largest"}[i] +
             " moment";
    }
    // "c₁" as the question names it; "entry x" or "entry e₁" along the frame's axes.
    if (!a.named_entries.empty()) return a.named_entries[i];
    const std::vector<std::string> axes = entry_names(a);
    return "entry " + (axes.size() == a.value.data.size() ? axes[i] : std::to_string(i + 1));
  }
  return fmt::format("entry ({}, {})", i / a.value.cols + 1, i % a.value.cols + 1);
}

namespace {
using Wrong = std::vector<WrongAnswer>;

// A value this small beside its unit's largest in the key (zero_scale, judge.hpp) is a zero left
// by rounding, as an identity's residual is (printed 0).
constexpr double kRoundingZero = 1e-9;

std::vector<double> times(const std::vector<double>& v, double factor) {
  std::vector<double> out = v;
  for (double& x : out) x *= factor;
  return out;
}

Wrong products_of_inertia_sign(const Answer& a, const Key&, const Unit&) {
  // An inertia tensor's, not a rotation's: the sign of its off-diagonal entries is no convention.
  if (a.kind != AnswerKind::tensor || a.value.data.size() != 9) return {};
  std::vector<double> flipped = a.value.data;
  for (std::size_t i = 0; i < 9; ++i) {
    if (i / 3 != i % 3) flipped[i] = -flipped[i];
  }
  return {{"", flipped,
           "the products of inertia have the wrong sign: I_xy = -sum m x y (so that L = I w)"}};
}

std::string reversed_sign_message(const Answer& a) {
  if (a.sign != SignConvention::sense_of_precession) return "the sign is reversed";
  if (a.value.data.size() != 1) {
    return "the sense is reversed: the precession runs the other way (check prolate, I3 < I1, "
           "against oblate, I3 > I1)";
  }
  // A signed rate given as its magnitude (or the sign flipped): the sign is the physics.
  const bool against = a.value.data[0] < 0;
  return fmt::format(
      "the size is right but not the sign: {} is signed along e3, and {} here: the "
      "precession runs {} the spin ({}; check prolate, I3 < I1, against oblate, I3 > I1)",
      a.name, against ? "negative" : "positive", against ? "against" : "with",
      against ? "a prolate body" : "an oblate body");
}

Wrong reversed_sign(const Answer& a, const Key&, const Unit&) {
  return {{"", times(a.value.data, -1.0), reversed_sign_message(a)}};
}

bool pure_angle(const Unit& u) { return u.angle && u.dim == std::array<int, 3>{0, 0, 0}; }
// Rates: rad/s and 1/s alike (symbolic/symbolic/units.hpp).
bool per_second(const Unit& u) { return u.dim == std::array<int, 3>{0, 0, -1}; }

Wrong degrees_for_radians(const Answer& a, const Key&, const Unit& key_unit) {
  if (!pure_angle(key_unit)) return {};
  return {{"", times(a.value.data, 180.0 / M_PI),
           "this is the angle in degrees: give radians, or write the unit (12 deg)"}};
}

// An angular rate in SI (rad/s), not a growth rate (1/s): what an instrument's degrees per
// second or a motor's revolutions per minute measure.
bool angular_rate(const Unit& u) {
  return per_second(u) && u.angle && u.to_si == 1.0;
}

Wrong degrees_per_second(const Answer& a, const Key&, const Unit& key_unit) {
  if (!angular_rate(key_unit)) return {};
  return {{"", times(a.value.data, 180.0 / M_PI),
           "this is the rate in degrees per second: give rad/s, or write the unit (12 deg/s)"}};
}

Wrong revolutions_per_minute(const Answer& a, const Key&, const Unit& key_unit) {
  if (!angular_rate(key_unit)) return {};
  return {{"", times(a.value.data, 60.0 / (2 * M_PI)),
           "this is revolutions per minute: multiply by 2π/60 for rad/s, or write rpm"}};
}

Wrong turns_per_second(const Answer& a, const Key&, const Unit& key_unit) {
  if (!per_second(key_unit)) return {};
  return {{"", times(a.value.data, 1.0 / (2 * M_PI)),
           "this is revolutions per second: multiply by 2π for rad/s, or write rev/s"}};
}

Wrong hertz_as_radians(const Answer& a, const Key&, const Unit& key_unit) {
  if (!per_second(key_unit)) return {};
  return {{"", times(a.value.data, 2 * M_PI),
           "this is 2π times the answer: Hz, rev/s and rpm count turns, so 1 Hz = 2π rad/s "
           "(the number in rad/s labelled Hz?)"}};
}

// A period given for a rate, or a rate for a time (1/x, 2π/x): the other quantity's number,
// typed in the key's unit as a quiz takes a number. The line is the one the judge says of such
// a number (reciprocal_mistake), so that an export's feedback is the judge's. Only where the
// key's unit is SI, as there alone a bare number is the SI reciprocal's.
Wrong reciprocal_given(const Answer& a, const Key& key, const Unit& key_unit) {
  Wrong out;
  if (a.value.data.size() != 1) return out;  // the rest reciprocal_mistake decides
  // The wrong number is the key's turned exactly: only rounding between them.
  constexpr double kRounding = 1e-12;
  const auto same = [](double x, double k) { return std::abs(x - k) <= kRounding * std::abs(k); };
  for (const double factor : {1.0, 2 * M_PI}) {
    const double typed = factor / a.value.data[0];
    if (auto message = reciprocal_mistake(a, typed, nullptr, key_unit, zero_scale(key, a), same))
      out.push_back({"", {typed}, std::move(*message)});
  }
  return out;
}

// The same vector in another frame: L0_body answered for L0_space and the like.
Wrong other_frame(const Answer& a, const Key& key, const Unit&) {
  Wrong out;
  if (a.frame == AnswerFrame::none) return out;
  for (const auto& part : key.parts) {
    for (const auto& b : part.answers) {
      if (b.frame == AnswerFrame::none || b.frame == a.frame || b.unit != a.unit ||
          b.value.data.size() != a.value.data.size()) {
        continue;
      }
      out.push_back({"", b.value.data,
                     fmt::format("these are the {}-frame components ({}); {} asks for the {}-frame "
                                 "ones",
                                 frame_name(b.frame), b.name, a.name, frame_name(a.frame))});
    }
  }
  return out;
}

// Whether one answer may be taken for the other: the same unit, or the same units asked (the
// asymmetric top's rates about its three axes, a frequency in rad/s or a growth rate in 1/s).
bool alike_units(const Answer& a, const Answer& b) {
  return a.unit == b.unit || asked_unit(a) == asked_unit(b);
}

// Another answer of the key, or its approximation: more specific than a factor (max_angle is
// exactly twice angle_L_e3, L0_space is L0_body turned). Not one that is zero (the flying plate's
// identity_residual): any value small beside its unit's scale would be named as it. One of
// another unit too where two of its entries or more are not zero, as a line pasted into the
// wrong box gives it (the tennis racket's Euler coefficients for its dω/dt): several numbers each
// matching are no coincidence, as one number matching a value of another unit may be (a
// centre of mass (0, 0, z) beside a spin (0, 0, ω)).
Wrong other_answer(const Answer& a, const Key& key, const Unit&) {
  Wrong out;
  for (const auto& part : key.parts) {
    for (const auto& b : part.answers) {
      const bool zero = std::all_of(b.value.data.begin(), b.value.data.end(),
                                    [](double x) { return x == 0; });
      const bool comparable =
          alike_units(a, b) || std::count_if(b.value.data.begin(), b.value.data.end(),
                                             [](double x) { return x != 0; }) > 1;
      // Nor one equal to this answer (the Euler angles read back are the angles): a value
      // close to it is no mistake of taking the other.
      if (&b == &a || b.name == a.name || !comparable ||
          b.value.data.size() != a.value.data.size() || zero || b.value.data == a.value.data) {
        continue;
      }
      out.push_back({"", b.value.data, "this is " + b.name + " (part " + part.id + "), not " + a.name});
    }
  }
  // The other answer's textbook approximation: I3 ω3 / (I1 cos θ), the fast top's fast rate,
  // given for the slow one. After the exact values, which name it more surely.
  for (const auto& part : key.parts) {
    for (const auto& b : part.answers) {
      if (&b == &a || b.name == a.name || !alike_units(a, b)) continue;
      for (const auto& approximation : b.approximations) {
        if (approximation.values.size() != a.value.data.size()) continue;
        out.push_back({"", approximation.values,
                       fmt::format("this is {} of {} (part {}), not {}", approximation.name, b.name,
                                   part.id, a.name)});
      }
    }
  }
  return out;
}

// A rotation made of the right turns, each taken the other way, or in reverse order: PHY 711's
// R_z(γ)ᵀ R_y(β)ᵀ R_z(α)ᵀ written R_z(γ) R_y(β) R_z(α) (the turns' own matrices where the
// components' are wanted: R(a)ᵀ = R(−a)), Taylor's R_z(φ) R_y(θ) R_z(ψ) written
// R_z(ψ) R_y(θ) R_z(φ). A turn taken the other way is the turn by minus its angle, so the first
// is the key's form at its angles negated, whatever the axes; the second is that one's transpose,
// (R₁(−a) R₂(−b) R₃(−c))ᵀ = R₃(c) R₂(b) R₁(a). From the key's exact form: a matrix of numbers
// does not say which turns made it.
Wrong turns_reversed(const Answer& a, const Key& key, const Unit&) {
  if (a.kind != AnswerKind::matrix || a.symbolic.empty() || a.value.data.size() != 9) return {};
  sym::SymbolTable table;
  GiNaC::lst at;
  std::vector<std::pair<GiNaC::ex, std::string>> angles;  // each symbol and its name
  std::string names;
  for (const auto& p : key.parameters) {
    const GiNaC::ex s = table.declare(p.name, p.latex, sym::SymbolSign::real);
    const bool angle = !p.unit.empty() && pure_angle(parse_unit(p.unit, "unit of " + p.name));
    at.append(s == sym::exact_value(angle ? -p.value : p.value));
    if (angle) angles.emplace_back(s, p.name);
  }
  try {
    const sym::ValueText form = sym::parse_value_text(a.symbolic, table, "key of " + a.name);
    std::vector<double> negated;
    for (const auto& e : form.entries) negated.push_back(sym::evaluate(e, at, "key of " + a.name));
    for (const auto& angle : angles) {
      const bool turns_by_it = std::any_of(form.entries.begin(), form.entries.end(),
                                           [&](const GiNaC::ex& e) { return e.has(angle.first); });
      if (turns_by_it) names += (names.empty() ? "" : ", ") + sym::to_unicode(angle.second);
    }
    if (names.empty() || form.rows != 3 || form.cols != 3) return {};
    std::vector<double> reversed(9);
    for (std::size_t r = 0; r < 3; ++r) {
      for (std::size_t c = 0; c < 3; ++c) reversed[c * 3 + r] = negated[r * 3 + c];
    }
    return {{"", negated,
             fmt::format("each turn is taken the other way: this is the answer with {} negated (a "
                         "turn's own matrix where the one for components is wanted, or back? "
                         "R(a)ᵀ = R(−a))",
                         names)},
            {"", reversed,
             "the right turns multiplied in reverse order: the turn written first acts last on a "
             "vector"}};
  } catch (const InputError&) {
    return {};  // no value at the angles negated (a square root of a sine): no such mistake
  }
}

// An approximation a course teaches, given for the exact answer: the fast top's steady rates.
// Numbers only (no approximation of a vector is taught here): the line says how far off it is.
Wrong approximation_given(const Answer& a, const Key&, const Unit&) {
  Wrong out;
  if (a.value.data.size() != 1 || a.value.data[0] == 0.0) return out;
  const double exact = a.value.data[0];
  for (const auto& approximation : a.approximations) {
    if (approximation.values.size() != 1) continue;
    const double off_percent = 100 * (approximation.values[0] - exact) / exact;
    out.push_back({"", approximation.values,
                   fmt::format("this is {}, {:.3g}% {} {} here: {}", approximation.name,
                               std::abs(off_percent), off_percent < 0 ? "below" : "above",
                               approximation.beside, approximation.remedy)});
  }
  return out;
}

Wrong factor_off(const Answer& a, const Key&, const Unit&) {
  Wrong out;
  for (const double factor : {2.0, 0.5, 4.0, 0.25, 12.0, 1.0 / 12, 3.0, 1.0 / 3}) {
    const double whole = factor >= 1 ? factor : 1 / factor;
    out.push_back(
        {"", times(a.value.data, factor),
         fmt::format("this is {} the answer: a factor {:g} is off (a 1/12 or 1/3 in a moment of "
                     "inertia, a 1/2 in an energy?)",
                     factor >= 1 ? fmt::format("{:g} times", whole) : fmt::format("1/{:g} of", whole),
                     whole)});
  }
  return out;
}
}  // namespace

const std::vector<Mistake>& known_mistakes() {
  static const std::vector<Mistake> table{
      {"products of inertia with the wrong sign", products_of_inertia_sign},
      {"a reversed sign", reversed_sign},
      {"degrees for radians", degrees_for_radians},
      {"degrees per second for rad/s", degrees_per_second},
      {"turns per second for rad/s", turns_per_second},
      {"revolutions per minute for rad/s", revolutions_per_minute},
      {"Hz taken as rad/s", hertz_as_radians},
      {"a period for a rate, a rate for a time", reciprocal_given},
      {"the components in another frame", other_frame},
      {"another answer of the key", other_answer},
      {"a rotation's turns reversed", turns_reversed},
      {"an approximation for the exact answer", approximation_given},
      {"a factor off", factor_off},
  };
  return table;
}

std::vector<WrongAnswer> wrong_answers(const Answer& answer, const Key& key, const Unit& key_unit) {
  std::vector<WrongAnswer> out;
  if (answer.kind == AnswerKind::principal_axes) return out;
  for (const auto& mistake : known_mistakes()) {
    for (auto& w : mistake.wrong_answers(answer, key, key_unit)) {
      w.mistake = mistake.name;
      out.push_back(std::move(w));
    }
  }
  return out;
}

namespace {
// "this is 1e-1 of the answer: ..." where every entry is the key's times one power of ten, from
// 10^-9 to 10^9 but 1: a prefix dropped or a unit converted the wrong way (720 g cm² for 7200, a
// length in cm as if in m). A rule, not entries of known_mistakes(): an export lists those as
// answers with feedback, and eighteen more for each answer would double a quiz.
// 10, 100, 1000, then 10^4 and up.
std::string power_words(int exponent) {
  return exponent <= 3 ? fmt::format("{:g}", std::pow(10.0, exponent))
                       : fmt::format("10^{}", exponent);
}

std::optional<std::string> power_of_ten_off(const Finding& f) {
  const auto& k = f.expected;
  if (k.empty() || k.size() != f.typed.size()) return std::nullopt;
  const std::size_t largest = static_cast<std::size_t>(
      std::max_element(k.begin(), k.end(),
                       [](double a, double b) { return std::abs(a) < std::abs(b); }) -
      k.begin());
  const double ratio = f.typed[largest] / k[largest];
  if (!(ratio > 0) || !std::isfinite(ratio)) return std::nullopt;
  const int exponent = static_cast<int>(std::lround(std::log10(ratio)));
  if (exponent == 0 || std::abs(exponent) > 9) return std::nullopt;
  if (!f.all_close(f.typed, times(k, std::pow(10.0, exponent)))) return std::nullopt;
  // An example of the conversion in this answer's unit: a moment of inertia's, or a length's.
  const auto& dim = f.key_unit.dim;
  const std::string example = dim[0] == 1 && dim[1] == 2 ? ": 1 g cm² = 10⁻⁷ kg m²"
                              : dim[1] != 0              ? ": 1 cm = 10⁻² m"
                                                         : "";
  return fmt::format(
      "this is {} the answer: a power of ten is off (a prefix, or a unit converted the wrong "
      "way{}?)",
      exponent > 0 ? power_words(exponent) + " times" : "1/" + power_words(-exponent) + " of",
      example);
}
// The right entries in other places: a matrix's transpose (rows for columns; for a rotation,
// its inverse), or a vector's entries in another order (x for z). Not for principal moments,
// judged in any order.
std::optional<std::string> entries_moved(const Finding& f) {
  const Value& shape = f.answer.value;
  const auto& k = f.expected;
  // Within the tolerance of the answer itself (an expression judged more strictly), nothing
  // moved: a symmetric matrix is its own transpose.
  if (f.answer.kind == AnswerKind::principal_moments || k.size() != f.typed.size() ||
      f.all_close(f.typed, k)) {
    return std::nullopt;
  }
  if (shape.shape == Value::Shape::matrix && shape.rows == shape.cols && k.size() > 1) {
    std::vector<double> transposed(k.size());
    for (std::size_t r = 0; r < shape.rows; ++r) {
      for (std::size_t c = 0; c < shape.cols; ++c)
        transposed[c * shape.cols + r] = k[r * shape.cols + c];
    }
    if (f.all_close(f.typed, transposed)) {
      return "this is the transpose of the answer: its rows are the answer's columns (for a "
             "rotation, the inverse one: from the body to space, or back?)";
    }
    return std::nullopt;
  }
  // A vector of three, or a pair (the racket's (Ω₃, Ω₁) about e₂, told the other way round).
  if (shape.shape != Value::Shape::vector || k.size() < 2 || k.size() > 3) return std::nullopt;
  std::vector<std::size_t> order(k.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  while (std::next_permutation(order.begin(), order.end())) {
    std::vector<double> moved(k.size());
    for (std::size_t i = 0; i < k.size(); ++i) moved[i] = k[order[i]];
    if (!f.all_close(f.typed, moved)) continue;
    std::vector<std::size_t> out_of_place;
    for (std::size_t i = 0; i < k.size(); ++i) {
      if (order[i] != i) out_of_place.push_back(i);
    }
    if (out_of_place.size() == 2) {
      return fmt::format("the right entries in another order: {} and {} are swapped",
                         entry_name(f.answer, out_of_place[0]),
                         entry_name(f.answer, out_of_place[1]));
    }
    return "the right entries in another order (the axes relabelled?)";
  }
  return std::nullopt;
}

// typed / expected where that is 10 or more in size, or 1/10 or less: far off, a ratio says more
// than a percentage ("308 times the answer", not "off by 3.07e+04%"; "0.0123 times", not "off
// by 98.8%"); nullopt nearer, or where either is zero.
constexpr double kFarOff = 10;
std::optional<double> far_off_ratio(double typed, double expected) {
  if (typed == 0.0 || expected == 0.0) return std::nullopt;
  const double ratio = typed / expected;
  if (std::abs(ratio) < kFarOff && std::abs(ratio) > 1 / kFarOff) return std::nullopt;
  return ratio;
}
}  // namespace

std::vector<std::string> diagnose(const Finding& f) {
  for (const auto& wrong : wrong_answers(f.answer, f.key, f.key_unit)) {
    if (f.all_close(f.typed, wrong.values)) return {wrong.message};
  }
  if (auto message = power_of_ten_off(f)) return {*message};
  if (auto message = entries_moved(f)) return {*message};
  const auto& v = f.typed;
  const auto& k = f.expected;
  std::vector<std::string> out;
  if (v.size() == 1) {
    // A zero (an identity's residual) has no size to be off by a percentage of.
    if (!(std::abs(k[0]) > kRoundingZero * f.zero_scale)) return {"the answer is zero"};
    if (const auto ratio = far_off_ratio(v[0], k[0])) {
      out.push_back(fmt::format("{:.3g} times the answer", *ratio));
    } else {
      out.push_back(fmt::format("off by {:.3g}% of the answer",
                                100 * std::abs(v[0] - k[0]) / std::max(std::abs(k[0]), 1e-300)));
    }
    return out;
  }
  // Zeros where the answer has none (dω/dt = 0 for a free body, "no torque, so ω is
  // constant"): one line, not each entry "off by 100%".
  const auto is_zero = [](double x) { return x == 0.0; };
  if (std::all_of(v.begin(), v.end(), is_zero) && !std::all_of(k.begin(), k.end(), is_zero))
    return {"every entry is zero; the answer is not"};
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (f.close(v[i], k[i])) continue;
    // One component's sign turned (a cross product's term, a minus lost in a matrix): its size
    // is right, and 200% off would hide that.
    if (k[i] != 0.0 && f.close(-v[i], k[i])) {
      out.push_back(entry_name(f.answer, i) + " has the wrong sign");
      continue;
    }
    if (const auto ratio = far_off_ratio(v[i], k[i])) {
      out.push_back(
          fmt::format("{} is {:.3g} times its right value", entry_name(f.answer, i), *ratio));
      continue;
    }
    out.push_back(fmt::format("{} is off by {:.3g}%", entry_name(f.answer, i),
                              100 * std::abs(v[i] - k[i]) / (k[i] != 0 ? std::abs(k[i]) : f.zero_scale)));
  }
  return out;
}

std::optional<std::string> reciprocal_mistake(
    const Answer& answer, double typed, const Unit* unit, const Unit& key_unit, double zero_scale,
    const std::function<bool(double typed, double expected)>& close) {
  constexpr std::array<int, 3> kTime{0, 0, 1};
  constexpr std::array<int, 3> kRate{0, 0, -1};
  // A number without its unit is in the key's unit; only where that is SI is it the SI
  // reciprocal's.
  if (unit == nullptr && key_unit.to_si != 1.0) return std::nullopt;
  Unit si;
  for (std::size_t i = 0; i < 3; ++i) si.dim[i] = -key_unit.dim[i];
  const Unit& typed_unit = unit != nullptr ? *unit : si;
  const bool rate_key = key_unit.dim == kRate && typed_unit.dim == kTime;
  const bool time_key = key_unit.dim == kTime && typed_unit.dim == kRate;
  if (answer.value.data.size() != 1 || typed == 0.0 || !(rate_key || time_key)) return std::nullopt;
  // A zero left by rounding: its reciprocal is no quantity anyone computes.
  if (!(std::abs(answer.value.data[0]) > kRoundingZero * zero_scale)) return std::nullopt;
  // Hz, rpm and rev/s have 2π in their factor to SI (symbolic/units.hpp): a revolution is 2π.
  const bool turns = typed_unit.angle && typed_unit.to_si_exact.find("2*pi") != std::string::npos;
  const bool degrees =
      typed_unit.angle && !turns && typed_unit.to_si_exact.find("pi") != std::string::npos;
  const double typed_si = typed * typed_unit.to_si;
  for (const double factor : {1.0, 2 * M_PI}) {
    const bool period = factor != 1.0;
    // 1/(2π f), and 1/x of a rate in deg/s taken in rad/s: no quantity a student means.
    if (!period && (turns || degrees)) continue;
    const double in_key = factor / typed_si / key_unit.to_si;
    if (!close(in_key, answer.value.data[0])) continue;
    // 2π over a rate in turns is one over it in turns: "1/(1.45 Hz)".
    const std::string over = period && !turns ? "2π" : "1";
    const std::string what = rate_key ? (period ? "the period given for the rate"
                                                : "a time given for the rate (its reciprocal)")
                                      : (period ? (turns ? "the frequency given for the period"
                                                         : "the rate given for the period")
                                                : "a rate or frequency given for the time (its "
                                                  "reciprocal)");
    const std::string given = unit != nullptr
                                  ? fmt::format("({:.4g} {})", typed, sym::to_unicode(unit->text))
                              : typed < 0 ? fmt::format("({:.4g})", typed)  // "2π/(-2.519)"
                                          : fmt::format("{:.4g}", typed);
    return fmt::format("{}/{} = {:.4g} {} is the answer: {}?", over, given, in_key,
                       sym::to_unicode(answer.unit), what);
  }
  return std::nullopt;
}

}  // namespace wobble::check
