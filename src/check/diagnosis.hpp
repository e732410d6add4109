#pragma once
/// @file
/// Diagnosing a wrong number: which known mistake it is, else how far off each entry is. Each
/// known mistake is a row that gives the wrong answers it leads to (the key's value turned by
/// the mistake) with their message; a typed value close to one of them is that mistake. The
/// same rows give the exports their wrong answers to recognise (export/graded_variants.hpp).
/// The judge (judge.hpp) decides that an answer is wrong and hands over what it found as data;
/// nothing here decides right or wrong.
///
/// The mistakes, tried in this order (the first that matches is named): products of inertia
/// with the wrong sign; a reversed sign (for a signed precession rate: what its sign means);
/// degrees for radians; degrees per second for rad/s; turns per second for rad/s; revolutions
/// per minute for rad/s; 2π times a rate (Hz taken as rad/s); the
/// components in another frame (answer kind and frame, solvers/key.hpp); another answer of the
/// key; a rotation's turns each taken the other way or in reverse order (from the key's exact
/// form at its angles negated); a factor 2, 1/2, 4, 1/4, 12, 1/12, 3 or 1/3. Then, by rule, every
/// entry a power of ten off; a square matrix's transpose; a 3-vector's entries in another order
/// (not principal moments, which may come in any). Else each wrong entry of a vector or matrix is
/// named: with the wrong sign where only its sign is wrong, else with how far off it is.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "solvers/key.hpp"
#include "symbolic/units.hpp"

namespace wobble::check {

/// What the judge found: the typed and expected values (SI, in the key's order), and how it
/// decides that two values agree (the tolerance of this answer).
struct Finding {
  const Answer& answer;
  const Key& key;  ///< for the other answers a wrong value may be
  std::vector<double> typed, expected;
  Unit key_unit;
  std::function<bool(double typed, double expected)> close;
  double zero_scale = 1.0;  ///< what a zero is judged against (judge.hpp)

  bool all_close(const std::vector<double>& v, const std::vector<double>& k) const;
};

/// A wrong answer that a known mistake leads to: its values (SI, in the key's order, as
/// Value::data) and what the judge says to it.
struct WrongAnswer {
  std::string mistake;  ///< the mistake's name
  std::vector<double> values;
  std::string message;
};

/// One known mistake: its name (for tests and the README) and the wrong answers it leads to for
/// an answer of a key (none where it does not apply: degrees for an answer that is no angle).
struct Mistake {
  std::string name;
  std::function<std::vector<WrongAnswer>(const Answer&, const Key&, const Unit& key_unit)>
      wrong_answers;
};

/// An entry's name in a message: by rank for principal moments (compared in increasing order),
/// as the question names it ("c₁"), by its frame's axis for a 3-vector ("entry z", "entry e₃"),
/// by position otherwise ("entry 2", "entry (1, 2)").
std::string entry_name(const Answer& a, std::size_t i);

/// The known mistakes, in the order they are tried.
const std::vector<Mistake>& known_mistakes();

/// Every known mistake's wrong answers for `answer` of `key`, in the order they are tried (the
/// first close to a typed value names it). None for principal axes: they are judged by meaning
/// (axes_judge.hpp).
std::vector<WrongAnswer> wrong_answers(const Answer& answer, const Key& key, const Unit& key_unit);

/// The first known mistake's message, else how far off the value (or each wrong entry) is.
std::vector<std::string> diagnose(const Finding& finding);

/// A time given for a rate or a rate for a time, where the other is right: `typed` (a number
/// in `unit`; null for none, the key's unit, where that is SI) for a one-number answer in
/// `key_unit`, with 1/x or 2π/x (a time constant or a period, the angle a pure number) `close`
/// to the key's value: "2π/(0.688 s) = 9.13 rad/s is the answer: the period given for the
/// rate?", "1/0.4593 = 2.177 s ..". A unit counting turns (Hz, rpm, rev/s) has its 2π in it, and
/// the period is written 1/f. nullopt otherwise (other dimensions too), and where the key's
/// value is a zero left by rounding beside `zero_scale` (judge.hpp), an identity's residual.
std::optional<std::string> reciprocal_mistake(
    const Answer& answer, double typed, const Unit* unit, const Unit& key_unit, double zero_scale,
    const std::function<bool(double typed, double expected)>& close);

}  // namespace wobble::check
