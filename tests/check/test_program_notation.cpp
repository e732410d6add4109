// Answers as Mathematica, Python and MATLAB write them: the rewriting itself, and every closed
// form of every key written in each program's notation (built here from the key's plain text,
// with the elliptic integrals' argument squared where the program takes the parameter m = k²),
// judged right.
#include <fmt/format.h>

#include <catch2/catch.hpp>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>
#include <functional>
#include <map>
#include <string>

#include "check/check_fixture.hpp"
#include "check/program_notation.hpp"
#include "solvers/catalog.hpp"

using namespace wobble;
using Fixture = wobble::test::CheckFixture;

namespace {
// The index of the ')' that closes s[open], counting all brackets alike.
std::size_t closing(const std::string& s, std::size_t open) {
  int depth = 0;
  for (std::size_t i = open; i < s.size(); ++i) {
    if (s[i] == '(' || s[i] == '[') ++depth;
    if ((s[i] == ')' || s[i] == ']') && --depth == 0) return i;
  }
  throw std::logic_error("unbalanced: " + s);
}

// A call's name and its arguments, split at the commas outside brackets.
std::vector<std::string> split_arguments(const std::string& inside) {
  std::vector<std::string> args{""};
  int depth = 0;
  for (char c : inside) {
    depth += (c == '(' || c == '[') - (c == ')' || c == ']');
    if (c == ',' && depth == 0) {
      args.emplace_back();
    } else {
      args.back() += c;
    }
  }
  return args;
}

// `plain` (a key's closed form as its JSON writes it) with each call `f(args)` written by
// `call(f, args)`, inside out, and each other character by `other`.
std::string with_calls(const std::string& plain,
                       const std::function<std::string(const std::string&,
                                                       const std::vector<std::string>&)>& call,
                       const std::function<std::string(char)>& other) {
  std::string out;
  for (std::size_t i = 0; i < plain.size();) {
    std::size_t j = i;
    while (j < plain.size() && (std::isalnum(static_cast<unsigned char>(plain[j])) || plain[j] == '_'))
      ++j;
    const bool name = j > i && std::isalpha(static_cast<unsigned char>(plain[i]));
    if (name && j < plain.size() && plain[j] == '(') {
      const std::size_t close = closing(plain, j);
      std::vector<std::string> args;
      for (const auto& a : split_arguments(plain.substr(j + 1, close - j - 1)))
        args.push_back(with_calls(a, call, other));
      out += call(plain.substr(i, j - i), args);
      i = close + 1;
    } else if (j > i) {
      out += plain.substr(i, j - i) == "pi" ? other('P') : plain.substr(i, j - i);
      i = j;
    } else {
      out += other(plain[i]);
      ++i;
    }
  }
  return out;
}

std::string joined(const std::vector<std::string>& args) {
  std::string out;
  for (const auto& a : args) out += (out.empty() ? "" : ",") + a;
  return out;
}

// Mathematica's InputForm: Sqrt[x], ArcTan[x, y] for atan2(y, x), EllipticK[k^2], lists in
// braces, Pi.
std::string mathematica(const std::string& plain) {
  static const std::map<std::string, std::string> names{
      {"sqrt", "Sqrt"}, {"sin", "Sin"},   {"cos", "Cos"},   {"tan", "Tan"},     {"asin", "ArcSin"},
      {"acos", "ArcCos"}, {"atan", "ArcTan"}, {"exp", "Exp"}, {"log", "Log"},   {"abs", "Abs"}};
  return with_calls(
      plain,
      [](const std::string& f, const std::vector<std::string>& args) -> std::string {
        if (f == "atan2") return "ArcTan[" + args.at(1) + "," + args.at(0) + "]";
        if (f == "EllipticK" || f == "EllipticE") return f + "[(" + args.at(0) + ")^2]";
        return names.at(f) + "[" + joined(args) + "]";
      },
      [](char c) -> std::string {
        if (c == 'P') return "Pi";
        if (c == '[') return "{";
        if (c == ']') return "}";
        return std::string(1, c);
      });
}

// NumPy and SciPy: np.sqrt(x), np.arctan2(y, x), scipy.special.ellipk(k**2), np.pi, '**'.
std::string python(const std::string& plain) {
  return with_calls(
      plain,
      [](const std::string& f, const std::vector<std::string>& args) -> std::string {
        if (f == "atan2") return "np.arctan2(" + joined(args) + ")";
        if (f == "EllipticK") return "scipy.special.ellipk((" + args.at(0) + ")**2)";
        if (f == "EllipticE") return "scipy.special.ellipe((" + args.at(0) + ")**2)";
        return "np." + f + "(" + joined(args) + ")";
      },
      [](char c) -> std::string {
        if (c == 'P') return "np.pi";
        if (c == '^') return "**";
        return std::string(1, c);
      });
}

// MATLAB's element-wise operators, and ellipke(k.^2).
std::string matlab(const std::string& plain) {
  return with_calls(
      plain,
      [](const std::string& f, const std::vector<std::string>& args) -> std::string {
        if (f == "EllipticK") return "ellipke((" + args.at(0) + ").^2)";
        return f + "(" + joined(args) + ")";
      },
      [](char c) -> std::string {
        if (c == 'P') return "pi";
        if (c == '^' || c == '*' || c == '/') return std::string(".") + c;
        return std::string(1, c);
      });
}

// Maple: arctan(y, x) for atan2(y, x), Pi; its EllipticK(k) takes the modulus, as wobble's.
std::string maple(const std::string& plain) {
  return with_calls(
      plain,
      [](const std::string& f, const std::vector<std::string>& args) -> std::string {
        if (f == "atan2") return "arctan(" + joined(args) + ")";
        return f + "(" + joined(args) + ")";
      },
      [](char c) -> std::string { return c == 'P' ? "Pi" : std::string(1, c); });
}
}  // namespace

