#pragma once
/// @file
/// A number glued to a name, as typed and as calculators and books write a product: "2pi",
/// "2π/3" (read into ASCII first), "3sin(x)", "2sqrt(3)". Against pi or a function's name it is
/// a product whatever the symbols; against a symbol, the reader that knows the symbols decides
/// (where m is a mass, "2m" may be two metres). A number's exponent is no name: "1e-3", "2E5".
/// ASCII text.
#include <cstddef>
#include <string>

namespace wobble::sym {

/// `ascii` with a '*' between each number (or closing bracket) and the pi or function name glued
/// to it: "2pi/3" -> "2*pi/3", "3sin^2(a)" -> "3*sin^2(a)", "(1/3)pi" -> "(1/3)*pi"; "theta0pi"
/// and "1e-3" unchanged.
std::string numbers_times_constants(const std::string& ascii);

/// Whether `text` ends in a number of its own, not in the digits that end a name ("theta0").
bool ends_in_number(const std::string& text);

/// Whether the letter at `at`, after a number, starts its exponent ("1e-3", "2E5").
bool starts_exponent(const std::string& s, std::size_t at);

/// The name (letters, digits, '_') that starts s at `at`.
std::string name_at(const std::string& s, std::size_t at);

}  // namespace wobble::sym
