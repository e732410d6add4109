#include "serve/server.hpp"

#include <fmt/format.h>
#include <sys/socket.h>

#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <random>

#include "check/absent_answer.hpp"
#include "check/answer_choice.hpp"
#include "check/judge.hpp"
#include "core/input_error.hpp"
#include "problem/values.hpp"
#include "render/render.hpp"
#include "solvers/solve.hpp"
#include "web/assets.hpp"
#include "web/motion.hpp"
#include "web/problem_view.hpp"
// Last: it includes <resolv.h>, whose _res macro breaks Eigen's headers after it.
#include <httplib.h>

namespace wobble::serve {

namespace {
using nlohmann::json;
// An answer longer than this is no answer (the judge's guard refuses long expressions anyway).
constexpr std::size_t kMaxAnswerChars = 2000;
// Variant numbers as `wobble solve --variant` takes them.
constexpr long kMaxVariant = 1000000;

void send_error(httplib::Response& res, int status, const std::string& message) {
  res.status = status;
  res.set_content(json{{"error", message}}.dump(), "application/json");
}

void send_json(httplib::Response& res, const std::string& body) {
  res.set_header("Cache-Control", "no-store");
  res.set_content(body, "application/json");
}

// A variant from the query (or body): a whole number in 1..kMaxVariant, or none.
std::optional<long> read_variant(const std::string& text) {
  if (text.empty()) return std::nullopt;
  std::size_t used = 0;
  long n = 0;
  try {
    n = std::stol(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || n < 1 || n > kMaxVariant) {
    throw InputError(fmt::format("variant: '{}' is not a variant number (1 to {})", text,
                                 kMaxVariant));
  }
  return n;
}

struct Entry {
  std::vector<std::string> assignments;  ///< the variant's NAME=VALUE as drawn
  sym::Values values;
  Key key;
  sym::SymbolTable table;  ///< the problem's symbols, made once (used under the work lock)
};
}  // namespace

std::string new_token() {
  std::random_device source;  // the system's random source: a token must be unguessable
  std::string out;
  for (int i = 0; i < 4; ++i) out += fmt::format("{:08x}", source());
  return out;
}

struct Server::Impl {
  ServeOptions options;
  httplib::Server http;
  std::mutex work;  // GiNaC is not thread-safe: solving and judging one at a time
  int listening = -1;
  std::map<std::pair<std::string, long>, std::shared_ptr<const Entry>> keys;
  std::map<std::pair<std::string, long>, std::string> motions;  ///< by (id, variant or 0)

  const Problem& problem(const std::string& id) const {
    for (const auto& p : options.problems) {
      if (p.id == id) return p;
    }
    throw std::out_of_range(id);
  }

  // The key of (problem, variant), computed once. Call with `work` held.
  std::shared_ptr<const Entry> entry(const Problem& p, std::optional<long> variant) {
    const auto at = std::make_pair(p.id, variant.value_or(0));
    if (auto it = keys.find(at); it != keys.end()) return it->second;
    if (keys.size() >= kMaxCachedKeys) keys.clear();
    const auto assignments = variant ? variant_for(p, *variant) : std::vector<std::string>{};
    sym::Values values = parameter_values(p, assignments);
    Key key = solve(p, values);
    key.variant = variant;
    auto e = std::make_shared<const Entry>(
        Entry{assignments, std::move(values), std::move(key), p.symbol_table()});
    keys.emplace(at, e);
    return e;
  }

  // The motion of (id, variant), computed once by `make`. Call with `work` held.
  template <class Make>
  const std::string& motion(const std::string& id, std::optional<long> variant, Make make) {
    const auto at = std::make_pair(id, variant.value_or(0));
    if (auto it = motions.find(at); it != motions.end()) return it->second;
    if (motions.size() >= kMaxCachedMotions) motions.clear();
    return motions.emplace(at, make()).first->second;
  }

  bool instructor(const httplib::Request& req) const {
    if (options.reveal) return true;
    const std::string bearer = "Bearer " + options.token;
    return req.get_header_value("Authorization") == bearer ||
           (req.has_param("token") && req.get_param_value("token") == options.token);
  }

  // Runs `handle` for the problem named in the path, turning bad input into a 4xx.
  template <class F>
  void with_problem(const httplib::Request& req, httplib::Response& res, F handle) {
    const std::string id = req.matches[1];
    const Problem* p = nullptr;
    try {
      p = &problem(id);
    } catch (const std::out_of_range&) {
      send_error(res, 404, fmt::format("no problem '{}'", id.substr(0, 80)));
      return;
    }
    try {
      handle(*p);
    } catch (const InputError& e) {
      send_error(res, 400, e.what());
    } catch (const json::exception&) {
      send_error(res, 400, "the body is not the JSON this request takes");
    }
  }