TEST_CASE("a program's notation is rewritten in the reader's") {
  using check::as_programs_mean;
  CHECK(as_programs_mean("Sqrt[m]/EllipticK[0.3]") == "sqrt(m)/EllipticK(sqrt(0.3))");
  CHECK(as_programs_mean("Sqrt[Sin[x]^2]") == "sqrt(sin(x)^2)");
  CHECK(as_programs_mean("ArcTan[x, y] + ArcTan[z]") == "atan2(y, x) + atan(z)");
  CHECK(as_programs_mean("N[Pi/4, 20]") == "pi/4");
  CHECK(as_programs_mean("2/N[Pi/4]") == "2/(pi/4)");
  CHECK(as_programs_mean("N[{40, 30, 70} Degree]") == "{40, 30, 70} (pi/180)");
  CHECK(as_programs_mean("2.395*^-7") == "2.395e-7");
  CHECK(as_programs_mean("30 Degree") == "30 (pi/180)");
  CHECK(as_programs_mean("np.sqrt(2)*math.pi") == "sqrt(2)*pi");
  CHECK(as_programs_mean("scipy.special.ellipk(m) + ellipe(m)") ==
        "EllipticK(sqrt(m)) + EllipticE(sqrt(m))");
  CHECK(as_programs_mean("np.radians(15)") == "((15)*pi/180)");
  CHECK(as_programs_mean("np.deg2rad([40, 30])") == "[((40)*pi/180), ((30)*pi/180)]");
  CHECK(as_programs_mean("m.*R.^2./4") == "m*R^2/4");
  CHECK(as_programs_mean("array([25.82+0.j, 4.995-0j, 1.5+0.00000000e+00j])") ==
        "array([25.82, 4.995, 1.5])");
  CHECK(as_programs_mean("(4.995+0j)") == "(4.995)");
  CHECK(as_programs_mean("4.995+0.5j") == "4.995+0.5j");  // not real: left to be refused
  CHECK(as_programs_mean("2+0*j") == "2+0*j");

  CHECK(as_programs_mean("arctan(sin(a), 2) + atan(y, x) + atan(z)") ==
        "atan2(sin(a), 2) + atan2(y, x) + atan(z)");
  CHECK(as_programs_mean("evalf(Pi/4)") == "pi/4");
  // A program's containers are the reader's to unwrap; names of the problem stay.
  CHECK(as_programs_mean("np.array([1, 2])") == "np.array([1, 2])");
  CHECK(as_programs_mean("np.float64(0.5)") == "np.float64(0.5)");
  CHECK(as_programs_mean("DiagonalMatrix[{1, 2}]") == "DiagonalMatrix[{1, 2}]");
  CHECK(as_programs_mean("N*[1, 2, 3]") == "N*[1, 2, 3]");
  CHECK(as_programs_mean("psidot0*cos(theta0)") == "psidot0*cos(theta0)");
  CHECK_FALSE(check::elliptic_of_parameter("sqrt(m)").has_value());
  CHECK(check::elliptic_of_parameter("4*EllipticK(m)/w") == "4*EllipticK(sqrt(m))/w");
}

