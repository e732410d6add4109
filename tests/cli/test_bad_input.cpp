// The catalog of bad input: every kind the program knows, with its exit code and the words its
// one-line message must contain. Adding a validation means adding a row.
#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <fstream>
#include <iterator>

#include "cli/bad_input_fixtures.hpp"
#include "cli/run.hpp"
#include "temp_files.hpp"

using namespace wobble::test;

namespace {
struct Row {
  std::string what;
  std::vector<std::string> args;
  int exit_code;
  std::vector<std::string> words;
};

std::vector<Row> catalog() {
  const std::string tensor_body =
      "[body]\ntensor = [[\"m\", \"0\", \"0\"], [\"0\", \"m\", \"0\"], [\"0\", \"0\", \"3*m\"]]\n";
  std::string fractions;  // \frac\frac...11..1: nested with no brace to count
  for (int k = 0; k < 14000; ++k) fractions += "\\frac";
  fractions += std::string(14001, '1');
  return {
      {"unknown problem", {"solve", "no-such"}, 2, {"unknown problem 'no-such'", "known: "}},
      {"missing file",
       {"solve", "/nonexistent/p.toml"},
       2,
       {"/nonexistent/p.toml", "no such problem file"}},
      {"unknown parameter",
       {"solve", "taylor-10-35", "--set", "q=1"},
       2,
       {"--set q=1: unknown parameter 'q' of taylor-10-35", "known: m, a"}},
      {"not a number",
       {"solve", "taylor-10-35", "--set", "m=abc"},
       2,
       {"--set m", "'abc' is not a number"}},
      {"NaN", {"solve", "taylor-10-35", "--set", "m=nan"}, 2, {"--set m", "finite"}},
      {"infinite", {"solve", "taylor-10-35", "--set", "m=inf"}, 2, {"--set m", "finite"}},
      {"overflow",
       {"solve", "taylor-10-35", "--set", "a=1e400"},
       2,
       {"--set a", "1e+400", "outside the range of double precision"}},
      {"exp of a huge number (CLN would give 1)",
       {"solve", "taylor-10-35", "--set", "a=exp(exp(exp(10)))"},
       2,
       {"--set a", "exp of a number about 9.4e+9565"}},
      {"zero mass",
       {"solve", "taylor-10-35", "--set", "m=0"},
       2,
       {"m = 0 kg", "outside its range (0, inf)"}},
      {"negative length",
       {"solve", "taylor-10-35", "--set", "a=-2"},
       2,
       {"a = -2 m", "outside its range"}},
      {"angle out of range",
       {"solve", "three-atom-molecule", "--set", "alpha=200deg"},
       2,
       {"--set alpha", "outside its range (0, pi]"}},
      {"degrees for a mass",
       {"solve", "taylor-10-35", "--set", "m=3deg"},
       2,
       {"--set m", "'3deg' is in deg (an angle), but m is in kg (mass)"}},
      {"a length for a mass",
       {"solve", "taylor-10-35", "--set", "m=0.5 m"},
       2,
       {"--set m", "'0.5 m' is in m (length), but m is in kg (mass)"}},
      {"a value and a word that is no unit",
       {"solve", "taylor-10-35", "--set", "a=0.16 parsecs"},
       2,
       {"--set a", "cannot read the unit 'parsecs'"}},
      {"a key's two sides that disagree",
       {"solve", "heavy-top", "--set", "θ0=30° = 0.6 rad"},
       2,
       {"--set theta0", "the two sides of '30° = 0.6 rad' differ (0.5235987756 and 0.6 rad)"}},
      {"malformed --set", {"solve", "taylor-10-35", "--set", "m"}, 2, {"expected NAME=VALUE"}},
      {"an answer the shell split at its spaces",
       {"check", "flying-plate", "I0", "0.00072", "kg", "m^2"},
       2,
       {"put it in quotes: wobble check flying-plate I0 '0.00072 kg m^2'"}},
      {"an --answer the shell split at its spaces",
       {"check", "flying-plate", "I0", "--answer", "m", "R^2/4", "--set", "R=12 cm"},
       2,
       {"put it in quotes: wobble check flying-plate I0 --answer 'm R^2/4' --set 'R=12 cm'"}},
      {"an answer after --name the shell split at its spaces",
       {"check", "flying-plate", "--name", "I0", "0.00072", "kg", "m^2"},
       2,
       {"put it in quotes: wobble check flying-plate --name I0 '0.00072 kg m^2'"}},
      {"no name between bars or in norm(..), where an answer's name may stand",
       {"check", "flying-plate", "t_max", "pi/norm(Omega_sp~ace)"},
       2,
       {"wobble: t_max: expression \"pi/norm(Omega_sp~ace)\" is refused"}},
      {"no name between bars, where an answer's name may stand",
       {"check", "flying-plate", "t_max", "pi/|Omega_sp~ace|"},
       2,
       {"wobble: t_max: cannot read expression"}},
      {"an unknown option after an answer is no negative answer",
       {"check", "flying-plate", "I0", "0.00072", "--frob"},
       2,
       {"not expected: --frob"}},
      {"a --set value the shell split at its space",
       {"solve", "flying-plate", "--set", "omega=10", "rpm"},
       2,
       {"got 'rpm'", "quote it: --set 'omega=10 rpm'"}},
      {"unknown format", {"solve", "taylor-10-35", "--format", "pdf"}, 2, {"--format", "pdf"}},
      {"unknown part", {"solve", "taylor-10-35", "--part", "z"}, 2, {"no part 'z'", "parts: a, b"}},
      {"unknown command",
       {"frobnicate"},
       2,
       {"unknown command 'frobnicate'",
        "commands: list, solve, check, worksheet, simulate, bench, keys"}},
      {"keys without an action",
       {"keys"},
       2,
       {"--check", "--update", "give --check, --update or --variants"}},
      {"keys with both actions", {"keys", "--check", "--update"}, 2, {"excludes"}},
      {"malformed TOML",
       {"solve", file("toml", with("title = \"t\"", "title = "))},
       2,
       {"toml.toml:2", "malformed TOML"}},
      {"unknown key",
       {"solve", file("key", with("statement", "statment"))},
       2,
       {"statment: unknown key"}},
      {"undefined symbol",
       {"solve", file("sym", with("mass = \"m\", at = [\"1\"", "mass = \"q*m\", at = [\"1\""))},
       2,
       {"body.masses[0].mass", "undefined symbol 'q'"}},
      {"mass in a unit of length",
       {"solve",
        file("massunit", with("mass = \"m\", at = [\"1\"", "mass = \"2 m\", at = [\"1\""))},
       2,
       {"body.masses[0].mass: '2 m' is in m (length); it must be in kg (mass)"}},
      {"position in an unknown unit",
       {"solve",
        file("posunit", with("at = [\"1\", \"0\", \"0\"]", "at = [\"1 parsecs\", \"0\", \"0\"]"))},
       2,
       {"body.masses[0].at[0]: cannot read the unit 'parsecs'"}},
      {"syntax error",
       {"solve", file("syntax", with("at = [\"1\", \"0\", \"0\"]", "at = [\"1\", \"0*\", \"0\"]"))},
       2,
       {"body.masses[0].at[1]", "cannot read expression \"0*\""}},
      {"negative mass expression",
       {"solve", file("negmass", with("mass = \"m\", at = [\"1\"", "mass = \"-m\", at = [\"1\""))},
       2,
       {"body.masses[0].mass", "\"-m\" is -1", "must be > 0"}},
      {"coinciding masses",
       {"solve",
        file("coincide", with("at = [\"0\", \"1\", \"0\"]", "at = [\"1\", \"0\", \"0\"]"))},
       2,
       {"body.masses[1].at", "coincides with body.masses[0].at"}},
      {"unknown shape",
       {"solve",
        file("shape", with("masses = [ { mass = \"m\", at = [\"1\", \"0\", \"0\"] }, { mass = "
                           "\"m\", at = [\"0\", \"1\", \"0\"] } ]",
                           "shapes = [ { shape = \"cube\", mass = \"m\", sizes = [\"1\"] } ]"))},
       2,
       {"body.shapes[0].shape", "unknown shape 'cube'"}},
      {"wrong number of sizes",
       {"solve",
        file("sizes",
             with("masses = [ { mass = \"m\", at = [\"1\", \"0\", \"0\"] }, { mass = \"m\", at = "
                  "[\"0\", \"1\", \"0\"] } ]",
                  "shapes = [ { shape = \"box\", mass = \"m\", sizes = [\"1\", \"2\"] } ]"))},
       2,
       {"body.shapes[0].sizes", "takes 3 sizes"}},
      {"triangle inequality",
       {"solve", file("triangle", with("[body]\nmasses = [ { mass = \"m\", at = [\"1\", \"0\", "
                                       "\"0\"] }, { mass = \"m\", at = [\"0\", \"1\", \"0\"] } ]\n",
                                       tensor_body))},
       2,
       {"body.tensor", "triangle inequality", "I1 + I2 = 1 + 1 = 2 < I3 = 3"}},
      {"unknown solver",
       {"solve", file("solver", with("solver = \"inertia\"", "solver = \"magic\""))},
       2,
       {"unknown solver 'magic'", "known: inertia"}},
      {"unknown quantity",
       {"solve", file("quantity", with("answers = [\"I\"]", "answers = [\"spin\"]"))},
       2,
       {"unknown quantity 'spin'"}},
      {"bad range",
       {"solve", file("range", with("range = \"(0, inf)\"", "range = \"(1, 0)\""))},
       2,
       {"parameters[0].range", "empty interval"}},
      {"top not axially symmetric",
       {"solve",
        file("asym", top_with("sizes = [\"1\", \"1\", \"2\"]", "sizes = [\"1\", \"2\", \"3\"]"))},
       2,
       {"needs a body symmetric about z, but about the centre of mass I_xx = ",
        "solver = \"asymmetric_top\""}},
      {"asymmetric top: moments out of order",
       {"solve", "asymmetric-top", "--set", "I1=3.5"},
       2,
       {"I_xx < I_yy < I_zz", "I_xx = 3.5", "relabel the axes"}},
      {"asymmetric top: two moments equal",
       {"solve", "asymmetric-top", "--set", "I2=2"},
       2,
       {"I_xx < I_yy < I_zz", "symmetric top", "torque_free_symmetric"}},
      {"asymmetric top: moments violate the triangle inequality",
       {"solve", "asymmetric-top", "--set", "I3=6"},
       2,
       {"body.tensor", "triangle inequality", "< I3 = 6"}},
      {"asymmetric top: on the separatrix (spin exactly about e2)",
       {"solve", file("separatrix", kAsym)},
       2,
       {"period: w(0) lies on the separatrix", "no period"}},
      {"asymmetric top: motion keys of another solver",
       {"solve", file("asymkeys", asym_with("w1 = \"0\"", "omega = \"0\""))},
       2,
       {"motion", "omega: unknown key"}},
      {"asymmetric top: w(0) zero",
       {"solve", file("asymzero", asym_with("w2 = \"s\"", "w2 = \"0*s\""))},
       2,
       {"motion: w(0)", "is zero"}},
      {"heavy top: vertical start",
       {"solve", "heavy-top", "--set", "theta0=0"},
       2,
       {"theta0 = 0 rad", "outside its range (0, pi)"}},
      {"heavy top: negative length",
       {"solve", "heavy-top", "--set", "l=-0.08"},
       2,
       {"l = -0.08 m", "outside its range"}},
      {"heavy top: centre of mass off the axis",
       {"solve", file("offaxis", repo_problem_with("heavy-top", "center = [\"0\", \"0\", \"l\"]",
                                                   "center = [\"R\", \"0\", \"l\"]"))},
       2,
       {"body: the heavy_top solver needs the centre of mass on the z axis, but its x is R"}},
      {"heavy top: centre of mass below the pivot",
       {"solve", file("below", repo_problem_with("heavy-top", "center = [\"0\", \"0\", \"l\"]",
                                                 "center = [\"0\", \"0\", \"-l\"]"))},
       2,
       {"body: the centre of mass is at z = -0.08 m", "above the pivot"}},
      {"euler angles: theta out of range",
       {"solve", "euler-angles", "--set", "theta=200deg"},
       2,
       {"--set theta", "outside its range [0, pi]"}},
      {"euler angles: phi out of range",
       {"solve", "euler-angles", "--set", "phi=-180deg"},
       2,
       {"--set phi", "outside its range (-pi, pi]"}},
      {"euler angles: motion theta outside [0, pi]",
       {"solve", file("thetaexpr", repo_problem_with("euler-angles", "theta = \"theta\"",
                                                     "theta = \"theta + pi\""))},
       2,
       {"motion.theta", "must lie in [0, pi]"}},
      {"euler angles: body not a symmetric top",
       {"solve", file("eulerbody", repo_problem_with("euler-angles", "[\"0\", \"I1\", \"0\"]",
                                                     "[\"0\", \"I3\", \"0\"]"))},
       2,
       {"body: the euler_angles solver needs a body symmetric about z", "I_xx = I1 and I_yy = I3"}},
      {"top alpha at the limit",
       {"solve", "flying-plate", "--set", "alpha=90deg"},
       2,
       {"--set alpha: alpha = 90deg = 1.570796327 rad is outside its range [0, pi/2)"}},
      {"top without motion",
       {"solve", file("nomotion", top_with("[motion]\nomega = \"3\"\nalpha = \"alpha\"\n", ""))},
       2,
       {"motion: missing"}},
      {"top alpha not a parameter",
       {"solve", file("alphaexpr", top_with("alpha = \"alpha\"", "alpha = \"alpha/2\""))},
       2,
       {"motion.alpha", "must name a parameter"}},
      {"top omega not positive",
       {"solve", file("omega", top_with("omega = \"3\"", "omega = \"-3\""))},
       2,
       {"motion.omega", "must be > 0"}},
      // Huge input is refused unread (a command-line argument is at most 128 KiB on Linux).
      {"a 100000-digit --set value",
       {"solve", "taylor-10-35", "--set", "m=" + std::string(100000, '7')},
       2,
       {"--set: 100002 characters", "at most 1000"}},
      {"an answer vector of 20000 components",
       {"check", "flying-plate", "b", "--name", "L0_body", "--answer",
        "[" +
            [] {
              std::string s = "1";
              for (int i = 1; i < 20000; ++i) s += ",1";
              return s;
            }() +
            "]"},
       2,
       {"--answer: more than 100 entries"}},
      {"an answer of 120000 characters",
       {"check", "flying-plate", "a", "--name", "I0", "--answer", std::string(120000, '1')},
       2,
       {"--answer: 120000 characters", "at most 90000"}},
      // Found by fuzzing: each crashed or hung wobble before its guard.
      {"--force over a device (it replaced /dev/full when run as root)",
       {"solve", "flying-plate", "--figure", "/dev/null", "--force"},
       2,
       {"/dev/null: is not a regular file"}},
      {"--out onto a folder",
       {"simulate", "tennis-racket", "--out", "/tmp/", "--force"},
       2,
       {"--out"}},
      {"a problem id of 5000 characters",
       {"solve", std::string(5000, 'a')},
       2,
       {"unknown problem 'aaaaaaaaaa", "...' (known: "}},
      {"a function called without arguments (crashed GiNaC's parser)",
       {"check", "flying-plate", "a", "--name", "I0", "--answer", "sqrt()*m"},
       2,
       {"--answer: expression \"sqrt()*m\" is refused", "without arguments"}},
      {"a call without arguments in an exponent (crashed GiNaC's parser)",
       {"check", "flying-plate", "a", "--name", "I0", "--answer", "m*R^sqrt()"},
       2,
       {"is refused", "without arguments"}},
      {"a function outside the list (tgamma would compute 99999! exactly)",
       {"check", "flying-plate", "a", "--name", "I0", "--answer", "m*tgamma(100000)"},
       2,
       {"is refused", "unknown function 'tgamma'"}},
      {"a constant GiNaC knows but wobble does not (the printer failed on it)",
       {"check", "flying-plate", "a", "--name", "I0", "--answer", "Catalan*m"},
       2,
       {"undefined symbol 'Catalan'"}},
      {"the imaginary unit",
       {"check", "flying-plate", "a", "--name", "I0", "--answer", "I*m*R^2"},
       2,
       {"undefined symbol 'I'"}},
      {"an answer with no value at the set values (0^m in a denominator)",
       {"check", "flying-plate", "a", "--name", "I0", "--answer", "2^m/0^m/m"},
       2,
       {"--answer", "no value at these values", "division by zero"}},
      {"a signed symbolic exponent without parentheses (GiNaC took the rest of the sum into it;"
       " a signed number, 10^-4, reads as 10^(-4))",
       {"check", "flying-plate", "a", "--name", "I0", "--answer", "m*R^2/4+2^-m+22^423"},
       2,
       {"is refused", "a signed exponent must be in parentheses"}},
      {"a control character in an expression",
       {"check", "flying-plate", "a", "--name", "I0", "--answer", "m*R^2/(1+cos\x1b(alpha))"},
       2,
       {"is refused", "it contains the control character U+001B"}},
      {"a letter no expression uses, named as typed",
       {"check", "flying-plate", "a", "--name", "I0", "--answer", "5é"},
       2,
       {"expression \"5é\" is refused: it contains 'é' (U+00E9), which no expression uses"}},
      {"a sign after the unit, named as typed",
       {"check", "flying-plate", "a", "--name", "I0", "--answer", "0.00072 kg m² ✓"},
       2,
       {"cannot read the unit 'kg m^2 ✓': unexpected '✓' (U+2713)"}},
      {"a byte that is no UTF-8",
       {"check", "flying-plate", "a", "--name", "I0", "--answer", "m*R^2/4\xff"},
       2,
       {"the byte 0xFF, which is no UTF-8"}},
      {"LaTeX with a brace left open",
       {"check", "flying-plate", "a", "--name", "I0", "--answer", "\\frac{m R^2}{4"},
       2,
       {"--answer: '}' missing"}},
      {"LaTeX fractions nested 14000 deep without a brace (overflowed the stack)",
       {"check", "flying-plate", "a", "--name", "I0", "--answer", fractions},
       2,
       {"--answer: nested deeper than 100 levels"}},
      {"a LaTeX command that is not read",
       {"check", "flying-plate", "a", "--name", "I0", "--answer", "\\int_0^R m\\,dr"},
       2,
       {"--answer: \\int is not read"}},
      {"a control character in LaTeX",
       {"check", "flying-plate", "a", "--name", "I0", "--answer", "\\frac{m}{2}\x1b"},
       2,
       {"--answer: cannot read the control character U+001B in LaTeX"}},
      {"a number with a huge exponent (hung computing it)",
       {"solve", "taylor-10-35", "--set", "m=888880e8888888888888"},
       2,
       {"--set m", "888880e8888888888888", "exponent beyond 400"}},
      {"an exact power too large (hung computing it)",
       {"check", "flying-plate", "a", "--name", "I0", "--answer", "m*R^2*((2^999)^999)^999"},
       2,
       {"is refused", "exponents multiply to more than 1000"}},
      {"an exact power inside an unclosed exponent (ran out of memory computing it)",
       {"check", "flying-plate", "a", "--name", "I0", "--answer", "0^((66666666^666666666 -*"},
       2,
       {"is refused", "a power inside an exponent"}},
      {"a number of 60 digits",
       {"check", "flying-plate", "a", "--name", "I0", "--answer", std::string(60, '9')},
       2,
       {"is refused", "more than 50 digits"}},
      {"expression nested too deep",
       {"solve", file("deep", with("mass = \"m\", at = [\"1\"",
                                   "mass = \"" + std::string(150, '(') + "m" +
                                       std::string(150, ')') + "\", at = [\"1\""))},
       2,
       {"body.masses[0].mass", "nested deeper than 100 levels"}},
      {"expression too long",
       {"solve", file("long", with("mass = \"m\", at = [\"1\"",
                                   "mass = \"m" + std::string(12000, '+') + "m\", at = [\"1\""))},
       2,
       {"body.masses[0].mass", "characters long", "limit is 10000"}},
      {"--set value too long",
       {"solve", "taylor-10-35", "--set", "m=" + std::string(12000, '1')},
       2,
       {"--set: 12002 characters", "at most 1000"}},
      {"unknown scene", {"simulate", "no-such"}, 2, {"unknown scene 'no-such'", "tennis-racket"}},
      {"unknown scene parameter",
       {"simulate", "tennis-racket", "--set", "omega=12"},
       2,
       {"--set omega=12: unknown parameter 'omega' of tennis-racket", "known: m, a, b, c, w"}},
      {"unknown effect",
       {"simulate", file("s_effect", kScene + "[effects]\nmagnetism = { B = 1 }\n")},
       2,
       {"effects.magnetism", "unknown effect", "gravity, free_flight or torque"}},
      {"scene missing omega",
       {"simulate", file("s_omega", scene_with("omega = [0.1, 2, 0.1]", ""))},
       2,
       {"initial.omega", "missing"}},
      {"non-unit quaternion",
       {"simulate",
        file("s_quat", scene_with("omega = [0.1, 2, 0.1]",
                                  "omega = [0.1, 2, 0.1]\nquaternion = [1, 0.1, 0, 0]"))},
       2,
       {"initial.quaternion", "(1, 0.1, 0, 0)", "unit quaternion"}},
      {"matrix not a rotation",
       {"simulate",
        file("s_matrix",
             scene_with("omega = [0.1, 2, 0.1]",
                        "omega = [0.1, 2, 0.1]\nmatrix = [[1, 0, 0], [0, 1, 0], [0, 0, -1]]"))},
       2,
       {"initial.matrix", "not a rotation", "det = -1"}},
      {"two orientations",
       {"simulate",
        file("s_two",
             scene_with("omega = [0.1, 2, 0.1]",
                        "omega = [0.1, 2, 0.1]\neuler = [0, 0, 0]\nquaternion = [1, 0, 0, 0]"))},
       2,
       {"initial", "give the orientation once"}},
      {"negative time span",
       {"simulate", file("s_tend", scene_with("t_end = 1", "t_end = -1"))},
       2,
       {"run.t_end", "\"-1\" is -1", "must be finite and > 0"}},
      {"one sample",
       {"simulate", file("s_samples", scene_with("samples = 3", "samples = 1"))},
       2,
       {"run.samples", "from 2 to 1000000"}},
      {"scene tolerance out of range",
       {"simulate", file("s_tol", scene_with("samples = 3", "samples = 3\ntolerance = 1e-20"))},
       2,
       {"run.tolerance", "from 1e-14 to 1e-2"}},
      {"--tolerance out of range",
       {"simulate", "tennis-racket", "--tolerance", "0.5"},
       2,
       {"--tolerance", "0.5", "1e-14 to 1e-2"}},
      {"unknown output",
       {"simulate",
        file("s_output", scene_with("outputs = [\"omega_body\"]", "outputs = [\"spin\"]"))},
       2,
       {"run.outputs[0]", "unknown output 'spin'", "omega_body"}},
      {"unknown frame",
       {"simulate", file("s_frame", scene_with("omega = [0.1, 2, 0.1]",
                                               "omega = [0.1, 2, 0.1]\nomega_frame = \"lab\""))},
       2,
       {"initial.omega_frame", "'lab' is not a frame"}},
      {"gravity and free flight together",
       {"simulate",
        file("s_both", kScene + "[effects]\ngravity = { pivot = [0, 0, 0] }\nfree_flight = {}\n")},
       2,
       {"effects", "exclude each other"}},
      {"gravity without a mass",
       {"simulate",
        file("s_tensor", scene_with("shapes = [ { shape = \"box\", mass = 1, sizes = [3, 2, 1] } ]",
                                    "tensor = [[1, 0, 0], [0, 2, 0], [0, 0, 2.5]]") +
                             "[effects]\ngravity = { pivot = [0, 0, 0] }\n")},
       2,
       {"effects.gravity", "needs the body's mass"}},
      {"unknown method",
       {"simulate", "tennis-racket", "--method", "euler"},
       2,
       {"--method", "unknown method 'euler'", "rkf78"}},
      {"exact solver with a torque",
       {"simulate", "spin-up", "--method", "exact"},
       2,
       {"--method exact", "torque-free motion only", "a torque"}},
      {"exact solver with gravity on a box: no symmetric top",
       {"simulate",
        file("s_box_gravity",
             scene_with("[run]", "[effects]\ngravity = { g = 9.81, pivot = [0, 0, -1] }\n\n[run]")),
        "--method", "exact"},
       2,
       {"--method exact", "gravity about a pivot", "no symmetric top pivoted on its axle"}},
      {"a heavy top without spin about its axle (a pendulum)",
       {"solve", "heavy-top", "--set", "psidot0=0"},
       2,
       {"motion.psidot0", "p_psi = 0", "a pendulum, not a top"}},
      {"exact solver with a top started vertical and moving",
       {"simulate", "heavy-top", "--set", "theta0=0", "--set", "thetadot0=5", "--method", "exact"},
       2,
       {"--method exact", "the axle starting vertical and moving", "start it tilted"}},
      {"splitting with a torque",
       {"simulate", "spin-up", "--method", "split2"},
       2,
       {"--method split2", "torque-free motion only", "a torque"}},
      {"closed form for an asymmetric body",
       {"simulate", "tennis-racket", "--method", "closed_form"},
       2,
       {"--method closed_form", "not axially symmetric", "0.0005725"}},
      {"--out with an unknown extension",
       {"simulate", "tennis-racket", "--out", "x.txt"},
       2,
       {"--out", "x.txt", ".csv or .json"}},
      {"--out over an existing file",
       {"simulate", "tennis-racket", "--out", existing_file()},
       2,
       {"--out", "existing.csv exists", "--force"}},
      {"scene parameter out of range",
       {"simulate", "heavy-top", "--set", "l=-1"},
       2,
       {"--set l", "outside its range"}},
      {"bench --plot over an existing file",
       {"bench", "--quick", "--plot", existing_file()},
       2,
       {"--plot", "existing.csv exists", "--force"}},
      {"bench with an unknown format", {"bench", "--format", "pdf"}, 2, {"--format", "pdf"}},
      {"solve --figure over an existing file",
       {"solve", "flying-plate", "--figure", text_file("figure.svg", "<svg/>")},
       2,
       {"--figure", "figure.svg exists", "--force"}},
      {"check: answers file missing",
       {"check", "four-masses", "--answers", "/nonexistent/answers.txt"},
       2,
       {"--answers", "/nonexistent/answers.txt", "is not a file"}},
      {"check: answers file with a variant that is no number",
       {"check", "four-masses", "--answers", text_file("answers.txt", "variant = seven\nI = 1\n")},
       2,
       {"--answers", "line 1", "variant 'seven'"}},
      {"check: answers file and --answer together",
       {"check", "four-masses", "a", "--answer", "1", "--answers", existing_file()},
       2,
       {"--answers", "excludes"}},
      {"check: --format without --answers",
       {"check", "four-masses", "a", "--answer", "1", "--format", "json"},
       2,
       {"--format", "--answers"}},
      {"serve: a port that is none",
       {"serve", "--port", "70000"},
       2,
       {"--port", "70000", "0 to 65535"}},
      {"serve: a problems folder that is none",
       {"serve", "--problems", "/nonexistent/problems"},
       2,
       {"--problems", "/nonexistent/problems", "not a folder"}},
      {"page: not an HTML file",
       {"page", "heavy-top", "--out", "/tmp/never.txt"},
       2,
       {"--out", "/tmp/never.txt", "FILE.html"}},
      {"page: over an existing file",
       {"page", "heavy-top", "--out", text_file("page.html", "<p>mine</p>")},
       2,
       {"--out", "page.html exists", "--force"}},
      {"page: unknown problem",
       {"page", "no-such-problem", "--out", "/tmp/never.html"},
       2,
       {"no-such-problem"}},
      {"page: a variant that is no number",
       {"page", "heavy-top", "--variant", "seven", "--out", "/tmp/never.html"},
       2,
       {"--variant", "seven"}},
      {"page: a folder that does not exist",
       {"page", "heavy-top", "--out", "/nonexistent/dir/page.html"},
       2,
       {"/nonexistent/dir/page.html"}},
      {"page: no --out", {"page", "heavy-top"}, 2, {"--out"}},
      {"export: unknown problem",
       {"export", "prairielearn", "no-such-problem", "--out", "/tmp/never-written"},
       2,
       {"no-such-problem"}},
      {"export: variants not a range",
       {"export", "moodle", "four-masses", "--variants", "0-3", "--out", "/tmp/never.xml"},
       2,
       {"--variants", "'0-3'"}},
      {"export: tolerance out of range",
       {"export", "moodle", "four-masses", "--tolerance", "2", "--out", "/tmp/never.xml"},
       2,
       {"--tolerance", "between 0 and 1"}},
      {"export: sigfigs out of range",
       {"export", "prairielearn", "four-masses", "--sigfigs", "0", "--out", "/tmp/never-written"},
       2,
       {"--sigfigs", "from 1 to 15"}},
      {"export: quiz over an existing file",
       {"export", "moodle", "four-masses", "--variants", "1-2", "--out", existing_file()},
       2,
       {"--out", "existing.csv exists", "--force"}},
      {"export: a quiz in a folder that does not exist",
       {"export", "moodle", "four-masses", "--out", "/nonexistent/dir/quiz.xml"},
       2,
       {"/nonexistent/dir/quiz.xml", "cannot be written here"}},
      {"export: an autograder in a folder that does not exist",
       {"export", "gradescope", "four-masses", "--deb", "/nonexistent/wobble.deb", "--out",
        "/nonexistent/dir/autograder.zip"},
       2,
       {"/nonexistent/dir/autograder.zip", "cannot be written here"}},
      {"export: question folders where none can be created",
       {"export", "prairielearn", "four-masses", "--out", "/proc/wobble/questions"},
       2,
       {"--out: /proc/wobble/questions (in /proc): cannot be written here"}},
      {"export: question folders under a file",
       {"export", "prairielearn", "four-masses", "--out", existing_file() + "/questions"},
       2,
       {"--out", "existing.csv is a file, not a folder"}},
      {"export: a package that is no Debian package",
       {"export", "gradescope", "four-masses", "--deb", existing_file(), "--out", "/tmp/never.zip"},
       2,
       {"--deb", "existing.csv", "not a Debian package"}},
      {"export: a package that does not exist",
       {"export", "gradescope", "four-masses", "--deb", "/nonexistent/wobble.deb", "--out",
        "/tmp/never.zip"},
       2,
       {"--deb", "cannot read"}},
      {"export: unknown system", {"export", "canvas", "four-masses"}, 2, {"canvas"}},
      {"export: an unknown option, its value no second problem",
       {"export", "moodle", "four-masses", "-o", "/tmp/never.xml"},
       2,
       {"not expected: -o"}},
      {"export: an unknown option among the required",
       {"export", "gradescope", "four-masses", "--frob", "--out", "/tmp/never.zip"},
       2,
       {"not expected: --frob"}},
      {"export: two problems where the system takes one",
       {"export", "moodle", "four-masses", "flying-plate", "--out", "/tmp/never.xml"},
       2,
       {"problem", "give one problem, not 2"}},
      {"check: a word that is no part nor an answer's name",
       {"check", "flying-plate", "ψ_L", "7.6°"},
       2,
       {"part: problem flying-plate has no part or answer 'ψ_L'", "(a) I0, I; (b) L0_body"}},
      {"check: empty answer",
       {"check", "flying-plate", "h", "--answer", ""},
       2,
       {"--answer", "empty"}},
      {"check: a unit glued to the number where its letter is a symbol",
       {"check", "flying-plate", "h", "--answer", "0.16m"},
       2,
       {"--answer", "\"0.16m\"",
        "m is one of the problem's symbols here: 0.16*m for it, 0.16 m for the unit"}},
      {"check: a glued unit that is no unit",
       {"check", "flying-plate", "h", "--answer", "0.16sec2x"},
       2,
       {"--answer", "\"0.16sec2x\"", "put a space between a number and its unit"}},
      {"check: wrong shape",
       {"check", "flying-plate", "h", "--answer", "[1, 2, 3]"},
       2,
       {"--answer", "t_max wants a number, not a 3-vector"}},
      {"check: absurd unit",
       {"check", "flying-plate", "h", "--answer", "0.16 parsecs"},
       2,
       {"--answer", "unknown unit 'parsecs'"}},
      {"check: part with several answers",
       {"check", "flying-plate", "e", "--answer", "1"},
       2,
       {"--name", "several answers", "Omega_body, Omega_space"}},
      {"check: unknown answer name",
       {"check", "flying-plate", "e", "--name", "spin", "--answer", "1"},
       2,
       {"--name", "no answer 'spin'"}},
      {"check: unknown part",
       {"check", "flying-plate", "z", "--answer", "1"},
       2,
       {"no part or answer 'z'", "answers by part: (a) I0, I; (b)"}},
      {"check: tolerance out of range",
       {"check", "flying-plate", "h", "--answer", "1", "--tolerance", "2"},
       2,
       {"--tolerance", "between 0 and 1"}},
      {"variant out of range",
       {"solve", "flying-plate", "--variant", "0"},
       2,
       {"--variant", "0 is out of range", "1 to 1000000"}},
      {"keys --variants not a range",
       {"keys", "--variants", "x", "--out", "/tmp"},
       2,
       {"--variants", "'x' is not a range"}},
      {"handout in JSON",
       {"solve", "flying-plate", "--variant", "1", "--handout", "--format", "json"},
       2,
       {"--handout", "not json"}},
      {"keys --problem unknown",
       {"keys", "--variants", "1-2", "--out", "/tmp", "--problem", "no-such"},
       2,
       {"--problem", "unknown problem 'no-such'", "flying-plate"}},
      {"answer tolerance out of range",
       {"solve",
        file("anstol", with("answers = [\"I\"]", "answers = [ { name = \"I\", tolerance = 2 } ]"))},
       2,
       {"parts[0].answers[0].tolerance", "between 0 and 1"}},
      {"simulate --out into a folder that does not exist: refused before the run",
       {"simulate", "tennis-racket", "--out", "/nonexistent/x.csv"},
       2,
       {"/nonexistent/x.csv", "cannot be written"}},
      {"simulate --plot into a folder that does not exist: refused before the run",
       {"simulate", "tennis-racket", "--plot", "/nonexistent/x.svg"},
       2,
       {"/nonexistent/x.svg", "cannot be written"}},
      {"an answer name used twice (check --name would find only one)",
       {"solve", file("dupname", with("answers = [\"I\"]", "answers = [\"I\", \"I\"]"))},
       2,
       {"answers[1]", "answer name 'I' is used twice"}},
      {"an escape sequence in an answer is not echoed to the terminal",
       {"check", "flying-plate", "a", "--name", "I0", "--answer", "m\x1b[31m"},
       2,
       {"--answer", "m?[31m", "control"}},
      {"simulate --samples a fraction",
       {"simulate", "tennis-racket", "--samples", "2.5"},
       2,
       {"--samples", "'2.5' is not a whole number"}},
      {"simulate --samples beyond any count",
       {"simulate", "tennis-racket", "--samples", "1e30"},
       2,
       {"--samples", "'1e30' is too large a count"}},
      {"simulate --t-end in a unit of length",
       {"simulate", "tennis-racket", "--t-end", "2 m"},
       2,
       {"--t-end", "'2 m' is in m (length); it must be in s (time)"}},
      {"simulate --t-end with a word that is no unit",
       {"simulate", "tennis-racket", "--t-end", "2 parsecs"},
       2,
       {"--t-end", "cannot read the unit 'parsecs'"}},
      {"simulate --t-end not positive",
       {"simulate", "tennis-racket", "--t-end", "-1"},
       2,
       {"--t-end", "-1", "> 0"}},
      {"an answer nested 5000 brackets deep (refused before it is rearranged)",
       {"check", "flying-plate", "a", "--name", "I", "--answer",
        std::string(5000, '[') + std::string(5000, ']')},
       2,
       {"--answer", "nested deeper than 100 levels"}},
      {"a rod as a torque-free top (no moment about its line)",
       {"solve",
        file("rodtop",
             top_with(
                 "shapes = [ { shape = \"box\", mass = \"m\", sizes = [\"1\", \"1\", \"2\"] } ]",
                 "masses = [ { mass = \"m\", at = [\"0\", \"0\", \"1\"] }, "
                 "{ mass = \"m\", at = [\"0\", \"0\", \"-1\"] } ]"))},
       2,
       {"body", "the torque_free_symmetric solver needs a body that can spin", "a rod"}},
      {"a point as a torque-free top",
       {"solve",
        file("pointtop",
             top_with(
                 "shapes = [ { shape = \"box\", mass = \"m\", sizes = [\"1\", \"1\", \"2\"] } ]",
                 "masses = [ { mass = \"m\", at = [\"0\", \"0\", \"0\"] } ]"))},
       2,
       {"body", "a point", "every moment is 0"}},
      {"a rod as a scene's body",
       {"simulate",
        file("s_rod",
             scene_with(
                 "shapes = [ { shape = \"box\", mass = 1, sizes = [3, 2, 1] } ]",
                 "masses = [ { mass = 1, at = [0, 0, 1] }, { mass = 1, at = [0, 0, -1] } ]"))},
       2,
       {"body", "a scene needs a body that can spin", "a rod"}},
      {"a pivot 1e10 m away: the top is a rod to double precision",
       {"simulate", "heavy-top", "--set", "l=1e10"},
       2,
       {"body", "as thin as one to double precision"}},
      {"a wobble whose square underflows (Boost's domain error before)",
       {"simulate", "tennis-racket", "--set", "wobble=1e-300"},
       2,
       {"initial.omega", "its square underflows"}},
      {"a spin of 1e200: beyond double's range at the start, whatever the torque",
       {"simulate",
        file("s_huge_spin", scene_with("omega = [0.1, 2, 0.1]",
                                       "omega = [0.1, 2e200, 0.1]\n[effects]\ntorque = { value = "
                                       "[0, 0, 1], frame = \"space\" }"))},
       2,
       {"initial.omega", "at the start", "beyond what double precision holds"}},
      {"a parameter's default that is not a number",
       {"solve", file("nan_default", with("default = 1", "default = nan"))},
       2,
       {"nan_default.toml:", "parameters[0].default: value must be finite, got 'nan'"}},
      {"a torque of 1e200: the energy leaves double's range",
       {"simulate", "spin-up", "--set", "tau=1e200"},
       2,
       {"effects.torque.value", "beyond what double precision holds"}},
      {"g = 1e300 on a heavy top",
       {"simulate", "heavy-top", "--set", "g=1e300"},
       2,
       {"effects.gravity", "beyond what double precision holds"}},
      {"a heavy top at spin 1e9 integrated: refused by its estimate, not run for minutes",
       {"simulate", "heavy-top", "--method", "rkf78", "--set", "psidot0=1e9"},
       2,
       {"--max-evaluations", "needs about 4.6e+10 evaluations", "raise --max-evaluations"}},
      {"rk4 at a step of 1e-12 s",
       {"simulate",
        file("s_rk4", scene_with("samples = 3", "samples = 3\nmethod = \"rk4\"\nstep = 1e-12"))},
       2,
       {"--max-evaluations", "1e+12 steps of 1e-12 s"}},
      {"a heavy top integrated for 1e12 s",
       {"simulate", "heavy-top", "--method", "rkf78", "--t-end", "1e12"},
       2,
       {"--max-evaluations", "over 1e+12 s"}},
      {"a run that outgrows its budget while running",
       {"simulate", "thrown-plate", "--method", "rkf78", "--max-evaluations", "600"},
       2,
       {"--max-evaluations", "needed more than 600 right-hand-side evaluations"}},
      {"--max-evaluations not a budget",
       {"simulate", "heavy-top", "--max-evaluations", "0"},
       2,
       {"--max-evaluations", "out of range"}},
      {"keys --out naming a file",
       {"keys", "--variants", "1-1", "--problem", "flying-plate", "--out", existing_file()},
       2,
       {"--out", "existing.csv is a file, not a folder"}},
      {"keys --out where no folder can be made",
       {"keys", "--variants", "1-1", "--problem", "flying-plate", "--out", "/proc/wobble/keys"},
       2,
       {"--out: /proc/wobble/keys (in /proc): cannot be written here"}},
      {"a folder given as a problem file",
       {"solve", std::string(WOBBLE_SOURCE_DIR) + "/problems"},
       2,
       {"problems", "is a folder"}},
      {"a scene body whose tensor leaves double's range",
       {"simulate", "flying-plate", "--set", "R=1e300"},
       2,
       {"body: its inertia tensor about the centre of mass leaves double precision's range"}},
      {"bench --plot into a folder that does not exist: refused before measuring",
       {"bench", "--quick", "--plot", "/nonexistent/x.svg"},
       2,
       {"/nonexistent/x.svg", "cannot be written", "nothing was computed"}},
      {"a scene's angular momentum whose square leaves double's range (R = 1e100)",
       {"simulate", "flying-plate", "--method", "dopri5", "--set", "R=1e100"},
       2,
       {"initial.omega", "at the start the angular momentum is"}},
      {"a parameter set twice",
       {"solve", "flying-plate", "--set", "m=1", "--set", "m=2"},
       2,
       {"--set m", "given twice ('1' and '2')"}},
      {"no command at all", {}, 2, {"name a command", "solve", "check"}},
      {"a variant with a fraction",
       {"solve", "flying-plate", "--variant", "2.5"},
       2,
       {"--variant", "'2.5' is not a whole number"}},
      {"an option's value that is no number",
       {"simulate", "flying-plate", "--tolerance", "tight"},
       2,
       {"--tolerance", "'tight' is not a number"}},
      {"several parameters in one --set",
       {"solve", "flying-plate", "--set", "m=0.5,R=0.1"},
       2,
       {"--set", "sets several parameters", "--set m=0.5 --set R=0.1"}},
      {"a value with two decimal points",
       {"solve", "flying-plate", "--set", "m=0.2.5"},
       2,
       {"--set m", "'0.2.5' is not a number"}},
      {"a parameter set twice, spelt two ways",
       {"solve", "heavy-top", "--set", "theta0=0.5", "--set", "θ0=30°"},
       2,
       {"--set theta0", "given twice ('0.5' and '30°')"}},
      {"an escape sequence in a problem's title (printed in every key)",
       {"solve", file("esc_title", with("title = \"t\"", "title = \"t\\u001b[31mred\""))},
       2,
       {"title", "control character U+001B"}},
      {"a C1 control character in a unit",
       {"solve", file("c1_unit", with("unit = \"kg\"", "unit = \"kg\\u009b2J\""))},
       2,
       {"parameters[0].unit", "control character U+009B"}},
      {"an answer that divides by zero",
       {"check", "flying-plate", "a", "--name", "I0", "--answer", "m/0"},
       2,
       {"--answer", "divides by zero"}},
      {"positions 1e-200 m apart do not coincide; the tensor leaves double's range",
       {"solve", "four-masses", "--set", "a=1e-200"},
       2,
       {"outside the range of double precision", "(at --set a=1e-200)"}},
      {"a value that takes an answer out of double's range names the answer and the --set",
       {"check", "heavy-top", "p_psi", "1", "--set", "psidot0=1e300"},
       2,
       {"lagrangian0: its value, about 3.1e+596, is outside the range of double precision",
        "(at --set psidot0=1e300)"}},
      {"problem file too large",
       {"solve", file("huge", kBase + "# " + std::string(2 << 20, 'x') + "\n")},
       2,
       {"huge.toml", "at most 1 MiB"}},
  };
}
}  // namespace