  void routes() {
    http.Get("/", [](const httplib::Request&, httplib::Response& res) {
      const auto page = web::asset("page.html");
      res.set_content(std::string(page->bytes), page->content_type);
    });
    http.Get("/assets/(.+)", [](const httplib::Request& req, httplib::Response& res) {
      const auto a = web::asset(req.matches[1]);
      if (!a) return send_error(res, 404, "no such asset");
      res.set_header("Cache-Control", "max-age=86400");
      res.set_content(std::string(a->bytes), a->content_type);
    });
    http.Get("/api/problems", [this](const httplib::Request&, httplib::Response& res) {
      send_json(res, web::problem_list_json(options.problems));
    });
    http.Get("/api/problems/([^/]+)", [this](const httplib::Request& req, httplib::Response& res) {
      with_problem(req, res, [&](const Problem& p) {
        const auto variant = read_variant(req.get_param_value("variant"));
        std::lock_guard lock(work);
        const auto e = entry(p, variant);
        send_json(res, web::student_view_json(p, e->key, variant, e->assignments));
      });
    });
    http.Get("/api/problems/([^/]+)/hint",
             [this](const httplib::Request& req, httplib::Response& res) {
               with_problem(req, res, [&](const Problem& p) {
                 const std::string part = req.get_param_value("part");
                 for (const auto& spec : p.parts) {
                   if (spec.id == part) return send_json(res, json{{"hint", spec.hint}}.dump());
                 }
                 send_error(res, 404, fmt::format("problem {} has no part '{}'", p.id,
                                                  part.substr(0, 20)));
               });
             });
    http.Get("/api/problems/([^/]+)/key",
             [this](const httplib::Request& req, httplib::Response& res) {
               if (!instructor(req)) {
                 return send_error(res, 403, "the key needs the instructor's token");
               }
               with_problem(req, res, [&](const Problem& p) {
                 const auto variant = read_variant(req.get_param_value("variant"));
                 std::lock_guard lock(work);
                 send_json(res, render_json(entry(p, variant)->key));
               });
             });
    http.Get("/api/problems/([^/]+)/motion",
             [this](const httplib::Request& req, httplib::Response& res) {
               with_problem(req, res, [&](const Problem& p) {
                 if (!web::has_motion(p)) {
                   return send_error(res, 404, fmt::format("problem {} has no motion to show",
                                                           p.id));
                 }
                 const auto variant = read_variant(req.get_param_value("variant"));
                 std::lock_guard lock(work);
                 send_json(res, motion(p.id, variant, [&] {
                   return web::problem_motion_json(p, entry(p, variant)->assignments);
                 }));
               });
             });
    http.Get("/api/session", [this](const httplib::Request& req, httplib::Response& res) {
      send_json(res, json{{"key", instructor(req)}}.dump());
    });
    http.Get("/api/scenes", [this](const httplib::Request&, httplib::Response& res) {
      json list = json::array();
      for (const auto& s : options.scenes) {
        list.push_back({{"id", s.model.id}, {"title", s.model.title}});
      }
      send_json(res, list.dump());
    });
    http.Get("/api/scenes/([^/]+)/motion",
             [this](const httplib::Request& req, httplib::Response& res) {
               const std::string id = req.matches[1];
               for (const auto& s : options.scenes) {
                 if (s.model.id != id) continue;
                 try {
                   std::lock_guard lock(work);
                   return send_json(res, motion("scene:" + id, std::nullopt,
                                                [&] { return web::scene_motion_json(s); }));
                 } catch (const InputError& e) {
                   return send_error(res, 400, e.what());
                 }
               }
               send_error(res, 404, fmt::format("no scene '{}'", id.substr(0, 80)));
             });
    http.Post("/api/problems/([^/]+)/check",
              [this](const httplib::Request& req, httplib::Response& res) {
                with_problem(req, res, [&](const Problem& p) { check(p, req, res); });
              });
    http.set_error_handler([](const httplib::Request&, httplib::Response& res) {
      if (res.body.empty()) {
        send_error(res, res.status, res.status == 413 ? "the request is too large"
                                                      : fmt::format("HTTP {}", res.status));
      }
    });
    http.set_exception_handler(
        [](const httplib::Request&, httplib::Response& res, std::exception_ptr) {
          send_error(res, 500, "internal error");
        });
  }

