#include "check/judge.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "check/text.hpp"
#include "check/units.hpp"
#include "core/inertia.hpp"
#include "core/input_error.hpp"
#include "symbolic/value_text.hpp"

namespace wobble::check {

namespace {
const std::string kField = "--answer";

struct Parsed {
  sym::ValueText value;
  std::optional<Unit> unit;
  bool symbolic = false;
};

bool has_symbols(const GiNaC::ex& e) {
  return !GiNaC::is_a<GiNaC::numeric>(GiNaC::evalf(e));
}

Parsed parse_answer(const std::string& raw, const sym::SymbolTable& table) {
  const std::string text = trim(raw);
  if (text.empty()) {
    throw InputError(kField +
                     ": empty; type a number (with a unit if you like), a vector [x, y, "
                     "z], a matrix [[..], [..], [..]] or an expression");
  }
  std::string value = text, unit;
  if (text.front() == '[') {
    const auto close = text.find_last_of(']');
    if (close == std::string::npos) throw InputError(kField + ": '" + text + "': no closing ']'");
    value = text.substr(0, close + 1);
    unit = trim(text.substr(close + 1));
  } else {
    // The shortest value before a unit: "0.21 kg m^2", "3.1 rad/s", "12 deg".
    for (std::size_t sp = text.find(' '); sp != std::string::npos; sp = text.find(' ', sp + 1)) {
      const std::string right = trim(text.substr(sp + 1));
      if (is_unit(right)) {
        value = trim(text.substr(0, sp));
        unit = right;
        break;
      }
    }
  }
  Parsed p;
  try {
    p.value = sym::parse_value_text(value, table, kField);
  } catch (const InputError& e) {
    // "0.16 parsecs": a value and something that is not a unit; say so, not "cannot read".
    if (const auto sp = value.find(' '); sp != std::string::npos) {
      bool left_reads = true;
      try {
        (void)sym::parse_value_text(trim(value.substr(0, sp)), table, kField);
      } catch (const InputError&) {
        left_reads = false;
      }
      if (left_reads) (void)parse_unit(trim(value.substr(sp + 1)), kField);  // throws its error
    }
    const bool glued = !value.empty() && std::isdigit(static_cast<unsigned char>(value[0])) &&
                       value.find(' ') == std::string::npos &&
                       value.find_first_of("*/+-^()") == std::string::npos &&
                       std::any_of(value.begin(), value.end(), [](char c) {
                         return std::isalpha(static_cast<unsigned char>(c));
                       });
    const bool refused = std::string(e.what()).find("is refused") != std::string::npos;
    throw InputError(
        std::string(e.what()) +
        (glued && !refused ? " (put a space between a number and its unit: '0.21 kg m^2')" : ""));
  }
  if (!unit.empty()) p.unit = parse_unit(unit, kField);
  for (const auto& e : p.value.entries) p.symbolic = p.symbolic || has_symbols(e);
  if (p.symbolic && p.unit) {
    throw InputError(kField +
                     ": an expression in the problem's symbols is in SI already; drop "
                     "the unit '" +
                     unit + "'");
  }
  return p;
}

std::string shape_words(std::size_t rows, std::size_t cols, bool vector, bool matrix) {
  if (matrix) return fmt::format("a {}x{} matrix [[..], ..]", rows, cols);
  if (vector) return fmt::format("a {}-vector [..]", rows);
  return "a number";
}

void check_shape(const Answer& a, const sym::ValueText& v) {
  const bool key_vec = a.value.shape == Value::Shape::vector;
  const bool key_mat = a.value.shape == Value::Shape::matrix;
  if (key_vec != v.is_vector || key_mat != v.is_matrix || a.value.data.size() != v.entries.size()) {
    throw InputError(fmt::format("{}: {} wants {}, not {}", kField, a.name,
                                 shape_words(a.value.rows, a.value.cols, key_vec, key_mat),
                                 shape_words(v.rows, v.cols, v.is_vector, v.is_matrix)));
  }
}

std::string entry_name(const Answer& a, std::size_t i) {
  if (a.value.shape == Value::Shape::vector) {
    // Moments are compared in increasing order: name them by rank, not by an axis.
    if (a.name.rfind("principal_moments", 0) == 0 && a.value.data.size() == 3) {
      return std::string("the ") + std::array<const char*, 3>{"smallest", "middle", "largest"}[i] +
             " moment";
    }
    return "entry " + (a.value.data.size() == 3 ? std::string(1, "xyz"[i]) : std::to_string(i + 1));
  }
  return fmt::format("entry ({}, {})", i / a.value.cols + 1, i % a.value.cols + 1);
}

// The largest value of the same unit in the key: the scale a zero is judged against.
double zero_scale(const Key& key, const Answer& a) {
  double s = 0.0;
  for (const auto& part : key.parts) {
    for (const auto& b : part.answers) {
      if (b.unit != a.unit) continue;
      for (double x : b.value.data) s = std::max(s, std::abs(x));
    }
  }
  return s > 0.0 ? s : 1.0;
}

struct Judge {
  const Context& ctx;
  const Answer& a;
  const Options& opt;
  double scale;