namespace {
// Whether a message names one field twice in a row, "f.default: f.default: ..": a reader that
// named the field and a caller that named it again.
bool field_said_twice(const std::string& message) {
  std::vector<std::string> said;
  for (std::size_t at = 0; at <= message.size();) {
    const std::size_t end = std::min(message.find(": ", at), message.size());
    said.push_back(message.substr(at, end - at));
    at = end + 2;
  }
  for (std::size_t i = 1; i < said.size(); ++i) {
    if (said[i] == said[i - 1] && said[i].find(' ') == std::string::npos) return true;
  }
  return false;
}

// Exit 2 (or the row's code), one line on stderr with the field and value, nothing on stdout,
// within kMaxSeconds: bad input never hangs (generous for the sanitizer builds; a plain build
// answers each in well under a second).
void check_row(const Row& row) {
  constexpr double kMaxSeconds = 5;
  write_fixture_files_for(row.args);
  const auto start = std::chrono::steady_clock::now();
  const RunResult r = run_wobble(row.args);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  INFO(row.what << " (" << seconds << " s)\nstderr: " << r.err << "stdout: " << r.out);
  CHECK(seconds < kMaxSeconds);
  CHECK(r.exit_code == row.exit_code);
  CHECK(r.out.empty());
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  for (const auto& w : row.words) CHECK_THAT(r.err, Catch::Contains(w));
  CHECK(r.err.find('\x1b') == std::string::npos);  // nothing drives the terminal
  CHECK_FALSE(field_said_twice(r.err));
}

const std::vector<Row>& rows() {
  static const std::vector<Row> all = catalog();
  return all;
}

// One Catch2 test case per row ("bad input: " + what), so ctest runs them in parallel and a
// failure names its row.
struct RowTest : Catch::ITestInvoker {
  explicit RowTest(std::size_t i) : index(i) {}
  void invoke() const override { check_row(rows().at(index)); }
  std::size_t index;
};

struct RegisterRows {
  RegisterRows() {
    static std::vector<std::string> names;  // the registry keeps references to the names
    names.reserve(rows().size());
    for (std::size_t i = 0; i < rows().size(); ++i) {
      std::string name = "bad input: " + rows()[i].what;
      // ctest's discovery splits names at ';' (a CMake list).
      std::replace(name.begin(), name.end(), ';', ',');
      if (std::find(names.begin(), names.end(), name) != names.end()) {
        throw std::logic_error("two bad-input rows are named '" + name + "'");
      }
      names.push_back(name);
      Catch::AutoReg(new RowTest(i), CATCH_INTERNAL_LINEINFO, Catch::StringRef(),
                     Catch::NameAndTags{names.back(), "[bad-input]"});
    }
  }
};
const RegisterRows register_rows;
}  // namespace

