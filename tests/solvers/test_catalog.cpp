// Every answer of every problem, at the defaults and at other values: the symbolic form, read
// back and evaluated, equals the value; and the answers agree with each other (eigen residual,
// orthonormal right-handed axes, parallel-axis consistency).
#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <limits>

#include "core/inertia.hpp"
#include "solvers/catalog.hpp"
#include "problem/values.hpp"
#include "solvers/exact_answer.hpp"
#include "solvers/inertia_body.hpp"
#include "symbolic/principal_sym.hpp"
#include "solvers/solve.hpp"
#include "symbolic/value_text.hpp"
#include "temp_files.hpp"

using namespace wobble;
using Catch::Matchers::WithinAbs;

namespace {
constexpr double kEps = std::numeric_limits<double>::epsilon();

// Deterministic other values: positive parameters scaled by 1.37^k, angles moved inside range.
sym::Values other_values(const Problem& p, int k) {
  sym::Values v = parameter_values(p, {});
  for (const auto& param : p.parameters) {
    double x = v[param.name];
    if (param.is_angle()) {
      const double lo = param.range.lo,
                   hi = std::isfinite(param.range.hi) ? param.range.hi : lo + 3.0;
      x = lo + (hi - lo) * (0.2 + 0.17 * k);
    } else {
      x *= std::pow(1.37, k) * (1.0 + 0.11 * static_cast<double>(param.name.size()));
    }
    if (param.range.contains(x)) v[param.name] = x;
  }
  return v;
}

const Answer* find(const Key& key, const std::string& name) {
  for (const auto& part : key.parts) {
    for (const auto& a : part.answers) {
      if (a.name == name) return &a;
    }
  }
  return nullptr;
}

Mat3 mat(const Answer& a) {
  Mat3 m;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j)
      m(i, j) = a.value.at(static_cast<std::size_t>(i), static_cast<std::size_t>(j));
  }
  return m;
}

void check_symbolic_equals_value(const Problem& p, const sym::Values& values, const Answer& a) {
  if (a.symbolic.empty()) {
    REQUIRE_FALSE(a.notes.empty());  // numeric-only answers must say why
    return;
  }
  const sym::SymbolTable table = p.symbol_table();
  const auto parsed = sym::parse_value_text(a.symbolic, table, a.name);
  REQUIRE(parsed.entries.size() == a.value.data.size());
  const GiNaC::lst at = sym::substitution(table, values);
  // Both sides are the same exact expression rounded once: equal to a few ulps of the scale.
  const double tol = 4 * kEps * std::max(a.value.scale(), 1e-300);
  for (std::size_t i = 0; i < parsed.entries.size(); ++i) {
    REQUIRE_THAT(sym::evaluate(parsed.entries[i], at, a.name), WithinAbs(a.value.data[i], tol));
  }
}

void check_principal(const Answer& I, const Answer* moments, const Answer* axes) {
  if (moments == nullptr || axes == nullptr) return;
  const Mat3 T = mat(I);
  const Mat3 E = mat(*axes);
  const double n = 3.0;
  REQUIRE((E.transpose() * E - Mat3::Identity()).norm() <= 8 * n * kEps);
  REQUIRE_THAT(E.determinant(), WithinAbs(1.0, 8 * n * kEps));
  for (int k = 0; k < 3; ++k) {
    const double lambda = moments->value.data[static_cast<std::size_t>(k)];
    if (k > 0) REQUIRE(moments->value.data[static_cast<std::size_t>(k - 1)] <= lambda);
    // Eigen residual bound 8 n eps |I|.
    REQUIRE((T * E.col(k) - lambda * E.col(k)).norm() <= 8 * n * kEps * T.norm());
  }
}