  bool close(double v, double k) const {
    if (opt.sigfigs) {
      const double ref = k != 0.0 ? std::abs(k) : scale;
      const double place = std::pow(10.0, std::floor(std::log10(ref)) - *opt.sigfigs + 1);
      return std::abs(v - k) <= 0.5 * place * (1 + 1e-9);
    }
    return std::abs(v - k) <= opt.rel_tol * (k != 0.0 ? std::abs(k) : scale);
  }
  bool all_close(const std::vector<double>& v, const std::vector<double>& k) const {
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (!close(v[i], k[i])) return false;
    }
    return true;
  }
  std::vector<double> scaled(const std::vector<double>& k, double f) const {
    std::vector<double> out = k;
    for (double& x : out) x *= f;
    return out;
  }
};

// Principal axes: columns right up to sign; in a degenerate pair, any orthonormal pair of the
// plane (orthogonal to the unique axis).
bool axes_match(const Judge& j, const std::vector<double>& v, const std::vector<double>& k) {
  const Answer* moments = nullptr;
  const std::string suffix = j.a.name.substr(std::string("principal_axes").size());
  for (const auto& part : j.ctx.key.parts) {
    for (const auto& b : part.answers) {
      if (b.name == "principal_moments" + suffix) moments = &b;
    }
  }
  const auto col = [](const std::vector<double>& m, int c) {
    return Vec3(m[static_cast<std::size_t>(c)], m[static_cast<std::size_t>(3 + c)],
                m[static_cast<std::size_t>(6 + c)]);
  };
  const auto same = [&](int a, int b) {
    if (moments == nullptr) return false;
    const double x = moments->value.data[static_cast<std::size_t>(a)],
                 y = moments->value.data[static_cast<std::size_t>(b)];
    return std::abs(x - y) <= 1e-12 * std::max(std::abs(x), std::abs(y));
  };
  for (int c = 0; c < 3; ++c) {
    const Vec3 vc = col(v, c), kc = col(k, c);
    bool in_pair = false;
    for (int d = 0; d < 3; ++d) in_pair = in_pair || (d != c && same(c, d));
    if (in_pair) {
      int unique = 0;
      while (unique < 3 && (unique == c || same(c, unique))) ++unique;
      const bool unit = std::abs(vc.norm() - 1.0) <= j.opt.rel_tol;
      const bool ortho = unique >= 3 || std::abs(vc.dot(col(k, unique))) <= j.opt.rel_tol;
      if (!unit || !ortho) return false;
      continue;
    }
    const auto close3 = [&](const Vec3& x) {
      for (int i = 0; i < 3; ++i) {
        if (std::abs(x[i] - kc[i]) > j.opt.rel_tol * std::max(std::abs(kc[i]), 1.0)) return false;
      }
      return true;
    };
    if (!close3(vc) && !close3(-vc)) return false;
  }
  return true;
}

// "L_body" -> ("L", "body"): the stem and the frame of an answer's name, for the frames a key
// names (body, space, and the intermediate "primed" frame of Euler angles).
std::optional<std::pair<std::string, std::string>> frame_of(const std::string& name) {
  for (const std::string frame : {"body", "space", "primed"}) {
    const std::string suffix = "_" + frame;
    if (name.size() > suffix.size() &&
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) {
      return std::make_pair(name.substr(0, name.size() - suffix.size()), frame);
    }
  }
  return std::nullopt;
}

// The likely mistake behind a wrong number, or its size.
std::vector<std::string> diagnose(const Judge& j, const Unit& key_unit,
                                  const std::vector<double>& v, const std::vector<double>& k) {
  std::vector<std::string> out;
  const bool matrix = j.a.value.shape == Value::Shape::matrix;
  if (matrix && v.size() == 9) {
    std::vector<double> flipped = k;
    for (std::size_t i = 0; i < 9; ++i) {
      if (i / 3 != i % 3) flipped[i] = -flipped[i];
    }
    if (j.all_close(v, flipped)) {
      out.push_back(
          "the products of inertia have the wrong sign: I_xy = -sum m x y (so that "
          "L = I w)");
      return out;
    }
  }
  if (j.all_close(v, j.scaled(k, -1.0))) {
    out.push_back(j.a.name.find("Omega") != std::string::npos
                      ? "the sense is reversed: the precession runs the other way (check prolate, "
                        "I3 < I1, against oblate, I3 > I1)"
                      : "the sign is reversed");
    return out;
  }
  if (key_unit.angle && key_unit.dim == std::array<int, 3>{0, 0, 0} &&
      j.all_close(v, j.scaled(k, 180.0 / M_PI))) {
    out.push_back("this is the angle in degrees: give radians, or write the unit (12 deg)");
    return out;
  }
  if (key_unit.angle && key_unit.dim == std::array<int, 3>{0, 0, -1} &&
      j.all_close(v, j.scaled(k, 1.0 / (2 * M_PI)))) {
    out.push_back("this is revolutions per second: multiply by 2 pi for rad/s, or write rev/s");
    return out;
  }
  // The same vector in another frame: "L_body" answered for "L_space" and the like.
  if (const auto mine = frame_of(j.a.name)) {
    for (const auto& part : j.ctx.key.parts) {
      for (const auto& b : part.answers) {
        const auto theirs = frame_of(b.name);
        if (!theirs || theirs->first != mine->first || theirs->second == mine->second ||
            b.value.data.size() != v.size() || !j.all_close(v, b.value.data)) {
          continue;
        }
        out.push_back("these are the " + theirs->second + "-frame components (" + b.name + "); " +
                      j.a.name + " asks for the " + mine->second + "-frame ones");
        return out;
      }
    }
  }
  // Another answer of the key first: it is the more specific diagnosis (max_angle is exactly
  // twice angle_L_e3, L0_space is L0_body turned).
  for (const auto& part : j.ctx.key.parts) {
    for (const auto& b : part.answers) {
      if (&b == &j.a || b.unit != j.a.unit || b.value.data.size() != v.size()) continue;
      if (j.all_close(v, b.value.data)) {
        out.push_back("this is " + b.name + " (part " + part.id + "), not " + j.a.name);
        return out;
      }
    }
  }
  for (const double f : {2.0, 0.5, 4.0, 0.25, 12.0, 1.0 / 12, 3.0, 1.0 / 3}) {
    if (j.all_close(v, j.scaled(k, f))) {
      const std::string factor =
          f >= 1 ? fmt::format("{:g} times", f) : fmt::format("1/{:g} of", 1 / f);
      out.push_back(
          fmt::format("this is {} the answer: a factor {:g} is off (a 1/12 or 1/3 "
                      "in a moment of inertia, a 1/2 in an energy?)",
                      factor, f >= 1 ? f : 1 / f));
      return out;
    }
  }
  if (v.size() == 1) {
    out.push_back(fmt::format("off by {:.3g}% of the answer",
                              100 * std::abs(v[0] - k[0]) / std::max(std::abs(k[0]), 1e-300)));
  } else {
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (!j.close(v[i], k[i])) {
        out.push_back(
            fmt::format("{} is off by {:.3g}%", entry_name(j.a, i),
                        100 * std::abs(v[i] - k[i]) / (k[i] != 0 ? std::abs(k[i]) : j.scale)));
      }
    }
  }
  return out;
}

