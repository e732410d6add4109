#pragma once
/// @file
/// Characters of UTF-8 text, named in messages: what a person typed is shown as typed, except
/// what would drive a terminal (the C0 and C1 controls and DEL: ESC starts a command) and bytes
/// that are no UTF-8. Decoding is Boost.Locale's (boost/locale/utf.hpp, header-only).
#include <cstddef>
#include <string>

namespace wobble {

/// The character that starts at byte i, as a message names it: "'é' (U+00E9)", "the control
/// character U+001B", "the byte 0xC3, which is no UTF-8". Its length in bytes goes to `bytes`
/// if given (1 for a byte that is no UTF-8).
std::string character_name(const std::string& text, std::size_t i, std::size_t* bytes = nullptr);

/// `s` without the spaces, tabs and line ends around it.
std::string trim(const std::string& s);

/// ASCII letters and digits only, whatever the locale (a byte of UTF-8 is neither).
bool is_letter(char c);
bool is_digit(char c);

/// `s` with its ASCII letters in lower case (a command or a name typed in any case).
std::string ascii_lower(std::string s);

/// Whether `text` starts with UTF-16's byte-order mark, either way round: what Windows' Notepad
/// saves as "Unicode" where UTF-8 is read.
bool starts_as_utf16(const std::string& text);

/// Whether a control character (C0, DEL or C1) starts at byte i: what a terminal may obey.
bool is_control_at(const std::string& text, std::size_t i);

/// The columns `text` takes in a terminal: its characters less the combining marks, so "ψ̇" (ψ
/// and U+0307) is one and "kg m²" five; a byte that is no UTF-8 is one ('?' where shown).
std::size_t columns(const std::string& text);

/// `text` for a one-line message: each control character and each byte that is no UTF-8 as '?',
/// at most `max_characters` characters, then "...".
std::string printable(const std::string& text, std::size_t max_characters);

/// Whether `typed` is a number written with a decimal comma: digits, one comma, digits (and an
/// exponent), then a unit if any, after a space or glued on ("0,0812", "-0,16 s", "9,375e-2",
/// "15,5deg", "15,5°"). Where a number is
/// wanted, a message can then say so (as a vector, "0,16" would be two entries).
bool looks_like_decimal_comma(const std::string& typed);
/// The commas in `typed` with a digit right before and right after ("0,57" but not "1, 2"):
/// in a vector or matrix written with decimal commas, each such comma splits one entry in two.
std::size_t commas_between_digits(const std::string& typed);
/// The number `typed` starts with, its digits written without the separators that group them by
/// threes, if they are so grouped ("26 233 128.66 s", thin or no-break spaces alike, "26 233
/// 128,66" and "26,233,128.66" all give "26233128.66"); "" otherwise. One comma alone ("1,234")
/// is left to looks_like_decimal_comma: it may be either. What follows the number may be a unit.
std::string digits_ungrouped(const std::string& typed);
/// Where looks_like_decimal_comma holds and the comma may as well group thousands (one to three
/// digits, no leading 0, before it; three and no exponent after it: "437,200 min"), the digits
/// without it ("437200"); "" otherwise ("0,160", "1600,500", "1,6000", "1,600e-3").
std::string decimal_comma_or_grouping(const std::string& typed);
/// What a message adds in parentheses where looks_like_decimal_comma holds.
inline constexpr const char* kDecimalCommaHint = "a decimal comma? write the point: 0.5, not 0,5";

}  // namespace wobble