void check_key(const Problem& p, const sym::Values& values) {
  const Key key = solve(p, values);
  for (const auto& part : key.parts) {
    REQUIRE_FALSE(part.steps.empty());
    for (const auto& a : part.answers) {
      INFO(p.id << " part " << part.id << " answer " << a.name << " symbolic " << a.symbolic);
      REQUIRE_FALSE(a.latex.empty());
      check_symbolic_equals_value(p, values, a);
    }
  }
  // Consistency between answers, whatever their names in this problem.
  if (const Answer* k2 = find(key, "k2"), *kc2 = find(key, "kc2"); k2 && kc2) {
    // Two exact forms, each rounded once: their sum is 1 to two roundings.
    REQUIRE_THAT(k2->value.data[0] + kc2->value.data[0], WithinAbs(1.0, 2 * kEps));
  }
  if (const Answer* T = find(key, "period"), *flip = find(key, "flip_interval"); T && flip) {
    REQUIRE_THAT(flip->value.data[0], WithinAbs(T->value.data[0] / 2, kEps * T->value.data[0]));
  }
  if (p.solver != "inertia" && p.solver != "torque_free_symmetric") return;
  const Answer* I = find(key, "I") ? find(key, "I") : find(key, "I_corner");
  if (I == nullptr) return;  // a problem that asks no tensor (the Earth's) has nothing to compare
  check_principal(*I,
                  find(key, "principal_moments") ? find(key, "principal_moments")
                                                 : find(key, "principal_moments_corner"),
                  find(key, "principal_axes") ? find(key, "principal_axes")
                                              : find(key, "principal_axes_corner"));
  if (const Answer* I_cm = find(key, "I_cm")) {
    check_principal(*I_cm, find(key, "principal_moments_cm"), find(key, "principal_axes_cm"));
    // Parallel axis: I_O - I_cm = M (|c|^2 1 - c c^T), with M = the sum of the point masses.
    const Answer* c = find(key, "center_of_mass");
    REQUIRE(c != nullptr);
    const Vec3 r(c->value.data[0], c->value.data[1], c->value.data[2]);
    const Mat3 shift = mat(*I) - mat(*I_cm);
    const Mat3 unit_shift = r.squaredNorm() * Mat3::Identity() - r * r.transpose();
    if (unit_shift.norm() > 0) {
      const double M = shift.trace() / unit_shift.trace();
      REQUIRE((shift - M * unit_shift).norm() <= 64 * kEps * mat(*I).norm());
    }
  }
}
}  // namespace

TEST_CASE("every problem: symbolic forms evaluate to their values, answers agree") {
  const auto problems = load_catalog();
  REQUIRE(problems.size() >= 5);
  for (const auto& p : problems) {
    for (int k = 0; k < 3; ++k) {
      INFO(p.id << " variant " << k);
      check_key(p, k == 0 ? parameter_values(p, {}) : other_values(p, k));
    }
  }
}

TEST_CASE("solving twice gives the same key (deterministic)") {
  const Problem p = find_problem("three-atom-molecule");
  const Key a = solve(p, parameter_values(p, {}));
  const Key b = solve(p, parameter_values(p, {}));
  for (std::size_t i = 0; i < a.parts.size(); ++i) {
    for (std::size_t j = 0; j < a.parts[i].answers.size(); ++j) {
      REQUIRE(a.parts[i].answers[j].symbolic == b.parts[i].answers[j].symbolic);
      REQUIRE(a.parts[i].answers[j].value.data == b.parts[i].answers[j].value.data);
    }
  }
}

TEST_CASE("every step reads as plain text too (the text key shows no LaTeX)") {
  for (const auto& p : load_catalog()) {
    const Key key = solve(p, parameter_values(p, {}));
    for (const auto& part : key.parts) {
      for (const auto& step : part.steps) {
        INFO(p.id << " (" << part.id << "): '" << step.text << "' / '" << step.latex << "'");
        REQUIRE_FALSE(step.text.empty());
        REQUIRE(step.text.find('\\') == std::string::npos);
      }
    }
  }
}

