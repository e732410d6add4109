#include <catch2/catch.hpp>

#include "core/work_budget.hpp"
#include "problem/field_lines.hpp"
#include "problem/load.hpp"
#include "problem/values.hpp"
#include "symbolic/dimension_check.hpp"
#include "symbolic/quantity.hpp"
#include "symbolic/units.hpp"
#include "temp_files.hpp"

using namespace wobble;

namespace {
const std::string kGood = R"TOML(id = "two"
title = "Two masses"
solver = "inertia"
statement = "Two masses."

[[parameters]]
name = "m"
unit = "kg"
default = 1
range = "(0, inf)"

[[parameters]]
name = "alpha"
latex = "\\alpha"
unit = "rad"
default = "30deg"
range = "[0, pi/2)"

[body]
masses = [ { mass = "m", at = [1, 0, 0] }, { mass = "2*m", at = ["0", "cos(alpha)", 0.5] } ]

[[parts]]
id = "a"
question = "Tensor?"
answers = ["I", { name = "I_about_O", quantity = "I" }]
)TOML";

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const auto p = s.find(from);
  REQUIRE(p != std::string::npos);
  return s.replace(p, from.size(), to);
}

// The solvers as this layer's tests know them (problem/solver_schema.hpp): the program's own
// registry lives in the solvers layer, above this one.
const SolverSchemas& test_schemas() {
  static const SolverSchemas schemas{{"inertia", {}, {"I", "mass"}}};
  return schemas;
}

Problem load_problem(const std::filesystem::path& file) {
  return wobble::load_problem(file, test_schemas());
}

std::string load_error(const std::string& content) {
  const auto file = test::write_file("load/bad.toml", content);
  try {
    load_problem(file);
  } catch (const InputError& e) {
    return e.what();
  }
  FAIL("no error for:\n" << content);
  return "";
}