  void check(const Problem& p, const httplib::Request& req, httplib::Response& res) {
    const json body = json::parse(req.body);
    if (!body.is_object()) throw InputError("the body is not a JSON object");
    const auto text = [&](const char* field) -> std::string {
      if (!body.contains(field)) return "";
      if (!body[field].is_string()) throw InputError(fmt::format("{}: not a string", field));
      return body[field].get<std::string>();
    };
    const std::string part_id = text("part"), name = text("name"), answer = text("answer");
    if (answer.size() > kMaxAnswerChars) {
      throw InputError(fmt::format("answer: longer than {} characters", kMaxAnswerChars));
    }
    std::optional<long> variant;
    if (body.contains("variant") && !body["variant"].is_null()) {
      variant = read_variant(body["variant"].is_number_integer()
                                 ? std::to_string(body["variant"].get<long>())
                                 : body["variant"].dump());
    }
    std::lock_guard lock(work);
    const auto e = entry(p, variant);
    const Answer* a = nullptr;
    const check::Context ctx{e->key, e->table, e->values};
    // An answer that does not exist at these values: "none" is right (check/absent_answer.hpp).
    // Without the key's reason, as the page names it: a slow top's gives ω3, part (c)'s answer.
    if (const auto absent =
            check::judge_absent(e->key, part_id, name, answer, /*with_reason=*/false)) {
      return send_verdict(res, *absent);
    }
    try {
      // No name for a part of several answers: the one the answer's label names, the only one
      // it is right for, or the only one it reads as a value of (check/answer_choice.hpp).
      a = &check::answer_for(ctx, part_id, name, answer, {}, "part", "name");
    } catch (const AnswerNotFound& missing) {
      return send_error(res, 404, missing.what());
    }
    check::Verdict v;
    try {
      v = check::judge(ctx, *a, answer, {});
    } catch (const InputError& error) {
      // The judge names the command line's option; on the page the answer box is the field.
      const std::string what = error.what(), bare = check::without_option(what);
      throw InputError(bare == what                   ? what
                       : bare.rfind("entry ", 0) == 0 ? "answer, " + bare
                                                      : "answer: " + bare);
    }
    send_verdict(res, v);
  }

  static void send_verdict(httplib::Response& res, const check::Verdict& v) {
    send_json(res, json{{"correct", v.correct}, {"verdict", v.line}, {"feedback", v.feedback}}.dump());
  }
};

Server::Server(ServeOptions options) : impl_(std::make_unique<Impl>()) {
  impl_->options = std::move(options);
  if (impl_->options.token.empty()) impl_->options.token = new_token();
  // The listening socket: reusable right after a restart (not shared with another process, as
  // SO_REUSEPORT would allow), and remembered to widen its backlog once bound (bind()).
  impl_->http.set_socket_options([this](int sock) {
    const int yes = 1;
    ::setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    impl_->listening = sock;
  });
  impl_->http.set_payload_max_length(kMaxBody);
  impl_->http.set_read_timeout(kReadTimeoutSeconds, 0);
  impl_->http.set_write_timeout(kReadTimeoutSeconds, 0);
  impl_->http.set_keep_alive_timeout(kReadTimeoutSeconds);
  impl_->http.set_keep_alive_max_count(1000);
  impl_->http.set_tcp_nodelay(true);  // no 40 ms wait for a delayed ACK between header and body
  // A student's browser keeps its connection open between checks and holds a worker meanwhile;
  // enough workers that a class's connections are served at once (the work itself is serialised
  // below, so they mostly wait on the network).
  impl_->http.new_task_queue = [] { return new httplib::ThreadPool(kWorkers); };
  impl_->routes();
}

Server::~Server() = default;

int Server::bind() {
  const auto& o = impl_->options;
  const int port = o.port == 0 ? impl_->http.bind_to_any_port(o.host)
                               : (impl_->http.bind_to_port(o.host, o.port) ? o.port : -1);
  if (port < 0) {
    throw InputError(fmt::format("--port: cannot listen on {}:{} (in use, or not this "
                                 "machine's address)",
                                 o.host, o.port));
  }
  // cpp-httplib listens with a backlog of 5: a class connecting at once would overflow it
  // (connections dropped, or stalled for a minute). Listening again sets the backlog.
  if (impl_->listening >= 0) ::listen(impl_->listening, kListenBacklog);
  return port;
}

void Server::run() { impl_->http.listen_after_bind(); }
void Server::stop() { impl_->http.stop(); }
const std::string& Server::token() const { return impl_->options.token; }

}  // namespace wobble::serve
