// `wobble serve` in process: a server on a free loopback port, asked as a page and a class
// would ask it (cpp-httplib's client), including what a student must never see and requests
// made to break it.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <thread>

#include "serve/server.hpp"
#include "problem/scene.hpp"
#include "solvers/catalog.hpp"
#include "solvers/key.hpp"
// Last: it includes <resolv.h>, whose _res macro breaks Eigen's headers after it.
#include <httplib.h>

using namespace wobble;
using Catch::Matchers::Contains;
using Catch::Matchers::Equals;
using Catch::Matchers::StartsWith;
using nlohmann::json;

namespace {
struct Running {
  explicit Running(bool reveal = false) {
    serve::ServeOptions o;
    o.port = 0;
    o.problems = load_catalog();
    o.scenes = load_scenes();
    o.reveal = reveal;
    server = std::make_unique<serve::Server>(std::move(o));
    port = server->bind();
    thread = std::thread([this] { server->run(); });
  }
  ~Running() {
    server->stop();
    thread.join();
  }
  httplib::Client client() const {
    httplib::Client c("127.0.0.1", port);
    // A key takes milliseconds; in a sanitizer build beside the load test (200 threads on the
    // same cores) the first key of a problem took over 30 s. A timeout is still an error.
    c.set_read_timeout(300, 0);
    return c;
  }
  std::unique_ptr<serve::Server> server;
  int port = 0;
  std::thread thread;
};

json get_json(httplib::Client& c, const std::string& path, int status = 200) {
  const auto res = c.Get(path.c_str());
  REQUIRE(res);
  INFO(path << ": " << res->body);
  REQUIRE(res->status == status);
  return json::parse(res->body);
}

json post_check(httplib::Client& c, const std::string& id, const json& body, int status = 200) {
  const auto res = c.Post(("/api/problems/" + id + "/check").c_str(), body.dump(),
                          "application/json");
  REQUIRE(res);
  INFO(body.dump() << ": " << res->body);
  REQUIRE(res->status == status);
  return json::parse(res->body);
}

// The numbers of a key's answers as wobble prints them (10 significant digits) and as JSON
// prints them (all digits), leaving out those that are also a parameter's value or too short
// to mean anything ("0", "1", "-1").
std::vector<std::string> key_numbers(const json& key) {
  std::vector<std::string> params, out;
  for (const auto& [name, p] : key["parameters"].items()) {
    params.push_back(format_number(p["value"].get<double>()));
  }
  const auto add = [&](double x) {
    const std::string s = format_number(x);
    if (s.size() >= 4 && std::find(params.begin(), params.end(), s) == params.end()) {
      out.push_back(s);
      out.push_back(json(x).dump());
    }
  };
  for (const auto& part : key["parts"]) {
    for (const auto& a : part["answers"]) {
      const auto& v = a["value"];
      if (v.is_number()) add(v.get<double>());
      for (const auto& row : v.is_array() ? v : json::array()) {
        if (row.is_number()) add(row.get<double>());
        for (const auto& x : row.is_array() ? row : json::array()) add(x.get<double>());
      }
    }
  }
  return out;
}
}  // namespace

