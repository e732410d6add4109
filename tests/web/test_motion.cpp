// The page's 3-D view reads the motion samples (web/motion.hpp) and the self-contained page
// (web/page_file.hpp): the samples follow the key's closed forms, turn little enough between
// two samples for slerp, and the page written to a file carries everything it links.
#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "core/rigid_body.hpp"
#include "problem/scene.hpp"
#include "problem/values.hpp"
#include "solvers/catalog.hpp"
#include "solvers/solve.hpp"
#include "web/assets.hpp"
#include "web/motion.hpp"
#include "web/page_file.hpp"
#include "web/problem_view.hpp"

using namespace wobble;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using nlohmann::json;

namespace {
// Lengths and times carry 6 significant digits: a number read back is off by up to half a unit
// in the 6th digit, 5e-6 relative.
constexpr double kSampleDigits = 5e-6;
// Directions and quaternions are rounded to kDirectionStep: each component is off by up to h.
constexpr double h = web::kDirectionStep / 2;
// A quaternion off by up to h in each of its 4 components is off by 2 h in norm, and the
// rotation it stands for by twice that angle.
constexpr double kAngleError = 4 * h;

double key_value(const Key& key, const std::string& name) {
  for (const auto& part : key.parts) {
    for (const auto& a : part.answers) {
      if (a.name == name) return a.value.data.at(0);
    }
  }
  FAIL("no answer " << name);
  return 0.0;
}

Key key_of(const Problem& p, const std::vector<std::string>& assignments = {}) {
  return solve(p, parameter_values(p, assignments));
}

Quat quat(const json& q) { return Quat(q[0], q[1], q[2], q[3]); }
Vec3 vec(const json& v) { return Vec3(v[0], v[1], v[2]); }

// The angle between e3 = z of the body and space's z at each sample.
std::vector<double> tilt(const json& motion) {
  std::vector<double> out;
  for (const auto& q : motion["q_BtoS"]) {
    const Vec3 e3 = quat(q).normalized() * Vec3::UnitZ();
    out.push_back(std::atan2(e3.head<2>().norm(), e3.z()));
  }
  return out;
}
}  // namespace

TEST_CASE("the flying plate's samples: e3 tilts to the key's largest angle at its time, on its cones") {
  const Problem p = find_problem("flying-plate");
  for (long variant : {0L, 3L, 11L}) {
    const auto assignments = variant ? variant_for(p, variant) : std::vector<std::string>{};
    const Key key = key_of(p, assignments);
    const json m = json::parse(web::problem_motion_json(p, assignments));
    REQUIRE(m["method"] == "closed_form");
    const auto angle = tilt(m);
    const double dt = m["t"][1].get<double>() - m["t"][0].get<double>();
    const double rate = key_value(key, "Omega_space_rate"), largest = key_value(key, "max_angle");
    const double t_max = key_value(key, "t_max");
    // The first maximum: the largest sample before 2 t_max (the tilt is back to 0 there).
    const auto first = static_cast<std::size_t>(2 * t_max / dt);
    REQUIRE(first < angle.size());
    const std::size_t k = static_cast<std::size_t>(
        std::max_element(angle.begin(), angle.begin() + first) - angle.begin());
    INFO("variant " << variant);
    // Near its maximum the tilt is largest * (1 - (rate (t - t_max))^2 / 8) to leading order, so
    // the sample nearest t_max (at most dt/2 away) is below it by largest (rate dt / 2)^2 / 8.
    const double sampling = largest * std::pow(rate * dt / 2, 2) / 8;
    CHECK(*std::max_element(angle.begin(), angle.end()) <= largest + kAngleError);
    CHECK(angle[k] >= largest - sampling - kAngleError);
    // The samples' rounding (kAngleError each) can put a sample up to 2 kAngleError below the
    // peak above a nearer one: the samples within that of the peak lie within
    // sqrt(8 * 2 kAngleError / largest) / rate of t_max.
    const double flat = std::sqrt(8 * 2 * kAngleError / largest) / rate;
    CHECK_THAT(m["t"][k].get<double>(), WithinAbs(t_max, dt / 2 + flat));
    // The cones as drawn against the key's half angles (the key's exact forms; here atan2 of
    // the vectors at t = 0).
    CHECK_THAT(m["cones"]["body_half_angle"].get<double>(),
               WithinAbs(key_value(key, "body_cone_half_angle"), h));
    CHECK_THAT(m["cones"]["space_half_angle"].get<double>(),
               WithinAbs(key_value(key, "space_cone_half_angle"), h));
    // The body as drawn: the disc of radius R about the centre of mass.
    REQUIRE(m["parts"].size() == 1);
    CHECK(m["parts"][0]["shape"] == "disc");
    CHECK_THAT(m["parts"][0]["sizes"][0].get<double>(),
               WithinRel(parameter_values(p, assignments).at("R"), kSampleDigits));
  }
}

