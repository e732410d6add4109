#pragma once
/// @file
/// Expressions in a problem's parameters: a symbol table, a strict parser, exact evaluation.
///
/// Symbols are declared with their sign (a mass or length is positive, an angle real) so that
/// GiNaC can simplify sqrt(m^2) = m. The table keeps declaration order, which the canonical
/// printer uses to order the factors of a product (so a key reads "m*a^2", as the file declares).
/// `pi` and `Pi` both name the constant.
#include <ginac/ginac.h>

#include <array>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/input_error.hpp"

namespace wobble::sym {

/// A malformed expression or one with an undefined symbol; what() names the field and the text.
/// An InputError, so every layer above can let it pass through to the command line.
struct ExpressionError : wobble::InputError {
  using wobble::InputError::InputError;
};

enum class SymbolSign { positive, real };

/// Limits on expression text: far above any textbook expression, far below what could exhaust
/// memory or the stack.
inline constexpr std::size_t kMaxExpressionLength = 10000;
inline constexpr int kMaxExpressionDepth = 100;

/// Names people write for functions GiNaC knows by another: each is read as the function it
/// stands for (ln(x) is log(x)), so an answer in either notation is the same expression.
inline constexpr std::array<std::pair<std::string_view, std::string_view>, 4> kFunctionAliases{
    {{"ln", "log"}, {"arcsin", "asin"}, {"arccos", "acos"}, {"arctan", "atan"}}};

/// Whether `s` can name a symbol: ASCII letters, digits and '_', not starting with a digit.
bool is_identifier(const std::string& s);

class SymbolTable {
 public:
  /// Declares a symbol. @throws std::invalid_argument if the name is taken or not an identifier.
  GiNaC::ex declare(const std::string& name, const std::string& latex, SymbolSign sign);
  /// @throws std::out_of_range for an undeclared name.
  const GiNaC::ex& at(const std::string& name) const;
  bool contains(const std::string& name) const { return index_.count(name) != 0; }
  /// LaTeX of a symbol (by its name); the name itself if none was given.
  std::string latex_of(const std::string& name) const;
  /// Position of a symbol in declaration order (for printing); the count of symbols for unknown
  /// names.
  std::size_t order_of(const std::string& name) const;
  const std::vector<std::string>& names() const { return names_; }
  /// Changes whenever the table does (a new table, a symbol declared), never coming back: what
  /// is printed with the table is kept under it (canonical_print.cpp). A copy keeps it.
  std::uint64_t version() const { return version_; }

  /// Parses `text` with only the declared symbols (and pi) allowed. Texts longer than
  /// kMaxExpressionLength or nested deeper than kMaxExpressionDepth are refused before GiNaC's
  /// recursive parser sees them (a 1e5-deep nesting would overflow the stack).
  /// @throws ExpressionError "FIELD: ..." naming the field, the text and what is wrong.
  GiNaC::ex parse(const std::string& text, const std::string& field) const;

  /// A symbol's dimension, as powers of kg, m and s, and a value of it (SI) at which a
  /// quantity's dimension is tested (parse_quantity, quantity.hpp).
  struct Dimension {
    std::array<int, 3> powers{0, 0, 0};
    double probe = 1.0;
  };
  /// @throws std::out_of_range for an undeclared name.
  void set_dimension(const std::string& name, const Dimension& dimension);
  /// Each symbol's dimension, by name; empty unless every symbol has one.
  std::map<std::string, Dimension> dimensions() const;

 private:
  std::vector<std::string> names_;
  std::vector<GiNaC::ex> symbols_;
  std::vector<std::string> latex_;
  std::map<std::string, std::size_t> index_;
  std::map<std::string, Dimension> dimensions_;
  std::uint64_t version_ = next_version();
  static std::uint64_t next_version();
};

/// Sets GiNaC's global precision (decimal digits) for a scope and restores it on exit.
struct DigitsGuard {
  long saved = static_cast<long>(GiNaC::Digits);
  explicit DigitsGuard(long digits) { GiNaC::Digits = digits; }
  ~DigitsGuard() { GiNaC::Digits = saved; }
  DigitsGuard(const DigitsGuard&) = delete;
  DigitsGuard& operator=(const DigitsGuard&) = delete;
};

/// Values of the parameters, by name (SI).
using Values = std::map<std::string, double>;

/// The exact number a parameter value stands for. Values travel as doubles; the exact route needs
/// what the user meant: a double equal to the correctly rounded value of r*pi (r rational with
/// denominator <= 720: "pi", "104.5deg", "pi/6") is taken as r*pi, any other as the decimal
/// of its shortest round-trip text ("0.1" -> 1/10). Non-finite values are rejected before here.
GiNaC::ex exact_value(double d);

/// Substitution list (symbol == exact_value(value)) for the given values.
GiNaC::lst substitution(const SymbolTable& table, const Values& values);

/// The value of e at the parameter values, evaluated with 40 significant digits then rounded
/// once to double, so a printed digit is right whenever the exact value rounds to it.
/// @throws ExpressionError if e does not evaluate to a finite real number.
double evaluate(const GiNaC::ex& e, const GiNaC::lst& at, const std::string& field);

/// The sign (-1 or +1) of e at the parameter values, for an e not identically zero there. Not
/// from the double value, which can underflow to 0 (a regime decided by a wobble of 1e-200
/// squared): evaluated with 40, then 120, 360, 1080 digits until two agree on the sign and on
/// the first two digits.
/// @throws ExpressionError if e has no real value, or is zero within 1080 digits.
int sign_of(const GiNaC::ex& e, const GiNaC::lst& at, const std::string& field);

/// Exact zero test after normal(): e is identically zero in the parameters. False (not proved)
/// for an expression of more than 400 nodes or more than 4 powers with a symbolic exponent,
/// where normal() can grow without bound, and where normal() divides by zero.
bool is_identically_zero(const GiNaC::ex& e);

/// sqrt(e) with even powers of positive factors and square numeric factors taken out
/// (sqrt(2*m^2*a^4) -> sqrt(2)*m*a^2), which GiNaC does not do by itself: of the numerator and
/// the denominator alike (sqrt(x/(a+b)^4) -> sqrt(x)/(a+b)^2), and of a sum's integer content
/// (sqrt(16*x^2 + 16) -> 4*sqrt(x^2 + 1)). A factor of unknown sign stays under the root.
GiNaC::ex simplified_sqrt(const GiNaC::ex& e);

/// GiNaC's normal(e), exactly, with the normal forms of function arguments kept across calls:
/// normal() of c*f(x) (c a number) is c*f(normal(x)), and a principal axis in a plane is made
/// of sin(theta) and cos(theta) of one angle, whose arguments normal() normalised for each.
GiNaC::ex normal_kept(const GiNaC::ex& e);

/// A neat form: normal(), then the numerator and denominator factored.
GiNaC::ex tidy(const GiNaC::ex& e);

/// The shortest of: normal(e), and normal(e) with sin^2 = 1 - cos^2 or cos^2 = 1 - sin^2 applied
/// (GiNaC does not use the Pythagorean identity by itself). Length is that of the canonical
/// text, which does not depend on GiNaC's run-dependent term order, so the choice is
/// deterministic. It depends on the rational function e is, not on how e is written: sums over
/// one denominator are written as one fraction first, which normal() reduces in fewer gcds.
GiNaC::ex simplify(const GiNaC::ex& e);

}  // namespace wobble::sym
