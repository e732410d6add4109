#pragma once
/// @file
/// An answer's text as typed, in the reader's notation: ASCII (sym::to_ascii: Unicode letters,
/// sub- and superscripts, primes), on one line, as the expression reader reads it. What a hand,
/// a PDF or a program writes otherwise is rewritten here: angle brackets and Mathematica's braces
/// as square ones, arc marks after a number (12' 30"), magnitudes in bars (|x|, ‖x‖) as abs(x),
/// programs' calls and wrappers (check/program_notation.hpp, NumPy's scalars, "$..$" delimiters),
/// diag(..) as its rows, Python's "**", a space before a call's bracket ("cos (θ)"), a root of
/// a number without brackets (√2), a function's power before its argument (sin²θ), "× 10⁻⁴",
/// a signed exponent in brackets ("10^-4" -> "10^(-4)"), and a Greek letter set apart from the
/// name or number beside it ("Hω" is H times ω, never a name "Homega"). Nothing here knows the
/// problem's symbols: splitting names run together and writing the '*' of products is the
/// reader's (answer_reading.hpp).
#include <string>
#include <vector>

namespace wobble::check {

/// The functions an answer may call with or without brackets about a one-factor argument, in
/// GiNaC's names ("sin", .., "sqrt": "cos θ", "cos (θ)", "sin²θ").
const std::vector<std::string>& bare_call_functions();

/// `typed` in the reader's notation, as above; `field` names the input in a message.
std::string prepared(const std::string& typed, const std::string& field);

}  // namespace wobble::check