TEST_CASE("a student's responses never hold a key value, and the key needs the token") {
  Running r;
  auto c = r.client();
  const json list = get_json(c, "/api/problems");
  REQUIRE(list.size() == load_catalog().size());
  std::size_t scanned = 0;
  for (const auto& p : list) {
    const std::string id = p["id"];
    get_json(c, "/api/problems/" + id + "/key", 403);
    httplib::Headers bearer{{"Authorization", "Bearer " + r.server->token()}};
    const auto key_res = c.Get(("/api/problems/" + id + "/key?variant=2").c_str(), bearer);
    REQUIRE(key_res);
    REQUIRE(key_res->status == 200);
    const json key = json::parse(key_res->body);
    std::vector<std::string> bodies;
    const auto view = c.Get(("/api/problems/" + id + "?variant=2").c_str());
    bodies.push_back(view->body);
    const json view_json = json::parse(view->body);  // kept alive for the loop below
    if (view_json["has_motion"] == true) {
      bodies.push_back(get_json(c, "/api/problems/" + id + "/motion?variant=2").dump());
    } else {
      get_json(c, "/api/problems/" + id + "/motion?variant=2", 404);
    }
    for (const auto& part : view_json["parts"]) {
      bodies.push_back(c.Get(("/api/problems/" + id + "/hint?part=" + part["id"].get<std::string>()).c_str())->body);
      for (const auto& a : part["answers"]) {
        const json wrong = post_check(c, id, {{"part", part["id"]}, {"name", a["name"]},
                                              {"answer", "7"}, {"variant", 2}}, 
                                      a["shape"] == "scalar" ? 200 : 400);
        bodies.push_back(wrong.dump());
      }
    }
    const auto numbers = key_numbers(key);
    CHECK(!numbers.empty());
    // The scan looks for what is there: each number's JSON form is in the key itself.
    for (std::size_t i = 1; i < numbers.size(); i += 2) {
      CHECK(key_res->body.find(numbers[i]) != std::string::npos);
    }
    for (const auto& number : numbers) {
      for (const auto& body : bodies) {
        INFO(id << ": " << number << " in " << body.substr(0, 300));
        CHECK(body.find(number) == std::string::npos);
        ++scanned;
      }
    }
  }
  CHECK(scanned > 500);
  // The page asks whether it may show keys: not without the token.
  CHECK(get_json(c, "/api/session")["key"] == false);
  CHECK(get_json(c, "/api/session?token=" + r.server->token())["key"] == true);
  CHECK(get_json(c, "/api/session?token=guess")["key"] == false);
}

