#pragma once
/// @file
/// Units of students' answers: a small, strict grammar (Debian has no units library for C++).
///
/// A unit is a product of names with integer powers, '/' putting what follows in the
/// denominator: "kg m^2", "kg*m^2/s", "rad/s", "m/s^2", "deg", "rev/s", "1/s" (or "s^-1").
/// Names: kg, g; m, cm, mm;
/// s, ms, min, h; rad, deg, rev (angles: dimensionless, but degrees and revolutions convert);
/// J, N, Hz, rpm. An unknown name, a missing or non-integer power is an error.
#include <array>
#include <string>

namespace wobble::check {

struct Unit {
  double to_si = 1.0;               ///< multiply a value in this unit by this to get SI
  std::array<int, 3> dim{0, 0, 0};  ///< powers of kg, m, s
  bool angle = false;               ///< contains rad, deg or rev (or rpm)
  std::string text;
  bool same_dimension(const Unit& o) const { return dim == o.dim; }
  /// "mass x length^2", for messages.
  std::string dimension_words() const;
};

/// @throws InputError naming `field` and the text for anything outside the grammar.
Unit parse_unit(const std::string& text, const std::string& field);

/// True if `text` reads as a unit (no throw).
bool is_unit(const std::string& text);

}  // namespace wobble::check