Verdict judge_symbolic(const Context& ctx, const Answer& a, const Parsed& p, const Options& opt) {
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
  // The set values and three more points, each parameter scaled in turn.
  std::vector<sym::Values> points{ctx.values};
  const double factors[] = {1.13, 0.87, 1.29};
  for (int f = 0; f < 3; ++f) {
    sym::Values v = ctx.values;
    std::size_t i = 0;
    for (auto& [name, x] : v) x *= factors[(f + i++) % 3];
    points.push_back(v);
  }
  for (const auto& pt : points) {
    const GiNaC::lst at = sym::substitution(ctx.table, pt);
    for (std::size_t i = 0; i < key.entries.size(); ++i) {
      const double want = sym::evaluate(key.entries[i], at, "key " + a.name);
      const double got = sym::evaluate(p.value.entries[i], at, kField);
      if (std::abs(got - want) > 1e-9 * std::max(1.0, std::abs(want))) {
        // Wrong: say why as for a number, from both values at the set parameters.
        const GiNaC::lst here = sym::substitution(ctx.table, ctx.values);
        std::vector<double> mine;
        for (const auto& e : p.value.entries) mine.push_back(sym::evaluate(e, here, kField));
        const Unit key_unit = a.unit.empty() ? Unit{} : parse_unit(a.unit, "key unit of " + a.name);
        const Judge j{ctx, a, opt, zero_scale(ctx.key, a)};
        return {false, "incorrect: " + a.name + " (your expression differs from the key's)",
                diagnose(j, key_unit, mine, a.value.data)};
      }
    }
  }
  return {true,
          "correct: " + a.name +
              " (your expression equals the key's at the set values and three more points)",
          {}};
}
}  // namespace