TEST_CASE("the heavy top's samples nod between the key's nutation limits") {
  const Problem p = find_problem("heavy-top");
  const Key key = key_of(p);
  const json m = json::parse(web::problem_motion_json(p, {}));
  CHECK(m["method"] == "exact");
  CHECK(m["gravity"] == true);
  const auto angle = tilt(m);
  const double lo = key_value(key, "theta_min"), hi = key_value(key, "theta_max");
  const auto values = parameter_values(p, {});
  // The nutation of a fast top turns at about I3 w3 / I1 (I1 about the pivot: the disc's
  // M R^2/4 plus M l^2); the sample nearest an extreme is below it by at most
  // amplitude (w_n dt / 2)^2 / 2. Twice that w_n covers the slow-top correction.
  const double M = values.at("M"), R = values.at("R"), l = values.at("l");
  const double I1 = M * (R * R / 4 + l * l), I3 = M * R * R / 2;
  const double w_n = 2 * I3 * key_value(key, "omega3") / I1;
  const double dt = m["t"][1].get<double>() - m["t"][0].get<double>();
  const double amplitude = (hi - lo) / 2;
  const double sampling = amplitude * std::pow(w_n * dt / 2, 2) / 2;
  // The integrator runs at 1e-10, far below the samples' rounding.
  const double digits = kAngleError;
  const auto [smallest, largest] = std::minmax_element(angle.begin(), angle.end());
  CHECK(*smallest >= lo - digits);
  CHECK(*largest <= hi + digits);
  CHECK(*smallest <= lo + sampling + digits);
  CHECK(*largest >= hi - sampling - digits);
  // The disc on its axle: its centre at l above the pivot along e3.
  CHECK(m["turning_point"] == "pivot");
  CHECK_THAT(m["parts"][0]["center"][2].get<double>(), WithinRel(l, kSampleDigits));
}