namespace {
// One torque-free top written with decimals (geometry, masses, sizes, motion) or with the
// same numbers as fractions.
std::string decimal_or_fraction_problem(bool decimals) {
  const auto n = [&](const char* decimal, const char* fraction) {
    return std::string("\"") + (decimals ? decimal : fraction) + "\"";
  };
  const std::string half_m = n("0.5*m", "m/2");
  return R"TOML(id = "decimals"
title = "t"
solver = "torque_free_symmetric"
statement = "s"

[[parameters]]
name = "m"
unit = "kg"
default = 1.5
range = "(0, inf)"

[[parameters]]
name = "alpha"
unit = "rad"
default = "15deg"
range = "[0, pi/2)"

[body]
masses = [ { mass = )TOML" + half_m + R"TOML(, at = ["0", "0", )TOML" + n("1.5", "3/2") +
         R"TOML(] }, { mass = )TOML" + half_m + R"TOML(, at = ["0", "0", )TOML" +
         n("-1.5", "-3/2") + R"TOML(] } ]
shapes = [ { shape = "box", mass = )TOML" + n("2.5*m", "5*m/2") + ", sizes = [" +
         n("0.5", "1/2") + ", " + n("0.5", "1/2") + ", " + n("1.2e-1", "3/25") + R"TOML(] } ]

[motion]
omega = )TOML" + n("2.5", "5/2") + R"TOML(
alpha = "alpha"

[[parts]]
id = "a"
question = "q"
answers = ["I0", "I", "Omega_body_rate", "max_angle", "t_max"]
)TOML";
}
}  // namespace

TEST_CASE("decimals in a problem file are the decimal numbers, exactly (no internal error)") {
  const auto solved = [](bool decimals) {
    const Problem p = load_problem(
        wobble::test::write_file(decimals ? "catalog/decimals.toml" : "catalog/fractions.toml",
                         decimal_or_fraction_problem(decimals)));
    return solve(p, parameter_values(p, {}));
  };
  const Key with_decimals = solved(true), with_fractions = solved(false);
  const auto& a = with_decimals.parts.at(0).answers;
  const auto& b = with_fractions.parts.at(0).answers;
  REQUIRE(a.size() == 5);
  for (std::size_t i = 0; i < a.size(); ++i) {
    INFO(a[i].name);
    // Exact both ways: the same closed form and the same value to the last bit.
    REQUIRE(a[i].symbolic == b[i].symbolic);
    REQUIRE(a[i].value.data == b[i].value.data);
  }
}

TEST_CASE("the exact and double routes are compared for every problem at its defaults") {
  // The comparison is skipped only where the double route over- or underflowed; at the
  // catalog's values nothing does, so every problem is checked both ways.
  for (const auto& p : load_catalog()) {
    const RouteCheckCounts before = route_check_counts();
    (void)solve(p, parameter_values(p, {}));
    const RouteCheckCounts after = route_check_counts();
    INFO(p.id);
    CHECK(after.skipped == before.skipped);
    CHECK(after.compared > before.compared);
  }
}

TEST_CASE("badly scaled values: the routes agree within the problem's conditioning") {
  // Each once failed the self-check (exit 3): a near-separatrix racket (period condition number
  // 1.7e4), a molecule far from its centre of mass, a heavy top tipped to 1e-5 rad of the
  // bottom, values whose squares leave double's range (the check is skipped, the exact route
  // answers), and a modulus within 1e-83 of 1 (K(k) needs 120 digits).
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases{
      {"tennis-racket", {"m=0.33", "a=0.51", "b=0.075", "c=0.011", "omega=16", "epsilon=0.0062"}},
      {"tennis-racket", {"a=5"}},
      {"tennis-racket", {"epsilon=1e-40"}},
      {"tennis-racket", {"omega=1e150"}},
      {"asymmetric-top", {"w2=1e150"}},
      {"three-atom-molecule", {"m1=3000"}},
      {"flying-plate", {"omega=1e-300"}},
      {"flying-plate", {"omega=1e300"}},
      {"heavy-top", {"g=1e12"}},
      {"heavy-top", {"g=1e-150"}},   // the nutation limit's quadratic, nearly linear
      {"asymmetric-top", {"w1=1e12"}},  // k ~ 1e-11: k'^2 rounds to 1
      {"asymmetric-top", {"w3=1e12"}},
      {"rect-solid", {"a=1e150"}},
  };
  for (const auto& [id, set] : cases) {
    const Problem p = find_problem(id);
    INFO(id << " " << set.back());
    CHECK_NOTHROW(solve(p, parameter_values(p, set)));
  }
}

TEST_CASE("a period near the separatrix is K(k) with enough digits (against mpmath)") {
  // tennis-racket at epsilon = 1e-40: k'^2 = 4.3395e-83; mpmath (120 digits) gives the period
  // 42.144758224211477 s. 40 digits would round k to 1 and refuse.
  const Problem p = find_problem("tennis-racket");
  const Key key = solve(p, parameter_values(p, {"epsilon=1e-40"}));
  for (const auto& part : key.parts) {
    for (const auto& a : part.answers) {
      if (a.name == "period") CHECK_THAT(a.value.data[0], Catch::Matchers::WithinULP(42.144758224211477, 1));
    }
  }
}

TEST_CASE("the symbolic budget: catalog tensors are far inside it, a file of 40 masses beyond") {
  // The closed-form route's budget (kMaxClosedFormNodes) must never send a catalog problem to
  // the numeric route: each tensor, about O and about the centre of mass, stays under half of it.
  int largest = 0;
  for (const auto& p : load_catalog()) {
    const BodyContext c(p, parameter_values(p, {}));
    const auto& e = c.body.exact;
    largest = std::max(largest, sym::tensor_nodes(e.I_O));
    if (c.body.has_mass) {
      const GiNaC::matrix I_cm = sym::normalized(e.I_O.sub(sym::parallel_axis_term(e.mass, e.r_cm)));
      largest = std::max(largest, sym::tensor_nodes(I_cm));
    }
  }
  INFO("largest catalog tensor: " << largest << " nodes");
  CHECK(largest * 2 < sym::kMaxClosedFormNodes);
  // 40 masses at sqrt(k) coordinates (minutes of factoring before the budget): numeric at once.
  std::string masses;
  for (int i = 0; i < 40; ++i) {
    masses += (i ? ", " : "") + std::string("{ mass = \"m\", at = [\"sqrt(") +
              std::to_string(2 + i % 29) + ")*a\", \"sqrt(" + std::to_string(3 + (7 * i) % 23) +
              ")*a\", \"" + std::to_string(i % 5 - 2) + "\"] }";
  }
  const Problem big = load_problem(test::write_file("budget/big.toml", R"TOML(id = "big"
title = "t"
solver = "inertia"
statement = "s"
[[parameters]]
name = "m"
unit = "kg"
default = 1
range = "(0, inf)"
[[parameters]]
name = "a"
unit = "m"
default = 1
range = "(0, inf)"
[body]
masses = [ )TOML" + masses + R"TOML( ]
[[parts]]
id = "a"
question = "q"
answers = ["principal_moments", "principal_axes_cm"]
)TOML"));
  const Key key = solve(big, parameter_values(big, {}));
  REQUIRE(key.parts.at(0).answers.size() == 2);
  CHECK_THAT(key.parts[0].answers[0].notes.at(0), Catch::Contains("too long for the closed-form"));
}

TEST_CASE("a heavy top without gravity to speak of nods by nothing: theta_max = theta0") {
  // g = 1e-150: the other nutation limit is u0 - beta s^2/a^2 + ..., 1e-151 from cos(theta0).
  // Written as (-c2 + root)/(2 beta) it cancelled all 40 digits and gave pi/2; as c1/q it is
  // theta0 to the last digit.
  const Problem p = find_problem("heavy-top");
  const Key key = solve(p, parameter_values(p, {"g=1e-150"}));
  bool seen = false;
  for (const auto& part : key.parts) {
    for (const auto& a : part.answers) {
      if (a.name != "theta_max") continue;
      seen = true;
      CHECK_THAT(a.value.data[0], Catch::Matchers::WithinULP(M_PI / 6, 1));
    }
  }
  CHECK(seen);
}

namespace {
// A problem file outside problems/, for the lookup by path.
const std::string kTwoMasses = R"TOML(id = "two"
title = "Two masses"
solver = "inertia"
statement = "Two masses."

[[parameters]]
name = "m"
unit = "kg"
default = 1
range = "(0, inf)"

[body]
masses = [ { mass = "m", at = [1, 0, 0] }, { mass = "2*m", at = [0, 1, 0] } ]

[[parts]]
id = "a"
question = "Tensor?"
answers = ["I"]
)TOML";
}  // namespace

TEST_CASE("problem lookup: by id, by file, and unknown ids list the known ones") {
  REQUIRE(find_problem("taylor-10-35").id == "taylor-10-35");
  REQUIRE(find_problem(test::write_file("load/two.toml", kTwoMasses).string()).id == "two");
  REQUIRE_THROWS_WITH(
      find_problem("taylor-10-53"),
      Catch::Contains("unknown problem 'taylor-10-53'") && Catch::Contains("taylor-10-35"));
  REQUIRE_THROWS_WITH(find_problem("/nonexistent/x.toml"), Catch::Contains("no such problem file"));
}

TEST_CASE("a problem file's named mistakes are read in the answer's unit when it is solved") {
  const auto with_mistake = [](const std::string& answer, const std::string& value) {
    std::string text = kTwoMasses;
    const std::string answers = "answers = [\"I\"]";
    REQUIRE(text.find(answers) != std::string::npos);
    return text.replace(text.find(answers), answers.size(),
                        "answers = [{ name = \"" + answer + "\", mistakes = [{ value = " + value +
                            ", what = \"the mass of one\", remedy = \"add both\" }] }]");
  };
  const auto solved = [](const std::string& text) {
    const Problem p = load_problem(test::write_file("mistakes/two.toml", text));
    return solve(p, parameter_values(p, {}));
  };
  // Masses m and 2m at m = 1 kg: the total is 3 kg; 2000 g is read as 2 kg, as a number as 1 kg.
  for (const auto& [typed, kg] : {std::pair{"\"2000 g\"", 2.0}, std::pair{"1", 1.0}}) {
    INFO(typed);
    const Key key = solved(with_mistake("mass", typed));
    const Answer& total = key.parts.at(0).answers.at(0);
    REQUIRE(total.value.data == std::vector<double>{3.0});
    REQUIRE(total.approximations.size() == 1);
    CHECK(total.approximations[0].values == std::vector<double>{kg});
    CHECK(total.approximations[0].name == "the mass of one");
    CHECK(total.approximations[0].remedy == "add both");
    CHECK(total.approximations[0].beside == "the answer");
  }
  // Refused, naming the file and the field: another dimension, no number, a tensor's.
  CHECK_THROWS_WITH(
      solved(with_mistake("mass", "\"2 m\"")),
      Catch::Contains("two.toml:18: parts[0].answers[0].mistakes[0].value: '2 m' is in "
                      "m (length), but mass is in kg (mass)"));
  CHECK_THROWS_WITH(
      solved(with_mistake("mass", "\"two kg\"")),
      Catch::Contains("parts[0].answers[0].mistakes[0].value") && Catch::Contains("'two kg'"));
  CHECK_THROWS_WITH(
      solved(with_mistake("I", "\"2 kg m^2\"")),
      Catch::Contains("mistakes[0].value: '2 kg m^2' is a number, but I is a matrix"));
}

TEST_CASE("a named mistake in the problem's parameters follows each variant's values") {
  const auto with_mistake = [](const std::string& value) {
    std::string t = kTwoMasses;
    const std::string answers = "answers = [\"I\"]";
    return t.replace(t.find(answers), answers.size(),
                     "answers = [{ name = \"mass\", mistakes = [{ value = \"" + value +
                         "\", what = \"the heavier mass alone\", remedy = \"add both\" }] }]");
  };
  const auto solved = [](const std::string& file, const std::vector<std::string>& sets) {
    const Problem p = load_problem(test::write_file("mistakes/two.toml", file));
    return solve(p, parameter_values(p, sets));
  };
  // Masses m and 2m: the heavier alone is 2m, at m = 1 kg and at m = 0.25 kg alike. (As in
  // every quantity of a file, "2 m" would be two metres: symbolic/quantity.hpp.)
  for (const std::string value : {"2*m", "m·2"}) {
    for (const auto& [sets, kg] : {std::pair{std::vector<std::string>{}, 2.0},
                                   std::pair{std::vector<std::string>{"m=250 g"}, 0.5}}) {
      INFO(value << " at " << kg / 2 << " kg");
      const Key key = solved(with_mistake(value), sets);
      const Answer& total = key.parts.at(0).answers.at(0);
      REQUIRE(total.approximations.size() == 1);
      CHECK(total.approximations[0].values == std::vector<double>{kg});
    }
  }
  // Refused, naming the file and the field: another dimension (a power off, a sum of unlike
  // terms, a function of a mass), and no real value.
  for (const std::string bad : {"m^2", "m + 1", "exp(m)", "sqrt(m)"}) {
    INFO(bad);
    CHECK_THROWS_WITH(
        solved(with_mistake(bad), {}),
        Catch::Contains("two.toml:18: parts[0].answers[0].mistakes[0].value: '" + bad +
                        "' is not of mass's dimension, mass (kg): its value does not scale as the "
                        "answer's when the units of mass, length and time do"));
  }
  CHECK_THROWS_WITH(solved(with_mistake("sqrt(-m)"), {}),
                    Catch::Contains("two.toml:18: parts[0].answers[0].mistakes[0].value"));
  // With no value at some values (a pure number k = 0 here), it names nothing there; its value
  // at the defaults is what is tested.
  std::string with_k = with_mistake("2*m/k");
  const std::string body = "[body]";
  with_k.insert(with_k.find(body),
                "[[parameters]]\nname = \"k\"\nunit = \"\"\ndefault = 1\nrange = \"[0, 2]\"\n\n");
  CHECK(solved(with_k, {}).parts.at(0).answers.at(0).approximations.size() == 1);
  CHECK(solved(with_k, {"k=0"}).parts.at(0).answers.at(0).approximations.empty());
  // Zero at the defaults scales as anything: the dimension is tested again where it is used. A
  // mass's square times k = 0 is refused at k = 1; twice a mass times k is 2 kg there.
  const auto with_zero_k = [&](const std::string& value) {
    std::string t = with_mistake(value);
    return t.insert(
        t.find(body),
        "[[parameters]]\nname = \"k\"\nunit = \"\"\ndefault = 0\nrange = \"[0, 2]\"\n\n");
  };
  CHECK(solved(with_zero_k("m^2*k"), {}).parts.at(0).answers.at(0).approximations.at(0).values ==
        std::vector<double>{0.0});
  CHECK_THROWS_WITH(solved(with_zero_k("m^2*k"), {"k=1"}),
                    Catch::Contains("mistakes[0].value: 'm^2*k' is not of mass's dimension"));
  CHECK(
      solved(with_zero_k("2*m*k"), {"k=1"}).parts.at(0).answers.at(0).approximations.at(0).values ==
      std::vector<double>{2.0});
}

TEST_CASE("one parameter per --set: several in one are refused with the options to type") {
  const Problem& plate = find_problem("flying-plate");
  for (const std::string several : {"m=0.5,R=0.1", "m=0.5; R=0.1", "m=0.5 R=0.1"}) {
    INFO(several);
    REQUIRE_THROWS_WITH(parameter_values(plate, {several}),
                        Catch::Equals("--set: '" + several +
                                      "' sets several parameters; give each its own --set: "
                                      "--set m=0.5 --set R=0.1"));
  }
  REQUIRE_THROWS_WITH(parameter_values(plate, {"R=5 cm,m=500 g"}),
                      Catch::EndsWith("--set 'R=5 cm' --set 'm=500 g'"));
  // A value's two sides, as a key prints them, set one parameter, even where a unit after the
  // first side spells another parameter (g, the heavy top's gravity).
  const Problem& top = find_problem("heavy-top");
  REQUIRE(parameter_values(top, {"M=500 g = 0.5 kg"}).at("M") == 0.5);
  REQUIRE(parameter_values(top, {"θ0 = 30° = 0.5235987756 rad"}).at("theta0") ==
          parameter_values(top, {"theta0=pi/6"}).at("theta0"));
  // A decimal comma is named as such.
  REQUIRE_THROWS_WITH(parameter_values(plate, {"m=0,5"}), Catch::Contains("a decimal comma?"));
  REQUIRE_THROWS_WITH(parameter_values(plate, {"alpha=15,5deg"}),
                      Catch::Contains("a decimal comma?"));
}

TEST_CASE("every part of every problem has a hint for the worksheet") {
  for (const auto& p : wobble::load_catalog()) {
    for (const auto& part : p.parts) {
      INFO(p.id << " part " << part.id);
      REQUIRE(part.hint.size() >= 20);  // a sentence, not a placeholder
    }
  }
}