TEST_CASE("every closed form written as Mathematica, NumPy, MATLAB or Maple writes it is right") {
  int judged = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        if (a.symbolic.empty() || a.kind == AnswerKind::principal_axes) continue;
        for (const auto& written :
             {mathematica(a.symbolic), python(a.symbolic), matlab(a.symbolic), maple(a.symbolic)}) {
          INFO(p.id << " " << a.name << ": " << written);
          const check::Verdict v = f.check(a.name, written);
          CHECK(v.correct);
          ++judged;
        }
      }
    }
  }
  REQUIRE(judged > 400);
}

TEST_CASE("angles in degrees as NumPy and Mathematica convert them") {
  const Fixture euler("euler-angles");  // φ, θ, ψ = 40°, 30°, 70°
  for (const std::string written :
       {"np.deg2rad([40, 30, 70])", "N[{40, 30, 70} Degree]", "{40 Degree, 30 Degree, 70 Degree}",
        "np.radians([40, 30, 70])"}) {
    INFO(written);
    REQUIRE(euler.check("angles_phy711", written).correct);
  }
  REQUIRE_FALSE(euler.check("angles_phy711", "np.deg2rad([40, 70, 30])").correct);
}

TEST_CASE("an elliptic integral given the parameter where it takes the modulus is named") {
  const Fixture racket("tennis-racket");  // k near 1: K(k) and K(k²) differ by 4%
  const double k = racket.answer("k").value.data.at(0);
  const double rate = 4 * std::comp_ellint_1(k) / racket.answer("period").value.data.at(0);
  const std::string of = fmt::format("{:.10g})/{:.10g} s", k * k, rate);
  REQUIRE(racket.check("period", "4*EllipticK[" + fmt::format("{:.10g}]/{:.10g} s", k * k, rate))
              .correct);
  REQUIRE(racket.check("period", "4*ellipk(" + of).correct);
  const auto v = racket.check("period", "4*EllipticK(" + of);
  REQUIRE_FALSE(v.correct);
  REQUIRE(v.feedback.size() == 1);
  REQUIRE_THAT(v.feedback[0], Catch::StartsWith("EllipticK and EllipticE take the modulus k here"));
  REQUIRE(racket.check("period", fmt::format("4*EllipticK({:.10g})/{:.10g} s", k, rate)).correct);
}

TEST_CASE("a two-argument arctangent with its arguments in another program's order is named") {
  // Every closed form with an atan2, its first atan2's arguments swapped, written as wobble,
  // Mathematica, NumPy and Maple write it: wrong, with the line that names the order.
  int judged = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        if (a.symbolic.find("atan2(") == std::string::npos) continue;
        int calls = 0;
        const std::string swapped = with_calls(
            a.symbolic,
            [&](const std::string& fn, const std::vector<std::string>& args) {
              const bool swap = fn == "atan2" && calls++ == 0;
              return fn + "(" + (swap ? args.at(1) + "," + args.at(0) : joined(args)) + ")";
            },
            [](char c) { return c == 'P' ? std::string("pi") : std::string(1, c); });
        for (const auto& written :
             {swapped, mathematica(swapped), python(swapped), maple(swapped)}) {
          INFO(p.id << " " << a.name << ": " << written);
          const check::Verdict v = f.check(a.name, written);
          REQUIRE_FALSE(v.correct);
          REQUIRE_FALSE(v.feedback.empty());
          CHECK_THAT(v.feedback[0], Catch::Contains("arguments are the other way round"));
          ++judged;
        }
      }
    }
  }
  REQUIRE(judged >= 20);
  // Mathematica's order is told as Mathematica's; a wrong answer of another kind is not.
  const Fixture plate("flying-plate");  // angle_L_e3 = atan2(sin α, 2 cos α)
  REQUIRE_THAT(plate.check("angle_L_e3", "ArcTan[Sin[α], 2 Cos[α]]").feedback.at(0),
               Catch::Contains("Mathematica's ArcTan[x, y] takes x first"));
  REQUIRE_THAT(
      plate.check("angle_L_e3", "np.arctan2(2*np.cos(alpha), np.sin(alpha))").feedback.at(0),
      Catch::Contains("arctan2(y, x) takes y first"));
  REQUIRE_THAT(plate.check("angle_L_e3", "atan2(sin α, 3 cos α)").feedback.at(0),
               !Catch::Contains("other way round"));
}