TEST_CASE("the tennis racket's samples flip at the key's interval, with energy and |L| kept") {
  const Problem p = find_problem("tennis-racket");
  const Key key = key_of(p);
  const json m = json::parse(web::problem_motion_json(p, {}));
  CHECK(m["method"] == "exact");
  const auto values = parameter_values(p, {});
  const double a = values.at("a"), b = values.at("b"), c = values.at("c");
  const Vec3 I_per_mass = Vec3(b * b + c * c, a * a + c * c, a * a + b * b) / 12;
  // w over |w(0)|: 2T and |L|, in those units, are the same at every sample.
  const auto energy = [&](const Vec3& w) { return w.dot(I_per_mass.cwiseProduct(w)); };
  const auto momentum = [&](const Vec3& w) { return I_per_mass.cwiseProduct(w).norm(); };
  const Vec3 w0 = vec(m["w_B"][0]);
  std::vector<double> crossings;
  // Components off by h change 2T = w.Iw by up to 2 |Iw| sqrt(3) h, relative to w.Iw at most
  // 2 sqrt(3) h I_max / (I_min |w|); |Iw| by sqrt(3) h I_max, relative half that. Both for
  // the sample and for w(0), so twice.
  const double ratio = I_per_mass.maxCoeff() / I_per_mass.minCoeff();
  for (std::size_t k = 0; k < m["w_B"].size(); ++k) {
    const Vec3 w = vec(m["w_B"][k]);
    const double bound = 2 * std::sqrt(3.0) * h * ratio / std::min(w.norm(), w0.norm());
    CHECK_THAT(energy(w), WithinRel(energy(w0), 2 * bound));
    CHECK_THAT(momentum(w), WithinRel(momentum(w0), bound));
    if (k > 0 && (vec(m["w_B"][k - 1]).y() > 0) != (w.y() > 0)) {
      crossings.push_back(m["t"][k].get<double>());
    }
  }
  // w2 changes sign once per flip: the crossings are flip_interval apart (to a sample).
  REQUIRE(crossings.size() >= 2);
  const double dt = m["t"][1].get<double>() - m["t"][0].get<double>();
  CHECK_THAT(crossings[1] - crossings[0], WithinAbs(key_value(key, "flip_interval"), 2 * dt));
}

TEST_CASE("every motion turns at most the allowed angle between two samples, for slerp") {
  std::vector<std::pair<std::string, json>> motions;
  for (const auto& p : load_catalog()) {
    if (web::has_motion(p)) motions.emplace_back(p.id, json::parse(web::problem_motion_json(p, {})));
  }
  for (const auto& s : load_scenes()) {
    motions.emplace_back("scene " + s.model.id, json::parse(web::scene_motion_json(s)));
  }
  CHECK(motions.size() >= 12);
  for (const auto& [id, m] : motions) {
    INFO(id);
    const std::size_t n = m["t"].size();
    CHECK(n >= static_cast<std::size_t>(web::kMinSamples));
    CHECK(n <= static_cast<std::size_t>(web::kMaxSamples));
    REQUIRE(m["q_BtoS"].size() == n);
    double largest = 0.0;
    for (std::size_t k = 1; k < n; ++k) {
      largest = std::max(largest, quat(m["q_BtoS"][k - 1]).normalized().angularDistance(
                                      quat(m["q_BtoS"][k]).normalized()));
    }
    // Each of the two quaternions is off by up to kAngleError.
    CHECK(largest <= web::kMaxTurnPerSample + 2 * kAngleError);
  }
}

TEST_CASE("a body written with units is drawn at its size in metres") {
  // wheel-brake's cylinder is written "20 cm" by "5 cm"; its centre is the turning point.
  const json m = json::parse(web::scene_motion_json(find_scene("wheel-brake")));
  REQUIRE(m["parts"].size() == 1);
  CHECK(m["parts"][0]["shape"] == "cylinder");
  CHECK(m["parts"][0]["sizes"] == json::array({0.2, 0.05}));
}

TEST_CASE("a problem's motion written with units is the same motion") {
  // The [motion] values are built into the scene's expressions (simulate/problem_scene.cpp):
  // each in SI first, so "(psidot0*60/(2*pi) rpm)" inside a product still reads.
  Problem top = find_problem("heavy-top");
  const std::string si = web::problem_motion_json(top, {});
  top.motion->exprs["psidot0"] = "psidot0*60/(2*pi) rpm";
  top.motion->exprs["theta0"] = "theta0*180/pi deg";
  top.motion->exprs["phidot0"] = "phidot0 1/s";
  CHECK(web::problem_motion_json(top, {}) == si);
}

TEST_CASE("a problem without motion has none to show") {
  const Problem p = find_problem("box-corner");
  CHECK_FALSE(web::has_motion(p));
  CHECK_THROWS_WITH(web::problem_motion_json(p, {}), Contains("box-corner has no motion"));
}

