#pragma once
// The problem and scene files the bad-input catalog changes one thing in, and the rows' fixture
// files (written only when the row that names them runs), in one place.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "temp_files.hpp"

namespace wobble::test {

// A minimal valid problem; each bad file below changes one thing in it.
inline const std::string kBase = R"TOML(id = "tmp"
title = "t"
solver = "inertia"
statement = "s"

[[parameters]]
name = "m"
unit = "kg"
default = 1
range = "(0, inf)"

[body]
masses = [ { mass = "m", at = ["1", "0", "0"] }, { mass = "m", at = ["0", "1", "0"] } ]

[[parts]]
id = "a"
question = "q"
answers = ["I"]
)TOML";

inline std::string with(const std::string& from, const std::string& to) {
  std::string s = kBase;
  const auto p = s.find(from);
  if (p == std::string::npos) throw std::logic_error("test setup: no '" + from + "'");
  return s.replace(p, from.size(), to);
}

// The fixture files by path, written only when a row that names one runs (fixture_files_for):
// every test process builds the whole catalog to name its test cases, and that writes nothing.
inline std::map<std::string, std::string>& fixture_files() {
  static std::map<std::string, std::string> files;
  return files;
}

// Keeps a fixture's content under its path. Two rows that gave one name to two contents would
// both run the last one: refused, so that each row tests what it says.
inline std::string keep_fixture(const std::string& path, const std::string& content) {
  const auto [at, added] = fixture_files().emplace(path, content);
  if (!added && at->second != content)
    throw std::logic_error("test setup: the fixture name of " + path + " is used twice");
  return path;
}

// A problem or scene file for a row: its path, the content kept until the row runs.
inline std::string file(const std::string& name, const std::string& content) {
  return keep_fixture((scratch_dir() / "bad" / (name + ".toml")).string(), content);
}

// Writes the fixture files that `args` name (as an argument or inside one).
inline void write_fixture_files_for(const std::vector<std::string>& args) {
  for (const auto& [path, content] : fixture_files()) {
    const bool named = std::any_of(args.begin(), args.end(), [&](const std::string& a) {
      return a.find(path) != std::string::npos;
    });
    if (!named) continue;
    std::filesystem::create_directories(std::filesystem::path(path).parent_path());
    std::ofstream(path, std::ios::binary) << content;
  }
}

// A torque-free problem: a box spun about z.
inline const std::string kTop = R"TOML(id = "top"
title = "t"
solver = "torque_free_symmetric"
statement = "s"

[[parameters]]
name = "m"
unit = "kg"
default = 1
range = "(0, inf)"

[[parameters]]
name = "alpha"
unit = "rad"
default = 0.1
range = "[0, pi/2)"

[body]
shapes = [ { shape = "box", mass = "m", sizes = ["1", "1", "2"] } ]

[motion]
omega = "3"
alpha = "alpha"

[[parts]]
id = "a"
question = "q"
answers = ["max_angle"]
)TOML";

inline std::string top_with(const std::string& from, const std::string& to) {
  std::string s = kTop;
  const auto p = s.find(from);
  if (p == std::string::npos) throw std::logic_error("test setup: no '" + from + "'");
  return s.replace(p, from.size(), to);
}

// An asymmetric top spun exactly about its intermediate axis: valid except for a period.
inline const std::string kAsym = R"TOML(id = "asym"
title = "t"
solver = "asymmetric_top"
statement = "s"

[[parameters]]
name = "s"
unit = "rad/s"
default = 3
range = "(0, inf)"

[body]
tensor = [["1", "0", "0"], ["0", "2", "0"], ["0", "0", "2.5"]]

[motion]
w1 = "0"
w2 = "s"
w3 = "0"

[[parts]]
id = "a"
question = "q"
answers = ["period"]
)TOML";

inline std::string asym_with(const std::string& from, const std::string& to) {
  std::string s = kAsym;
  const auto p = s.find(from);
  if (p == std::string::npos) throw std::logic_error("test setup: no '" + from + "'");
  return s.replace(p, from.size(), to);
}

// A problem of the repository with one thing changed.
inline std::string repo_problem_with(const std::string& id, const std::string& from,
                              const std::string& to) {
  std::ifstream in(std::string(WOBBLE_SOURCE_DIR) + "/problems/" + id + ".toml");
  std::string s((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto p = s.find(from);
  if (p == std::string::npos) throw std::logic_error("test setup: no '" + from + "' in " + id);
  s.replace(p, from.size(), to);
  const auto idp = s.find("id = \"" + id + "\"");
  if (idp != std::string::npos) s.replace(idp, 7 + id.size(), "id = \"tmp\"");
  return s;
}

// A minimal valid scene: a box spun about y; each bad scene changes one thing.
inline const std::string kScene = R"TOML(id = "s"
title = "t"

[body]
shapes = [ { shape = "box", mass = 1, sizes = [3, 2, 1] } ]

[initial]
omega = [0.1, 2, 0.1]

[run]
t_end = 1
samples = 3
outputs = ["omega_body"]
)TOML";

inline std::string scene_with(const std::string& from, const std::string& to) {
  std::string s = kScene;
  const auto p = s.find(from);
  if (p == std::string::npos) throw std::logic_error("test setup: no '" + from + "'");
  return s.replace(p, from.size(), to);
}

// Any other file a row names (an answers file): its path, the content kept until the row runs.
inline std::string text_file(const std::string& name, const std::string& content) {
  return keep_fixture((scratch_dir() / "bad" / name).string(), content);
}

inline std::string existing_file() {
  return keep_fixture((scratch_dir() / "bad" / "existing.csv").string(), "keep me\n");
}

}  // namespace wobble::test