TEST_CASE("the bad-input catalog names every row once and covers every command") {
  std::vector<std::string> commands;
  for (const auto& row : rows()) {
    REQUIRE_FALSE(row.what.empty());
    REQUIRE_FALSE(row.words.empty());
    if (!row.args.empty()) commands.push_back(row.args.front());
  }
  for (const std::string c : {"solve", "check", "simulate", "keys", "bench"}) {
    CHECK(std::count(commands.begin(), commands.end(), c) > 0);
  }
}

TEST_CASE("hostile answers are answered within seconds and bounded memory (check and worksheet)") {
  // Each once hung the grader or grew to gigabytes inside GiNaC: EllipticK at k = +-1 evaluated
  // forever, normal() expanded (4 terms)^400. Now each is judged (exit 0 or 1) or refused
  // (exit 2), never an internal error (3), a time-out (124) or a kill. A
  // row over kMaxSeconds fails; the process gets at most 2 GB of address space (ulimit -v).
#if defined(__SANITIZE_ADDRESS__)
  // AddressSanitizer slows GiNaC's allocation-heavy parsing about tenfold (4000 unit vectors in
  // a sum: 0.28 s plain, 2.8 s under ASan alone, over 5 s beside ctest's other jobs): the bound
  // for a hang, three times the plain one, still tells minutes from seconds.
  constexpr double kMaxSeconds = 15;
#else
  constexpr double kMaxSeconds = 5;
#endif
#if defined(__SANITIZE_ADDRESS__)
  // AddressSanitizer reserves terabytes of address space for its shadow memory: no limit here
  // (the plain build keeps it).
  const std::string kAddressLimit;
#else
  const std::string kAddressLimit = "ulimit -v 2000000; ";
#endif
  const std::string exe = std::string("'") + WOBBLE_EXE + "'";
  std::vector<std::string> answers{"EllipticK(1)", "EllipticK(-1)", "EllipticK(m/m)*m",
                                   "EllipticE(2)", "(m+R+omega+alpha)^400",
                                   "(m+R+1)^300*(m-R+2)^300", "(m+R)^999-(m+R)^999+m*R^2/4",
                                   // LaTeX, where each letter is a symbol: a run of 89000 (the
                                   // reader rescanned it for each letter, taking minutes).
                                   "\\alpha " + std::string(89000, 'R')};
  // A diagonal written out: n entries would be n² (thousands of entries, millions of zeros);
  // many diagonals at once; a Greek letter set apart from each Latin one, thousands of times.
  std::string diagonal = "diag(1", diagonals, greek;
  for (int k = 0; k < 3000; ++k) diagonal += ", 1";
  for (int k = 0; k < 2000; ++k) diagonals += "diag(m, R, m) + ";
  for (int k = 0; k < 5000; ++k) greek += "mω";
  // And a run of digits: each digit once walked back over the whole run before it (13 s).
  answers.insert(answers.end(), {diagonal + ")", diagonals + "0", greek, std::string(89000, '7')});
  // Fractions nested 97 deep under runs of minus signs (fuzzing's input, its symbol a as R):
  // normal() took 4.7 s proving what it could not (41 s under the sanitizers).
  std::ifstream fuzzed(std::string(WOBBLE_SOURCE_DIR) +
                       "/tests/fuzz/corpus/expression/deep_nested_fractions");
  std::string nested{std::istreambuf_iterator<char>(fuzzed), std::istreambuf_iterator<char>()};
  REQUIRE(nested.size() > 1000);
  std::replace(nested.begin(), nested.end(), 'a', 'R');
  answers.push_back(nested);
  // Passes that rewrite as they go: NumPy's scalars unwrapped, rates in Leibniz's notation,
  // styled letters set apart, calls unspaced, unit vectors respelled (in a sum the reader
  // splits term by term), thousands of times each.
  std::string numpy, leibniz, styled, calls, basis = "\\hat{\\mathbf{e}}_{1}";
  for (int k = 0; k < 5000; ++k) numpy += "np.float64(1)+";
  for (int k = 0; k < 8000; ++k) leibniz += "dm/dt+";
  for (int k = 0; k < 20000; ++k) styled += "𝑚";
  for (int k = 0; k < 10000; ++k) calls += "cos (m)+";
  for (int k = 0; k < 4000; ++k) basis += "+m e₂+\\hat{e}_{3}";
  // Four turns about the axes, each angle as long as one may be: multiplied out, every entry
  // repeats each angle up to 27 times.
  std::string angle = "m";
  while (angle.size() + 2 <= 200) angle += "+R";
  const std::string turns =
      "Rz(" + angle + ") Ry(" + angle + ") Rz(" + angle + ") Rx(" + angle + ")";
  std::string quantities;  // siunitx's, rewritten before the LaTeX is read
  for (int k = 0; k < 2500; ++k) quantities += "\\SI{1}{\\kilo\\gram\\metre\\squared}+";
  answers.insert(answers.end(),
                 {numpy + "0", leibniz + "0", styled, calls + "0", basis, quantities + "0", turns});
  for (const std::string& answer : answers) {
    for (const std::string how : {"check", "worksheet"}) {
      const std::string command =
          how == "check" ? exe + " check flying-plate a --name I0 --answer '" + answer + "'"
                         : "printf '%s\\nq\\n' '" + answer + "' | " + exe + " worksheet flying-plate";
      const auto start = std::chrono::steady_clock::now();
      const RunResult r = run_shell(kAddressLimit + "timeout 20 " + command);
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      INFO(how << " " << answer.substr(0, 80) << ": exit " << r.exit_code << " in " << seconds
               << " s\n"
               << r.err);
      CHECK(seconds < kMaxSeconds);
      if (how == "check") {
        CHECK((r.exit_code >= 0 && r.exit_code <= 2));
      } else {
        CHECK(r.exit_code == 0);  // the worksheet says so and asks again
      }
    }
  }
}
