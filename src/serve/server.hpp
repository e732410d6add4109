#pragma once
/// @file
/// `wobble serve`: the worksheet for a whole class over HTTP (cpp-httplib), a JSON API over the
/// existing layers and the page (web/), with nothing computed twice.
///
///   GET  /                                  the page (web/page/page.html)
///   GET  /assets/PATH                       a built-in asset (web/assets.hpp), exactly by name
///   GET  /api/problems                      [{"id", "title"}]
///   GET  /api/problems/ID[?variant=N]       the student view (web/problem_view.hpp): no answers
///   POST /api/problems/ID/check             {"part", "name"?, "answer", "variant"?} -> the
///                                           judge's verdict: {"correct", "verdict", "feedback"}
///   GET  /api/problems/ID/hint?part=P       {"hint"}
///   GET  /api/problems/ID/key[?variant=N]   the JSON key: instructors only (the token)
///   GET  /api/problems/ID/motion[?variant=N] the motion for the 3-D view (web/motion.hpp);
///                                           404 for a problem without one
///   GET  /api/session[?token=T]             {"key": whether this request may see keys}
///   GET  /api/scenes                        [{"id", "title"}]
///   GET  /api/scenes/ID/motion              a scene's motion at its defaults
///
/// Answers and keys are never sent to a student: the key endpoint answers only with the token
/// the server prints at start (header "Authorization: Bearer TOKEN" or ?token=), or to everyone
/// when started with `reveal` (self-study). Every request is validated: a 4xx with
/// {"error": "..."} for malformed JSON, a body over kMaxBody, an unknown problem, part or
/// answer, a bad variant; a client that sends nothing is dropped after kReadTimeout. The keys
/// and motions are computed once per (problem, variant) and kept (up to kMaxCachedKeys and
/// kMaxCachedMotions). GiNaC is not thread-safe, so solving and judging run one at a time (each
/// takes milliseconds).
#include <memory>
#include <string>
#include <vector>

#include "problem/problem.hpp"
#include "problem/scene.hpp"

namespace wobble::serve {

/// A request body larger than this is refused (413): an answer is a line, not a file.
inline constexpr std::size_t kMaxBody = 16 * 1024;
/// A connection that sends nothing for this long is closed.
inline constexpr int kReadTimeoutSeconds = 5;
/// Connections served at once: a class of a few hundred, each browser keeping one open.
inline constexpr std::size_t kWorkers = 256;
/// Connections waiting to be accepted: a class arriving at once.
inline constexpr int kListenBacklog = 1024;
/// Keys kept at once; beyond, the cache starts again (a class uses a few hundred).
inline constexpr std::size_t kMaxCachedKeys = 4096;
/// Motions kept at once (up to ~200 KB each: at most ~100 MB).
inline constexpr std::size_t kMaxCachedMotions = 512;

struct ServeOptions {
  std::string host = "127.0.0.1";
  int port = 8080;  ///< 0: any free port
  std::vector<Problem> problems;
  std::vector<Scene> scenes;
  bool reveal = false;  ///< keys for everyone (self-study)
  std::string token;    ///< the instructor's token (empty: one is drawn)
};

class Server {
 public:
  explicit Server(ServeOptions options);
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  /// Binds the port. @return the port. @throws InputError naming host and port if it cannot.
  int bind();
  /// Serves until stop() (from another thread or a signal handler's thread).
  void run();
  void stop();
  const std::string& token() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// A token no one can guess: 128 bits from the system's random source, as hex.
std::string new_token();

}  // namespace wobble::serve