Verdict judge(const Context& ctx, const Answer& a, const std::string& text,
              const Options& options) {
  // The problem file's tolerance for this answer, unless the user gave one.
  Options opt = options;
  if (!options.rel_tol_given && a.check_tolerance) opt.rel_tol = *a.check_tolerance;
  const Parsed p = parse_answer(text, ctx.table);
  check_shape(a, p.value);
  if (p.symbolic) return judge_symbolic(ctx, a, p, opt);
  const Unit key_unit = a.unit.empty() ? Unit{} : parse_unit(a.unit, "key unit of " + a.name);
  double to_key = 1.0;
  if (p.unit) {
    if (!p.unit->same_dimension(key_unit) || (p.unit->angle && !key_unit.angle)) {
      Verdict v;
      v.line = "incorrect: " + a.name + " has the wrong dimension";
      v.feedback.push_back("you gave " + p.unit->text + " (" + p.unit->dimension_words() +
                           "); the answer is in " + (a.unit.empty() ? "no unit" : a.unit) + " (" +
                           key_unit.dimension_words() + ")");
      return v;
    }
    to_key = p.unit->to_si / key_unit.to_si;
  }
  std::vector<double> got;
  for (const auto& e : p.value.entries)
    got.push_back(sym::evaluate(e, GiNaC::lst{}, kField) * to_key);
  std::vector<double> want = a.value.data;
  const Judge j{ctx, a, opt, zero_scale(ctx.key, a)};
  std::vector<double> compare = got;
  if (a.name.rfind("principal_moments", 0) == 0) std::sort(compare.begin(), compare.end());
  const bool right = a.name.rfind("principal_axes", 0) == 0 && got.size() == 9
                         ? axes_match(j, got, want)
                         : j.all_close(compare, want);
  if (right) {
    std::string note;
    if (a.name.rfind("principal_moments", 0) == 0 && compare != got) note = " (in any order)";
    return {true, "correct: " + a.name + note, {}};
  }
  return {false, "incorrect: " + a.name, diagnose(j, key_unit, compare, want)};
}

}  // namespace wobble::check