TEST_CASE("the judge over HTTP: a right answer, a named mistake, a variant's own values") {
  Running r(/*reveal=*/true);
  auto c = r.client();
  const json key = get_json(c, "/api/problems/flying-plate/key?variant=5");
  const auto& I0 = key["parts"][0]["answers"][0];
  REQUIRE(I0["name"] == "I0");
  const std::string right = format_number(I0["value"].get<double>()) + " kg m^2";
  CHECK(post_check(c, "flying-plate", {{"part", "a"}, {"name", "I0"}, {"answer", right},
                                       {"variant", 5}})["correct"] == true);
  // The default values' answer is wrong for variant 5.
  const json at_default = post_check(c, "flying-plate", {{"part", "a"}, {"name", "I0"},
                                                         {"answer", right}});
  CHECK(at_default["correct"] == false);
  const std::string doubled = format_number(2 * I0["value"].get<double>());
  const json twice = post_check(c, "flying-plate", {{"part", "a"}, {"name", "I0"},
                                                    {"answer", doubled}, {"variant", 5}});
  CHECK(twice["correct"] == false);
  // Twice I₀ is the moment about the axis, m R²/2, which the problem file names: at variant
  // 5's values, not the defaults'.
  CHECK_THAT(twice["feedback"][0].get<std::string>(),
             Contains("this is the moment about the symmetry axis, I₃ = m R²/2, 100% above"));
  // A name alone finds its part, as `wobble check --name` does; an unknown one is a 404.
  CHECK(post_check(c, "flying-plate",
                   {{"name", "I0"}, {"answer", right}, {"variant", 5}})["correct"] == true);
  CHECK_THAT(post_check(c, "flying-plate", {{"name", "I9"}, {"answer", right}}, 404)["error"]
                 .get<std::string>(),
             Contains("name: problem flying-plate has no answer 'I9' (answers: I0, I, "));
  // The name as the statement writes it; an entry that does not read is named counted from 1,
  // without the command line's option.
  CHECK(post_check(c, "flying-plate",
                   {{"name", "I₀"}, {"answer", right}, {"variant", 5}})["correct"] == true);
  CHECK_THAT(post_check(c, "four-masses",
                        {{"name", "principal_moments"}, {"answer", "5/2 Ma², 3, 4"}}, 400)["error"]
                 .get<std::string>(),
             StartsWith("answer, entry 1: cannot read expression") && !Contains("--answer"));
  // A part of several answers and no name: the answer's label names it, or it is right for one
  // of them only, or (right for none) a value of one only; else the name is needed.
  const json labelled =
      post_check(c, "flying-plate", {{"part", "a"}, {"answer", "I₀ = " + doubled}, {"variant", 5}});
  CHECK(labelled["verdict"] == "incorrect: I0");
  CHECK(post_check(c, "flying-plate",
                   {{"part", "a"}, {"answer", right}, {"variant", 5}})["verdict"] == "correct: I0");
  // Variant 5's I₀ at the default values: wrong, and a number, so I₀'s (I is a matrix).
  CHECK(post_check(c, "flying-plate", {{"part", "a"}, {"answer", right}})["verdict"] ==
        "incorrect: I0");
  // A vector of angular velocity is a value of Ω_body and of Ω_space alike.
  CHECK_THAT(
      post_check(c, "flying-plate", {{"part", "e"}, {"answer", "(1, 2, 3) rad/s"}}, 404)["error"]
          .get<std::string>(),
      Equals("name: part e has several answers; name one (Omega_body, Omega_space, "
             "Omega_body_rate, Omega_space_rate)"));
  // Euler's equations, one coefficient wrong, are the coefficients' answer, and the view names
  // the entries as the question does (c₁ .. c₃; the body's components along e₁ .. e₃).
  const json equations = post_check(
      c, "asymmetric-top",
      {{"part", "a"}, {"answer", "dω₁/dt = −½ ω₂ω₃, dω₂/dt = 0.7 ω₃ω₁, dω₃/dt = −¼ ω₁ω₂"}});
  CHECK(equations["verdict"] == "incorrect: euler_coefficients");
  CHECK(equations["feedback"][0] == "c₂ is off by 5%");
  const json answers_a = get_json(c, "/api/problems/asymmetric-top")["parts"][0]["answers"];
  CHECK(answers_a[0]["entries"] == json{"c₁", "c₂", "c₃"});
  CHECK(answers_a[1]["entries"] == json{"e₁", "e₂", "e₃"});
  CHECK_THAT(post_check(c, "flying-plate", {{"answer", right}}, 400)["error"].get<std::string>(),
             StartsWith("part or name: neither is given") &&
                 Contains("(answers: (a) I0, I; (b) L0_body, L0_space; "));
  // A variant whose top spins too slowly for steady precession: part d has no answer, and
  // "none" is right for it over HTTP too (a number wrong), without the key's reason, which
  // gives ω3 (part c's answer) away, as the page does.
  int slow = 0;
  json slow_part;
  for (int n = 1; n <= 20 && slow == 0; ++n) {
    const json view = get_json(c, "/api/problems/heavy-top?variant=" + std::to_string(n));
    if (view["parts"][3].contains("absent") && view["parts"][3]["answers"].empty()) {
      slow = n;
      slow_part = view["parts"][3];
    }
  }
  REQUIRE(slow > 0);
  // The page asks for them as for answers that exist: by name, in their unit.
  CHECK(slow_part["absent"] == json{"phidot_slow", "phidot_fast"});
  CHECK(slow_part["absent_units"] == json{"rad/s", "rad/s"});
  const json none =
      post_check(c, "heavy-top", {{"part", "d"}, {"answer", "none"}, {"variant", slow}});
  CHECK(none["correct"] == true);
  CHECK(none["verdict"] == "correct: phidot_slow, phidot_fast do not exist at these values");
  CHECK(none["feedback"] == json::array());
  CHECK(
      post_check(c, "heavy-top",
                 {{"name", "phidot_fast"}, {"answer", "12 rad/s"}, {"variant", slow}})["verdict"] ==
      "incorrect: phidot_fast does not exist at these values");
  // The hint as the problem file writes it: its math in $...$, for the page to typeset.
  CHECK_THAT(get_json(c, "/api/problems/flying-plate/hint?part=a")["hint"].get<std::string>(),
             StartsWith("A thin disc: $I_3 = m R^2/2$ about its axis"));
}

