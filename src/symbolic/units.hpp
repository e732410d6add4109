#pragma once
/// @file
/// Units of students' answers and of parameter values (`--set R=5 cm`): a small, strict grammar
/// (Debian has no units library for C++).
///
/// A unit is a product of names with integer powers, '/' putting what follows in the
/// denominator: "kg m^2", "kg*m^2/s", "rad/s", "m/s^2", "deg", "rev/s", "1/s" (or "s^-1"), in one
/// pair of brackets or not ("[kg m^2]", "(rad/s)", as a table's heading writes a unit). A
/// second '/' or "per" divides too: "m/s/s" and "metres per second per second" are m/s², "J/kg
/// s" and "J/kg/s" alike J/(kg s).
/// Names: kg, g; m, cm, mm; s, ms, min, h, day (days), week, sidereal day (two words, 86164.0905
/// s), yr (the Julian year); rad, deg, arcmin,
/// arcsec, rev; J, N, Hz, rpm, rps; and an SI prefix (G, M, k, m, mu or u, n) on g, m, s, J, N and
/// Hz, and m, mu or u, n on rad ("kJ", "mN", "mus" for µs, "mrad"), where the whole name is no
/// unit of its own (min is minutes). An unknown name, a missing or non-integer power is an error.
///
/// Radians, one rule everywhere: an angle is a pure number, so rad/s and 1/s are the same unit
/// and a radian converts as 1; a degree is pi/180 and a revolution 2 pi. Hz and rpm count
/// revolutions (cycles) per time: 1 Hz = 1 rev/s = 2 pi rad/s = 2 pi 1/s, whatever the rate
/// (a precession rate, a spin, a growth rate). An angle unit is refused only where the key is a
/// pure number that is no angle (k^2, a direction cosine): judge.cpp.
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace wobble {

struct Unit {
  double to_si = 1.0;  ///< multiply a value in this unit by this to get SI
  /// The same factor exactly, as a constant expression ("(1/100)^(2)", "(pi/180)^(1)"): a value
  /// converted through it is rounded once (30 deg is the double nearest pi/6).
  std::string to_si_exact = "1";
  std::array<int, 3> dim{0, 0, 0};  ///< powers of kg, m, s
  bool angle = false;               ///< contains rad, deg, rev, Hz or rpm
  std::string text;                 ///< as read, without a pair of brackets around it
  bool same_dimension(const Unit& o) const { return dim == o.dim; }
  /// "mass × length² / time", for messages (in the key's notation, as its units are printed).
  std::string dimension_words() const;
};

/// @throws InputError naming `field` and the text for anything outside the grammar.
Unit parse_unit(const std::string& text, const std::string& field);

/// "(44 + 41/60 + 37/3600) deg" for "44 deg 41 arcmin 37 arcsec" (the ASCII of "44° 41′ 37″";
/// "'" and '"' as well as arcmin and arcsec), a sign before it outside the bracket; `ascii` itself
/// when the whole of it is no such angle. For answers and parameter values alike.
/// @throws InputError naming `field` for minutes or seconds of 60 or more ("30°75′"): a count
///   that runs over is a slip in writing the angle, and its reading would be a guess.
std::string sexagesimal_degrees(const std::string& ascii, const std::string& field);

/// "(303*(86400) + 15*(3600)) s" for "303 days 15 h": a quantity in parts, as durations are
/// told ("1 h 30 min", "2 min 5 s"), each a plain number and one unit's name, of one dimension,
/// the largest first, written as their sum in the SI unit (exactly, through to_si_exact); a sign
/// before it outside the bracket. `ascii` itself when the whole of it is no such quantity (one
/// part, or parts that are not as above). Angles in degrees and minutes: sexagesimal_degrees.
std::string compound_quantity(const std::string& ascii);

/// The SI unit of `unit`'s dimension as the grammar reads it: "kg m^2 s^-1"; "rad" first for an
/// angle or a rate of one ("rad s^-1" for rpm); "" for a pure number.
std::string si_unit_text(const Unit& unit);

/// True if `text` reads as a unit (no throw).
bool is_unit(const std::string& text);

/// A word that is unit names run together, written apart: "kgm" -> "kg m", "Nms" -> "N m s"
/// (the shortest name first: "ms" there is m s); the word itself if it is one name; "" if it is
/// none of these, or longer than 16 characters.
std::string units_apart(const std::string& word);

/// Whether `word` is no unit but unit names run together, which units_apart writes apart
/// ("kgm", "Nms", "kgm2"; not "kg", "m2" or "mN", which are units).
bool units_run_together(const std::string& word);

/// A value and the unit after it, "" if none: the longest tail that reads as a unit and starts
/// a word ("0.05 m", "5cm", "9.81 m/s^2", "150 1/s", "5 [cm]", "(90 - 15)deg"; not the "i" of
/// "2*pi"). Both trimmed; the value is not read here. ASCII text (sym::to_ascii first).
std::pair<std::string, std::string> split_value_unit(const std::string& text);

/// Every such split, the longest unit first: "100*g cm/s^2" is 100* in g cm/s^2, then 100*g in
/// cm/s^2 (for a reader that knows which values read: a parameter g, symbolic/quantity.hpp).
std::vector<std::pair<std::string, std::string>> value_unit_splits(const std::string& text);

/// Whether a value given in `given` may stand for one in `wanted`: the same dimension, and no
/// angle for a pure number that is no angle (radians are pure numbers, so rad/s is 1/s, but
/// "30deg" is no moment ratio). A pure number `wanted` is Unit{}; an angle is parse_unit("rad").
bool unit_fits(const Unit& given, const Unit& wanted);

/// What a field that takes SI `si_unit` (parsed: `wanted`) must be, for a refusal that says what
/// was given: "an angle (rad, deg or rev)", "a pure number", "in rad/s (1 / time)". Only an angle
/// of no dimension is "an angle": a rate, rad/s, is a time's inverse (5 rad is no spin).
std::string unit_wanted_words(const Unit& wanted, const std::string& si_unit);

}  // namespace wobble