// What parse_quantity says of `text` as `field` in `si_unit`; "" where it reads.
std::string quantity_error(const sym::SymbolTable& table, const std::string& text,
                           const std::string& field, const std::string& si_unit) {
  try {
    (void)sym::parse_quantity(table, text, field, si_unit);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("a good file loads with every field") {
  const Problem p = load_problem(test::write_file("load/good.toml", kGood));
  REQUIRE(p.id == "two");
  REQUIRE(p.parameters.size() == 2);
  REQUIRE_THAT(p.parameters[1].default_value, Catch::Matchers::WithinULP(M_PI / 6, 1));
  REQUIRE(p.body.masses[0].at[0] == "1");
  REQUIRE(p.body.masses[1].at[2] == "0.5");
  REQUIRE(p.parts[0].answers[1].name == "I_about_O");
  REQUIRE(p.parts[0].answers[1].quantity == "I");
}

TEST_CASE("a parameter's unit is SI however spelt; an angle's is rad") {
  // is_angle() tests the unit "rad": spelt "radians", the angle would read 30deg as a number.
  const Problem p = load_problem(test::write_file(
      "load/radians.toml", replaced(kGood, "unit = \"rad\"", "unit = \"radians\"")));
  REQUIRE(p.parameters[1].unit == "rad");
  REQUIRE(p.parameters[1].is_angle());
  REQUIRE_THAT(p.parameters[1].default_value, Catch::Matchers::WithinULP(M_PI / 6, 1));
  // Another coherent SI unit is kept as written.
  const Problem q = load_problem(
      test::write_file("load/kgm.toml", replaced(kGood, "unit = \"kg\"", "unit = \"kg m^2/m^2\"")));
  REQUIRE(q.parameters[0].unit == "kg m^2/m^2");
}

TEST_CASE("a quantity's dimension follows from its parameters' units, and another is refused") {
  using Catch::Contains;
  const Problem p = load_problem(test::write_file("load/dims.toml", kGood));
  const sym::SymbolTable table = p.symbol_table();
  const auto error = [&](const std::string& text, const std::string& si_unit) {
    return quantity_error(table, text, "body.masses[0].mass", si_unit);
  };
  // alpha is an angle, a pure number: m cos(alpha) is a mass; 200 g, 0.05 and 2 pi name no
  // parameter, so their unit, not written, is not told.
  for (const std::string mass :
       {"2*m", "m*cos(alpha)", "m/alpha", "200 g", "0.05", "m + 0.05", "2*pi", "m + sqrt(2)"})
    CHECK(error(mass, "kg").empty());
  CHECK(error("m*alpha", "kg m^2")
            .find("is in kg (mass) by its parameters' units; it must be in "
                  "kg m^2 (mass × length²)") != std::string::npos);
  CHECK_THAT(error("cos(alpha)", "kg"),
             Contains("body.masses[0].mass: 'cos(alpha)' is a pure number by its parameters' "
                      "units; it must be in kg (mass)"));
  CHECK_THAT(error("m", "m"), Contains("'m' is in kg (mass)") && Contains("must be in m (length)"));
  // A sum: each term that has a dimension must have the quantity's; a bare number has none told.
  CHECK_THAT(error("m + m*m", "kg"),
             Contains("'m + m*m' has a term, m^2, in kg^2 (mass²)") && Contains("must be in kg"));
  CHECK_THAT(error("m + 0.05 + m^2", "kg"), Contains("has a term, m^2"));
  // A bare number inside takes the unit of the terms it is added to: m (1 + m) is m + m^2 in
  // kg and kg^2, whatever the 1 was meant to be.
  CHECK(error("m*(1 + m)", "kg^2").empty());
  CHECK(error("m*(alpha + 1)", "kg").empty());
  CHECK(error("m*abs(m - 1)", "kg^2").empty());
  CHECK_THAT(error("m*(1 + m)", "kg"),
             Contains("'m*(1 + m)' is in kg^2 (mass²) by its parameters' units; it must be in kg"));
  // A term shown in the refusal is as written, without the unit its number was given.
  CHECK_THAT(error("m + m*(m + 1)", "kg"), Contains("has a term, m*(m + 1), in kg^2"));
  // Inside the quantity: a sum of unlike terms, a function of a quantity with a unit, a unit in
  // an exponent.
  CHECK_THAT(error("m*(alpha + m)", "kg"),
             Contains("has a sum, alpha + m, of terms a pure number and in kg (mass)"));
  CHECK_THAT(error("m*exp(m)", "kg"),
             Contains("takes exp(m) of m, in kg (mass) by its parameters' units; its argument "
                      "must be a pure number"));
  CHECK_THAT(error("2^m", "kg"), Contains("has an exponent, m, in kg (mass)"));
  // A table that does not know its symbols' units tells nothing.
  sym::SymbolTable plain;
  plain.declare("m", "m", sym::SymbolSign::positive);
  CHECK_NOTHROW(sym::parse_quantity(plain, "m", "body.masses[0].at[0]", "m"));
}

TEST_CASE("a quantity's dimension read from its form is the one its value scales with") {
  // What the form tells is taken without evaluating; asked for another unit, the probe (which
  // evaluates the quantity as the units' sizes change) must find the same dimension.
  const Problem p = load_problem(test::write_file("load/form.toml", kGood));  // m kg, alpha rad
  const sym::SymbolTable table = p.symbol_table();
  const std::vector<std::pair<std::string, std::string>> told{
      {"2*m", "kg"},
      {"m*cos(alpha)^2 + m/3", "kg"},
      {"sqrt(m^2)*abs(m)", "kg^2"},
      {"-pi*m^3/alpha", "kg^3"},
      {"atan2(m*cos(alpha), m) + alpha", ""},
      {"exp(-alpha)/m", "1/kg"},
  };
  for (const auto& [text, unit] : told) {
    INFO(text);
    const GiNaC::ex e = sym::parse_quantity(table, text, "body.masses[0].mass", unit);
    const auto form = sym::dimension_by_form(table, e);
    Unit expected;
    if (!unit.empty()) expected = parse_unit(unit, "unit");
    REQUIRE(form == expected.dim);
    REQUIRE_THAT(quantity_error(table, text, "body.masses[0].mass", "m^5"),
                 Catch::Contains(unit.empty() ? "is a pure number by its parameters' units"
                                              : "is in " + si_unit_text(expected) + " ("));
  }
  // Where the form does not tell (a bare number in a sum, a half power, a function of a mass),
  // the probe decides, as before.
  for (const std::string text : {"m + 0.05", "sqrt(m)", "m*exp(m)"}) {
    INFO(text);
    REQUIRE_FALSE(sym::dimension_by_form(table, table.parse(text, "x")));
  }
  REQUIRE(quantity_error(table, "m + 0.05", "body.masses[0].mass", "kg").empty());
}

TEST_CASE("a unit inside a file's expression is said to go once, after the whole value") {
  using Catch::Contains;
  using Catch::EndsWith;
  const Problem p = load_problem(test::write_file("load/inside.toml", kGood));  // m kg, alpha rad
  const sym::SymbolTable table = p.symbol_table();
  const auto error = [&](const std::string& text, const std::string& si_unit) {
    return quantity_error(table, text, "initial.euler[1]", si_unit);
  };
  // Where the unit multiplies all of it, with the value so written, which then reads.
  CHECK(error("(10deg)*(pi/3)", "rad") ==
        "initial.euler[1]: cannot read \"(10deg)*(pi/3)\": 'deg' is a unit inside the "
        "expression; a unit goes once, after the whole value: \"((10)*(pi/3)) deg\"");
  CHECK(error("((10)*(pi/3)) deg", "rad").empty());
  CHECK_THAT(error("2*(20 cm) + 5cm", "m"), EndsWith(": \"(2*(20) + 5) cm\""));
  CHECK(error("(2*(20) + 5) cm", "m").empty());
  CHECK_THAT(error("(0.5 kg)*cos(alpha)", "kg"), EndsWith(": \"((0.5)*cos(alpha)) kg\""));
  // Where it does not (alpha is in rad), or is of another kind than the field's: said without.
  CHECK_THAT(error("90deg - alpha", "rad"),
             EndsWith("'deg' is a unit inside the expression; a unit goes once, after the whole "
                      "value (\"(90 - 15) deg\")"));
  CHECK_THAT(error("(20 cm)*2", "kg"), EndsWith("after the whole value (\"(90 - 15) deg\")"));
  // A name that is neither a unit nor a parameter leaves the reader's own message, as do two
  // units.
  CHECK_THAT(error("(10deg)*q", "rad"), Contains("undefined symbol"));
  CHECK_THAT(error("(2 kg)*(3 cm)", "kg m"), Contains("undefined symbol"));
  // A parameter named like a unit is the parameter: m here is the mass, not the metre.
  CHECK(error("2*m", "kg").empty());
}

TEST_CASE("a range's bounds may carry a unit, as the default does") {
  const Problem p = load_problem(test::write_file(
      "load/range_units.toml", replaced(kGood, "range = \"[0, pi/2)\"", "range = \"[0, 90deg)\"")));
  REQUIRE_THAT(p.parameters[1].range.hi, Catch::Matchers::WithinULP(M_PI / 2, 1));
  REQUIRE(p.parameters[1].range.hi_open);
  const Problem q = load_problem(test::write_file(
      "load/range_grams.toml", replaced(kGood, "range = \"(0, inf)\"", "range = \"(0, 1500 g]\"")));
  REQUIRE_THAT(q.parameters[0].range.hi, Catch::Matchers::WithinULP(1.5, 0));
  CHECK_THAT(load_error(replaced(kGood, "range = \"[0, pi/2)\"", "range = \"[0, 1 kg)\"")),
             Catch::Contains("parameters[1].range: '1 kg' is in kg (mass), but alpha is in rad"));
}

TEST_CASE("math that no renderer could typeset is refused with its field") {
  using Catch::Contains;
  // pdflatex stops with no PDF at an unclosed brace, and the rest of the text turns to math at
  // an unclosed '$'.
  CHECK_THAT(load_error(replaced(kGood, "statement = \"Two masses.\"",
                                 "statement = \"Two masses, $\\\\frac{1}{2$ apart.\"")),
             Contains("bad.toml:4: statement: the math \"$\\frac{1}{2$\" leaves a '{' unclosed"));
  CHECK_THAT(load_error(replaced(kGood, "question = \"Tensor?\"", "question = \"$I}$?\"")),
             Contains("parts[0].question: the math \"$I}\" closes a '}' that no '{' opened"));
  CHECK_THAT(load_error(replaced(kGood, "question = \"Tensor?\"",
                                 "question = \"Tensor?\"\nhint = \"It costs $5.\"")),
             Contains("parts[0].hint: a '$' opens math that no '$' closes: \"$5.\""));
  CHECK_THAT(load_error(replaced(kGood, "name = \"alpha\"",
                                 "name = \"alpha\"\ndescription = \"angle $\\\\alpha_{0\"")),
             Contains("parameters[1].description: a '$' opens math"));
  // Braces to show, \{ and \}, are no group; closed math is fine, however it nests.
  const Problem p = load_problem(test::write_file(
      "load/braces.toml",
      replaced(kGood, "statement = \"Two masses.\"",
               "statement = \"A set $\\\\{m, 2m\\\\}$ at $\\\\frac{a}{b_{1}}$.\"")));
  REQUIRE(p.statement == "A set $\\{m, 2m\\}$ at $\\frac{a}{b_{1}}$.");
}

TEST_CASE("bad files: the message names the file, the line and the field") {
  using Catch::Contains;
  CHECK_THAT(load_error("id = \"x\"\ntitle = \n"),
             Contains("bad.toml:2") && Contains("malformed TOML"));
  // Notepad's "Unicode" (UTF-16 with its mark) is said as such, not as an invalid UTF-8 byte.
  CHECK_THAT(load_error(std::string("\xff\xfei\0d\0", 6)),
             Contains("bad.toml: the problem file is UTF-16 (its first bytes say so); TOML is "
                      "UTF-8: save it as UTF-8"));
  CHECK_THAT(load_error(replaced(kGood, "title", "titel")),
             Contains("titel: unknown key") && Contains("expected one of"));
  CHECK_THAT(load_error(replaced(kGood, "solver = \"inertia\"\n", "")),
             Contains("solver: missing"));
  CHECK_THAT(load_error(replaced(kGood, "range = \"(0, inf)\"", "range = \"0 to inf\"")),
             Contains("parameters[0].range") && Contains("expected an interval"));
  CHECK_THAT(
      load_error(replaced(kGood, "default = 1", "default = -1")),
      Contains("bad.toml:9") && Contains("parameters[0].default") && Contains("outside its range"));
  CHECK_THAT(load_error(replaced(kGood, "default = \"30deg\"", "default = \"100deg\"")),
             Contains("parameters[1].default") && Contains("outside its range [0, pi/2)"));
  CHECK_THAT(load_error(replaced(kGood, "at = [1, 0, 0]", "at = [1, 0]")),
             Contains("body.masses[0].at") && Contains("3 expressions"));
  CHECK_THAT(load_error(replaced(kGood, "name = \"alpha\"", "name = \"m\"")),
             Contains("declared twice"));
  // What a student types or reads: a part id is one word; a title or question is not blank.
  CHECK_THAT(load_error(replaced(kGood, "id = \"a\"", "id = \"a b\"")),
             Contains("parts[0].id: 'a b' is no part id"));
  CHECK_THAT(load_error(replaced(kGood, "id = \"a\"", "id = \"\"")),
             Contains("parts[0].id: '' is no part id"));
  CHECK_THAT(load_error(replaced(kGood, "question = \"Tensor?\"", "question = \" \"")),
             Contains("parts[0].question: empty"));
  CHECK_THAT(load_error(replaced(kGood, "title = \"Two masses\"", "title = \"\"")),
             Contains("bad.toml:2: title: empty"));
  CHECK_THAT(load_error(replaced(kGood, "statement = \"Two masses.\"", "statement = \" \"")),
             Contains("bad.toml:4: statement: empty"));
  // A name no formula can use is refused at its own field, I (GiNaC's imaginary unit) too.
  CHECK_THAT(load_error(replaced(kGood, "name = \"alpha\"", "name = \"I\"")),
             Contains("parameters[1].name: 'I' is the imaginary unit in a formula"));
  CHECK_THAT(load_error(replaced(kGood, "name = \"alpha\"", "name = \"α\"")),
             Contains("parameters[1].name: 'α' is no name a formula can use"));
  CHECK_THAT(load_error(replaced(kGood, "name = \"alpha\"", "name = \"pi\"")),
             Contains("parameters[1].name: 'pi' is the constant π"));
  CHECK_THAT(load_error(kGood + "\n[[parts]]\nid = \"a\"\nquestion = \"Mass?\"\nanswers = "
                                "[\"mass\"]\n"),
             Contains("parts[1].id: part id 'a' is used twice; give each part its own"));
  // Degrees written as a bare number are radians; said where the degrees would be in range.
  CHECK_THAT(load_error(replaced(kGood, "default = \"30deg\"", "default = 30")),
             Contains("parameters[1].default: alpha = 30 rad is outside its range [0, pi/2); a "
                      "bare number is in radians: for degrees write \"30deg\""));
  CHECK_THAT(load_error(replaced(kGood, "default = \"30deg\"", "default = 300")),
             Contains("alpha = 300 rad is outside its range [0, pi/2)") && !Contains("degrees"));
  CHECK_THAT(load_error(replaced(kGood, "name = \"alpha\"", "name = \"sqrt\"")),
             Contains("parameters[1].name: 'sqrt' is a function in a formula (sqrt(x))"));
  CHECK_THAT(load_error(replaced(kGood, "name = \"alpha\"", "name = \"ln\"")),
             Contains("parameters[1].name: 'ln' is a function in a formula"));
  CHECK_THAT(load_error(replaced(kGood, "answers = [\"I\", ", "answers = [3, ")),
             Contains("parts[0].answers[0]"));
  CHECK_THAT(
      load_error(replaced(kGood, "masses = [", "tensor = [[1,0,0],[0,1,0],[0,0,1]]\nmasses = [")),
      Contains("cannot be combined"));
}

TEST_CASE("an answer's tolerance is a fraction or a percentage, as it is said") {
  using Catch::Contains;
  const auto with = [](const std::string& tolerance) {
    return replaced(kGood, "{ name = \"I_about_O\", quantity = \"I\" }",
                    "{ name = \"I_about_O\", quantity = \"I\", tolerance = " + tolerance + " }");
  };
  for (const auto& [written, fraction] :
       {std::pair{"0.02", 0.02}, std::pair{"\"2%\"", 0.02}, std::pair{"\"0.5 %\"", 0.005}}) {
    INFO(written);
    const Problem p = load_problem(test::write_file("load/tolerance.toml", with(written)));
    REQUIRE(p.parts[0].answers[1].tolerance);
    CHECK_THAT(*p.parts[0].answers[1].tolerance, Catch::Matchers::WithinULP(fraction, 1));
  }
  CHECK_THAT(load_error(with("\"2 percent\"")),
             Contains("parts[0].answers[1].tolerance: expected a relative tolerance between 0 and "
                      "1 (0.05 is 5%), got \"2 percent\""));
  CHECK_THAT(load_error(with("\"200%\"")), Contains("got \"200%\""));
}

TEST_CASE("an answer's named mistakes are read as written and refused with their field") {
  using Catch::Contains;
  const auto with = [](const std::string& mistakes) {
    return replaced(kGood, "{ name = \"I_about_O\", quantity = \"I\" }",
                    "{ name = \"I_about_O\", quantity = \"I\", mistakes = " + mistakes + " }");
  };
  const Problem p = load_problem(test::write_file(
      "load/mistakes.toml",
      with("[{ value = \"2 kg m^2\", what = \"one mass's\", remedy = \"sum both\" }, "
           "{ value = 0.5, what = \"half\", remedy = \"all\" }]")));
  const auto& mistakes = p.parts[0].answers[1].mistakes;
  REQUIRE(mistakes.size() == 2);
  CHECK(mistakes[0].value == "2 kg m^2");
  CHECK(mistakes[0].what == "one mass's");
  CHECK(mistakes[0].remedy == "sum both");
  CHECK(mistakes[0].field == "parts[0].answers[1].mistakes[0]");
  CHECK(mistakes[1].value == "0.5");
  CHECK(p.parts[0].answers[0].mistakes.empty());
  CHECK_THAT(load_error(with("3")),
             Contains("bad.toml:25: parts[0].answers[1].mistakes: expected a list"));
  CHECK_THAT(load_error(with("[3]")), Contains("parts[0].answers[1].mistakes[0]: expected a "
                                               "{ value, what, remedy } table, got 3"));
  CHECK_THAT(load_error(with("\"1\"")),
             Contains("mistakes: expected a list of { value, what, remedy } tables, got \"1\""));
  CHECK_THAT(load_error(with("[{ value = \"1\", what = \"x\" }]")),
             Contains("parts[0].answers[1].mistakes[0].remedy: missing"));
  CHECK_THAT(load_error(with("[{ value = \"1\", what = \" \", remedy = \"y\" }]")),
             Contains("parts[0].answers[1].mistakes[0].what: is empty"));
  CHECK_THAT(load_error(with("[{ value = \"1\", what = \"x\", remedy = \"y\", why = 1 }]")),
             Contains("mistakes[0].why: unknown key (expected one of: remedy, value, what)"));
  CHECK_THAT(load_error(with("[{ value = [1], what = \"x\", remedy = \"y\" }]")),
             Contains("mistakes[0].value: expected an expression"));
}

TEST_CASE("the solver, its motion keys and each quantity are checked when the file loads") {
  using Catch::Contains;
  // A schema of the loader's own (problem/solver_schema.hpp), not the program's registry.
  const SolverSchemas schemas{{"inertia", {}, {"I", "mass"}},
                              {"spinner", {"omega"}, {"rate"}}};
  const auto error = [&](const std::string& text) -> std::string {
    try {
      (void)load_problem(test::write_file("load/schema.toml", text), schemas);
    } catch (const InputError& e) {
      return e.what();
    }
    return "(loaded)";
  };
  CHECK(error(replaced(kGood, "{ name = \"I_about_O\", quantity = \"I\" }", "\"mass\"")) ==
        "(loaded)");
  CHECK_THAT(error(replaced(kGood, "quantity = \"I\"", "quantity = \"Ixx\"")),
             Contains("schema.toml:") && Contains("unknown quantity 'Ixx' for the inertia solver") &&
                 Contains("it computes: I, mass"));
  CHECK_THAT(error(replaced(kGood, "solver = \"inertia\"", "solver = \"inertial\"")),
             Contains("schema.toml:3: solver: unknown solver 'inertial' (known: inertia, spinner)"));
  CHECK_THAT(error(replaced(kGood, "solver = \"inertia\"", "solver = \"spinner\"")),
             Contains("motion: missing (a table { omega })"));
  CHECK_THAT(error(kGood + "\n[motion]\nomega = \"1\"\n"),
             Contains("the inertia solver takes no [motion] table"));
}

TEST_CASE("a refusal found after loading names the field's file and line") {
  // kGood's lines: the second parameter's default on 16, the masses on 20, the answers on 25.
  const Problem p = load_problem(test::write_file("load/lines.toml", kGood));
  const std::string file = p.file.string();
  CHECK(placed_in_file(p, "body.masses[1].mass: '2*m' is refused") ==
        file + ":20: body.masses[1].mass: '2*m' is refused");
  CHECK(placed_in_file(p, "parameters[1].default: too large") ==
        file + ":16: parameters[1].default: too large");
  CHECK(placed_in_file(p, "parts[0].answers[1].quantity: x") ==
        file + ":25: parts[0].answers[1].quantity: x");
  // An element of an array the file holds as one field is placed at the array.
  CHECK(placed_in_file(p, "body.masses[1].at[5]: x") == file + ":20: body.masses[1].at[5]: x");
  CHECK(field_in_file(p, "body.masses[0].at[2]") == file + ":20: body.masses[0].at[2]");
  CHECK(placed_in_file(p, "body: does not turn") == file + ":19: body: does not turn");
  CHECK(placed_in_file(p, "parameters[0].default (at these values): x") ==
        file + ":9: parameters[0].default (at these values): x");
  CHECK(placed_in_file(p, file + ": body: the centre is off") ==
        file + ":19: body: the centre is off");
  // Not a field of the file, or no field at all: as it is.
  for (const std::string& as_is :
       std::vector<std::string>{"motion.omega: x", file + ": motion: missing", "I1: is negative",
                                "no field here", "a body: in words", "--t-end: '2 m'", "body"}) {
    CHECK(placed_in_file(p, as_is) == as_is);
  }
  CHECK(field_in_file(p, "run.method") == file + ": run.method");
  // From the catalog, what is refused after loading came from values set: no line.
  Problem catalog = p;
  catalog.from_catalog = true;
  CHECK(placed_in_file(catalog, "body.masses[1].mass: x") == "body.masses[1].mass: x");
  // Rethrown placed, its type kept where nothing is added.
  try {
    try {
      throw InputError("body.masses[0].at[1]: cannot read");
    } catch (const InputError&) {
      rethrow_placed_in_file(p);
    }
  } catch (const InputError& e) {
    CHECK(std::string(e.what()) == file + ":20: body.masses[0].at[1]: cannot read");
  }
  CHECK_THROWS_AS(
      [&] {
        try {
          throw WorkLimitReached("body.masses[0].mass: over the budget");
        } catch (const InputError&) {
          rethrow_placed_in_file(p);
        }
      }(),
      WorkLimitReached);
}

TEST_CASE("set assignments NAME=VALUE") {
  const Problem p = load_problem(test::write_file("load/good3.toml", kGood));
  const auto v = parameter_values(p, {"m=2", "alpha = 45deg"});
  REQUIRE(v.at("m") == 2.0);
  REQUIRE_THAT(v.at("alpha"), Catch::Matchers::WithinULP(M_PI / 4, 1));
  REQUIRE_THROWS_WITH(parameter_values(p, {"q=1"}), Catch::Contains("unknown parameter 'q'") &&
                                                        Catch::Contains("known: m, alpha"));
  REQUIRE_THROWS_WITH(parameter_values(p, {"m"}), Catch::Contains("expected NAME=VALUE"));
  // A word after an assignment is the rest of its value, split off by the shell.
  REQUIRE_THROWS_WITH(parameter_values(p, {"alpha=45", "deg"}),
                      Catch::Contains("quote it: --set 'alpha=45 deg'"));
  REQUIRE_THROWS_WITH(require_each_set_once(p, {"alpha=45", "deg"}),
                      Catch::Contains("quote it: --set 'alpha=45 deg'"));
}