TEST_CASE("bad requests get a 4xx with a message, and the server keeps serving") {
  Running r;
  auto c = r.client();
  const auto status = [&](const httplib::Result& res) { return res ? res->status : -1; };
  CHECK(status(c.Post("/api/problems/four-masses/check", "{not json", "application/json")) == 400);
  CHECK(status(c.Post("/api/problems/four-masses/check", "[1, 2]", "application/json")) == 400);
  CHECK(status(c.Post("/api/problems/four-masses/check",
                      json{{"part", "a"}, {"answer", 5}}.dump(), "application/json")) == 400);
  CHECK(status(c.Post("/api/problems/four-masses/check",
                      json{{"part", "z"}, {"answer", "1"}}.dump(), "application/json")) == 404);
  CHECK(status(c.Post("/api/problems/four-masses/check",
                      json{{"part", "a"}, {"answer", "1"}, {"variant", -3}}.dump(),
                      "application/json")) == 400);
  CHECK(status(c.Post("/api/problems/four-masses/check",
                      json{{"part", "a"}, {"answer", "(m+a)^99999"}}.dump(),
                      "application/json")) == 400);
  const std::string huge(serve::kMaxBody + 1, 'x');
  CHECK(status(c.Post("/api/problems/four-masses/check", huge, "application/json")) == 413);
  CHECK(status(c.Get("/api/problems/no-such-problem")) == 404);
  CHECK(status(c.Get("/api/problems/four-masses?variant=0")) == 400);
  CHECK(status(c.Get("/api/problems/four-masses?variant=1e3")) == 400);
  CHECK(status(c.Get("/api/problems/four-masses/hint?part=q")) == 404);
  CHECK(status(c.Get("/assets/../../etc/passwd")) == 404);
  CHECK(status(c.Get("/assets/%2e%2e/%2e%2e/etc/passwd")) == 404);
  CHECK(status(c.Get("/assets/katex/../page.js")) == 404);
  CHECK(status(c.Get("/nothing-here")) == 404);
  CHECK(status(c.Get("/api/problems/no-such-problem/motion")) == 404);
  CHECK(status(c.Get("/api/problems/box-corner/motion")) == 404);  // a problem without motion
  CHECK(status(c.Get("/api/problems/heavy-top/motion?variant=x")) == 400);
  CHECK(status(c.Get("/api/scenes/no-such-scene/motion")) == 404);
  CHECK(status(c.Get("/api/scenes/../problems/motion")) == 404);
  CHECK(status(c.Get("/api/scenes/heavy-top/motion")) == 200);
  const auto res = c.Get("/api/problems/no-such-problem");
  CHECK_THAT(res->body, Contains("\"error\""));
  CHECK(status(c.Get("/api/problems")) == 200);
  CHECK(status(c.Get("/assets/katex/katex.min.js")) == 200);
  CHECK(status(c.Get("/assets/katex/fonts/KaTeX_Main-Regular.woff2")) == 200);
  CHECK(status(c.Get("/assets/three/three.min.js")) == 200);
}

