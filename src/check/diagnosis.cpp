#include "check/diagnosis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace wobble::check {

bool Finding::all_close(const std::vector<double>& v, const std::vector<double>& k) const {
  if (v.size() != k.size()) return false;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!close(v[i], k[i])) return false;
  }
  return true;
}

std::vector<double> Finding::expected_times(double factor) const {
  std::vector<double> out = expected;
  for (double& x : out) x *= factor;
  return out;
}

namespace {
using Seen = std::optional<std::string>;

// The entry's name in a message: by rank for moments (compared in increasing order), by axis
// for a 3-vector, by position otherwise.
std::string entry_name(const Answer& a, std::size_t i) {
  if (a.value.shape == Value::Shape::vector) {
    if (a.kind == AnswerKind::principal_moments && a.value.data.size() == 3) {
      return std::string("the ") + std::array<const char*, 3>{"smallest", "middle", "largest"}[i] +
             " moment";
    }
    return "entry " + (a.value.data.size() == 3 ? std::string(1, "xyz"[i]) : std::to_string(i + 1));
  }
  return fmt::format("entry ({}, {})", i / a.value.cols + 1, i % a.value.cols + 1);
}

Seen products_of_inertia_sign(const Finding& f) {
  if (f.answer.value.shape != Value::Shape::matrix || f.typed.size() != 9) return {};
  std::vector<double> flipped = f.expected;
  for (std::size_t i = 0; i < 9; ++i) {
    if (i / 3 != i % 3) flipped[i] = -flipped[i];
  }
  if (!f.all_close(f.typed, flipped)) return {};
  return "the products of inertia have the wrong sign: I_xy = -sum m x y (so that L = I w)";
}

Seen reversed_sign(const Finding& f) {
  if (!f.all_close(f.typed, f.expected_times(-1.0))) return {};
  const bool precession = f.answer.sign == SignConvention::sense_of_precession;
  if (precession && f.typed.size() == 1) {
    // A signed rate given as its magnitude (or the sign flipped): the sign is the physics.
    const bool against = f.expected[0] < 0;
    return fmt::format(
        "the size is right but not the sign: {} is signed along e3, and {} here: the "
        "precession runs {} the spin ({}; check prolate, I3 < I1, against oblate, I3 > I1)",
        f.answer.name, against ? "negative" : "positive", against ? "against" : "with",
        against ? "a prolate body" : "an oblate body");
  }
  if (precession) {
    return "the sense is reversed: the precession runs the other way (check prolate, I3 < I1, "
           "against oblate, I3 > I1)";
  }
  return "the sign is reversed";
}

bool pure_angle(const Unit& u) { return u.angle && u.dim == std::array<int, 3>{0, 0, 0}; }
// Rates: rad/s and 1/s alike (units.hpp).
bool per_second(const Unit& u) { return u.dim == std::array<int, 3>{0, 0, -1}; }

Seen degrees_for_radians(const Finding& f) {
  if (!pure_angle(f.key_unit) || !f.all_close(f.typed, f.expected_times(180.0 / M_PI))) return {};
  return "this is the angle in degrees: give radians, or write the unit (12 deg)";
}

Seen turns_per_second(const Finding& f) {
  if (!per_second(f.key_unit) || !f.all_close(f.typed, f.expected_times(1.0 / (2 * M_PI)))) {
    return {};
  }
  return "this is revolutions per second: multiply by 2 pi for rad/s, or write rev/s";
}

Seen hertz_as_radians(const Finding& f) {
  if (!per_second(f.key_unit) || !f.all_close(f.typed, f.expected_times(2 * M_PI))) return {};
  return "this is 2 pi times the answer: Hz, rev/s and rpm count turns, so 1 Hz = 2 pi rad/s "
         "(the number in rad/s labelled Hz?)";
}

// The same vector in another frame: L0_body answered for L0_space and the like.
Seen other_frame(const Finding& f) {
  if (f.answer.frame == AnswerFrame::none) return {};
  for (const auto& part : f.key.parts) {
    for (const auto& b : part.answers) {
      if (b.frame == AnswerFrame::none || b.frame == f.answer.frame || b.unit != f.answer.unit ||
          !f.all_close(f.typed, b.value.data)) {
        continue;
      }
      return fmt::format("these are the {}-frame components ({}); {} asks for the {}-frame ones",
                         frame_name(b.frame), b.name, f.answer.name, frame_name(f.answer.frame));
    }
  }
  return {};
}

// Another answer of the key: more specific than a factor (max_angle is exactly twice
// angle_L_e3, L0_space is L0_body turned).
Seen other_answer(const Finding& f) {
  for (const auto& part : f.key.parts) {
    for (const auto& b : part.answers) {
      if (&b == &f.answer || b.unit != f.answer.unit) continue;
      if (f.all_close(f.typed, b.value.data)) {
        return "this is " + b.name + " (part " + part.id + "), not " + f.answer.name;
      }
    }
  }
  return {};
}

Seen factor_off(const Finding& f) {
  for (const double factor : {2.0, 0.5, 4.0, 0.25, 12.0, 1.0 / 12, 3.0, 1.0 / 3}) {
    if (!f.all_close(f.typed, f.expected_times(factor))) continue;
    const double whole = factor >= 1 ? factor : 1 / factor;
    return fmt::format(
        "this is {} the answer: a factor {:g} is off (a 1/12 or 1/3 in a moment of inertia, a "
        "1/2 in an energy?)",
        factor >= 1 ? fmt::format("{:g} times", whole) : fmt::format("1/{:g} of", whole), whole);
  }
  return {};
}
}  // namespace

const std::vector<Mistake>& known_mistakes() {
  static const std::vector<Mistake> table{
      {"products of inertia with the wrong sign", products_of_inertia_sign},
      {"a reversed sign", reversed_sign},
      {"degrees for radians", degrees_for_radians},
      {"turns per second for rad/s", turns_per_second},
      {"Hz taken as rad/s", hertz_as_radians},
      {"the components in another frame", other_frame},
      {"another answer of the key", other_answer},
      {"a factor off", factor_off},
  };
  return table;
}

std::vector<std::string> diagnose(const Finding& f) {
  for (const auto& mistake : known_mistakes()) {
    if (auto message = mistake.message_if_seen(f)) return {*message};
  }
  const auto& v = f.typed;
  const auto& k = f.expected;
  std::vector<std::string> out;
  if (v.size() == 1) {
    out.push_back(fmt::format("off by {:.3g}% of the answer",
                              100 * std::abs(v[0] - k[0]) / std::max(std::abs(k[0]), 1e-300)));
    return out;
  }
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (f.close(v[i], k[i])) continue;
    out.push_back(fmt::format("{} is off by {:.3g}%", entry_name(f.answer, i),
                              100 * std::abs(v[i] - k[i]) / (k[i] != 0 ? std::abs(k[i]) : f.zero_scale)));
  }
  return out;
}

}  // namespace wobble::check
