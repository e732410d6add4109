#pragma once
/// @file
/// siunitx's quantities, as physics students write them in LaTeX, rewritten to the LaTeX the
/// answer reader takes (latex_answer.hpp):
/// - \num{7.2e-4} -> "7.2e-4" (exponent markers e, E, d, D; "x" for times before a power of ten;
///   spaces, \, and {,} inside dropped);
/// - \SI{7.2e-4}{\kilo\gram\metre\squared} (siunitx 2) and \qty{..}{..} (siunitx 3) ->
///   "7.2e-4\,\mathrm{kg\,m^{2}}"; \si{..} and \unit{..} -> "\mathrm{..}";
/// - units as macros: the prefixes \giga \mega \kilo \centi \milli \micro \nano, the units
///   \gram \kilogram \metre \meter \second \minute \hour \day \radian \degree \arcminute
///   \arcsecond \joule \newton \hertz, and \per (the next unit in the denominator), \squared
///   \cubed (the last unit's power), \square \cubic (the next unit's), \tothe{n} \raiseto{n};
///   or as text, "kg.m^2", "kg m^2", "rad/s";
/// - \ang{44;41;37} (degrees; minutes and seconds of arc below 60, symbolic/units.hpp) ->
///   "\left(44 + 41/60 + 37/3600\right)\,\mathrm{deg}".
/// An option in brackets after the command ("\SI[per-mode=symbol]{..}{..}") is skipped.
#include <string>

namespace wobble::check {

/// `latex` with each siunitx command rewritten as above; `latex` itself where it has none.
/// @throws InputError naming `field` for a siunitx command whose braces are missing or whose
///   unit has a macro outside the list above (named).
std::string siunitx_as_latex(const std::string& latex, const std::string& field);

}  // namespace wobble::check