TEST_CASE("a client that connects and sends nothing is dropped, and blocks no one") {
  Running r;
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  REQUIRE(fd >= 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(static_cast<std::uint16_t>(r.port));
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  REQUIRE(::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0);
  auto c = r.client();
  const auto start = std::chrono::steady_clock::now();
  CHECK(c.Get("/api/problems")->status == 200);  // served while the silent one waits
  char byte = 0;
  const auto got = ::recv(fd, &byte, 1, 0);  // the server closes it after its read timeout
  const double waited =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ::close(fd);
  CHECK(got == 0);
  // Closed after the read timeout, give or take the server's polling.
  CHECK(waited < serve::kReadTimeoutSeconds + 5);
}

namespace {
// Resident memory of this process (server and clients), bytes.
long resident_bytes() {
  long pages = 0, resident = 0;
  FILE* f = std::fopen("/proc/self/statm", "r");
  if (f == nullptr) return 0;
  if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
  std::fclose(f);
  return resident * ::sysconf(_SC_PAGESIZE);
}

constexpr int kLoadReadTimeoutSeconds = 600;

// The resident size may grow between two equal rounds by the allocator's pools (a tenth of what
// the first round left) and, under AddressSanitizer, by its quarantine: freed blocks are held
// back from reuse up to quarantine_size_mb (256 MB by default) to catch use after free, so a
// second round that frees as much as it allocates still raises the resident size by up to that.
#if defined(__SANITIZE_ADDRESS__)
constexpr long kQuarantineBytes = 256L << 20;
#else
constexpr long kQuarantineBytes = 0;
#endif

struct LoadResult {
  std::vector<double> latency_ms;
  int errors = 0;
};

// kStudents students at once, each loading a problem at their own variant and checking
// kChecksEach answers (right ones from the key, wrong ones, unreadable ones).
LoadResult class_at_work(const Running& r, int students, int checks_each) {
  const auto problems = load_catalog();
  std::vector<LoadResult> per(static_cast<std::size_t>(students));
  std::vector<std::thread> threads;
  for (int s = 0; s < students; ++s) {
    threads.emplace_back([&, s] {
      auto& out = per[static_cast<std::size_t>(s)];
      httplib::Client c("127.0.0.1", r.port);
      // The first round computes 200 keys one after another: a minute in a sanitizer build,
      // so a student may wait that long for the first answer; a timeout is still an error.
      c.set_read_timeout(kLoadReadTimeoutSeconds, 0);
      c.set_keep_alive(true);  // as a browser does
      c.set_tcp_nodelay(true);
      const std::string id = problems[static_cast<std::size_t>(s) % problems.size()].id;
      const std::string variant = std::to_string(s + 1);
      const auto timed = [&](auto request) {
        const auto start = std::chrono::steady_clock::now();
        auto res = request();
        out.latency_ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count());
        if (!res || res->status >= 500) ++out.errors;
        return res;
      };
      const auto view = timed([&] { return c.Get(("/api/problems/" + id + "?variant=" + variant).c_str()); });
      if (!view || view->status != 200) return;
      const json parts = json::parse(view->body)["parts"];
      std::vector<std::pair<std::string, std::string>> inputs;
      for (const auto& p : parts) {
        for (const auto& a : p["answers"]) inputs.emplace_back(p["id"], a["name"]);
      }
      if (inputs.empty()) return;
      for (int k = 0; k < checks_each; ++k) {
        const auto& [part, name] = inputs[static_cast<std::size_t>(k) % inputs.size()];
        const std::string answer = k % 3 == 0 ? "1.5" : k % 3 == 1 ? "[1, 2, 3]" : "m*2";
        const json body = {{"part", part}, {"name", name}, {"answer", answer},
                           {"variant", s + 1}};
        timed([&] {
          return c.Post(("/api/problems/" + id + "/check").c_str(), body.dump(), "application/json");
        });
      }
    });
  }
  for (auto& t : threads) t.join();
  LoadResult all;
  for (const auto& p : per) {
    all.latency_ms.insert(all.latency_ms.end(), p.latency_ms.begin(), p.latency_ms.end());
    all.errors += p.errors;
  }
  return all;
}

double percentile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1))];
}
}  // namespace

TEST_CASE("a class at work: 200 students, 20 checks each, no error, memory flat") {
  constexpr int kStudents = 200, kChecksEach = 20;
  Running r;
  const LoadResult first = class_at_work(r, kStudents, kChecksEach);
  const long after_first = resident_bytes();
  const LoadResult second = class_at_work(r, kStudents, kChecksEach);
  const long after_second = resident_bytes();
  const LoadResult third = class_at_work(r, kStudents, kChecksEach);
  const long after_third = resident_bytes();
  // Every request answered (4xx for the unreadable answers is an answer), none failed.
  CHECK(first.latency_ms.size() == kStudents * (kChecksEach + 1));
  CHECK(first.errors == 0);
  CHECK(second.errors == 0);
  CHECK(third.errors == 0);
  // The keys are cached after the first round: the third holds no more memory than the second
  // left, give or take the allocator's pools and the sanitizer's quarantine. The second is the
  // baseline, not the first: the allocator's per-thread arenas are still being taken up by the
  // server's workers in the second round (6-10% more resident on the 2-core machine). A leak of
  // two kilobytes a request (8.4 MB a round) is over the tenth of the 70-80 MB held.
  CHECK(after_third <= after_second + after_second / 10 + kQuarantineBytes);
  // Measured, not asserted (timings on a shared machine are noise for a test): reported here
  // and in the README.
  std::printf(
      "load: %zu requests; first round (keys computed) p50 %.1f ms, p99 %.1f ms; "
      "later rounds (keys cached) p50 %.1f ms, p99 %.1f ms; resident %.0f MB -> %.0f MB "
      "-> %.0f MB\n",
      first.latency_ms.size() + second.latency_ms.size() + third.latency_ms.size(),
      percentile(first.latency_ms, 0.5), percentile(first.latency_ms, 0.99),
      percentile(third.latency_ms, 0.5), percentile(third.latency_ms, 0.99),
      static_cast<double>(after_first) / 1e6, static_cast<double>(after_second) / 1e6,
      static_cast<double>(after_third) / 1e6);
}