TEST_CASE("the self-contained page links nothing and carries its data") {
  const Problem p = find_problem("heavy-top");
  const Key key = key_of(p);
  const std::string view = web::student_view_json(p, key, std::nullopt, {});
  const std::string page = web::self_contained_page(view, web::problem_motion_json(p, {}), "");
  // No element loads a file: every script and style is inline.
  const auto count = [&](const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = page.find(what); at != std::string::npos; at = page.find(what, at + 1)) ++n;
    return n;
  };
  CHECK(count("src=\"assets/") == 0);
  CHECK(count("href=\"assets/") == 0);
  CHECK(count("url(fonts/") == 0);
  // One data: URL per KaTeX font built in.
  std::size_t fonts = 0;
  for (const auto& [path, bytes] : web::embedded_files()) {
    if (path.rfind("katex/fonts/", 0) == 0) ++fonts;
  }
  const std::size_t inlined = count("url(data:font/woff2;base64,");
  CHECK(fonts >= 10);
  CHECK(inlined == fonts);
  CHECK_THAT(page, Contains("const WOBBLE_DATA = {\"view\": " + view));
  CHECK_THAT(page, Contains("\"key\": null}"));
  // A script's text never ends its element early.
  const std::size_t scripts = count("<script>"), ends = count("</script");
  // The data, KaTeX with auto-render and copy-tex, three.js with its controls, the page's two.
  CHECK(scripts == 8u);
  CHECK(ends == scripts);
}

TEST_CASE("the view carries a part's hint only when asked (the page file), never for the server") {
  const Problem p = find_problem("heavy-top");
  const Key key = key_of(p);
  const auto served = json::parse(web::student_view_json(p, key, std::nullopt, {}));
  const auto filed = json::parse(web::student_view_json(p, key, std::nullopt, {}, true));
  REQUIRE(served["parts"].size() == p.parts.size());
  for (std::size_t i = 0; i < p.parts.size(); ++i) {
    INFO(p.parts[i].id);
    CHECK(served["parts"][i]["has_hint"] == !p.parts[i].hint.empty());
    CHECK_FALSE(served["parts"][i].contains("hint"));
    CHECK(filed["parts"][i].value("hint", "") == p.parts[i].hint);
  }
  CHECK_THAT(filed["parts"][0]["hint"].get<std::string>(), StartsWith("Use $\\omega$"));
}

TEST_CASE("the page labels a rate with both units where its unit would tell the answer") {
  // The growth rate about e2 is in 1/s, the frequencies in rad/s: the label says both for all.
  const Problem p = find_problem("asymmetric-top");
  const auto view = json::parse(web::student_view_json(p, key_of(p), std::nullopt, {}));
  int rates = 0;
  for (const auto& part : view["parts"]) {
    for (const auto& a : part["answers"]) {
      if (a["name"].get<std::string>().rfind("rate_axis", 0) != 0) continue;
      INFO(a["name"]);
      CHECK(a["asked_unit"] == "rad/s or 1/s");
      ++rates;
    }
  }
  CHECK(rates == 3);
}

TEST_CASE(
    "the page has each answer's form from the key, as the handout and the worksheet word it") {
  const Problem p = find_problem("tennis-racket");
  const Key key = key_of(p);
  const auto view = json::parse(web::student_view_json(p, key, std::nullopt, {}));
  REQUIRE(view["parts"].size() == key.parts.size());
  int vectors = 0;
  for (std::size_t i = 0; i < key.parts.size(); ++i) {
    const auto& answers = view["parts"][i]["answers"];
    REQUIRE(answers.size() == key.parts[i].answers.size());
    for (std::size_t j = 0; j < answers.size(); ++j) {
      const Answer& a = key.parts[i].answers[j];
      INFO(a.name);
      CHECK(answers[j]["form"] == answer_form(a));
      vectors += a.value.shape == Value::Shape::vector ? 1 : 0;
    }
  }
  CHECK(vectors >= 5);  // the coefficients, dω/dt and the three pairs of Ω
}
