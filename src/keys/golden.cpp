#include "keys/golden.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

#include "core/work_budget.hpp"
#include "io/data_dir.hpp"
#include "problem/values.hpp"
#include "io/atomic_write.hpp"
#include "render/render.hpp"
#include "solvers/solve.hpp"

namespace wobble {

namespace {
using J = nlohmann::ordered_json;

double scale_of(const J& value) {
  if (value.is_number()) return std::abs(value.get<double>());
  double s = 0.0;
  if (value.is_array()) {
    for (const auto& v : value) s = std::max(s, scale_of(v));
  }
  return s;
}

void compare(const J& e, const J& a, const std::string& path, double scale,
             std::vector<std::string>& out) {
  if (e.is_number() && a.is_number()) {
    const double x = e.get<double>(), y = a.get<double>();
    if (std::abs(x - y) > kKeyRelTol * std::max(scale, std::abs(x))) {
      out.push_back(fmt::format("{}: {:.17g} -> {:.17g}", path, x, y));
    }
    return;
  }
  if (e.type() != a.type()) {
    out.push_back(fmt::format("{}: {} -> {}", path, e.dump(), a.dump()));
    return;
  }
  if (e.is_object()) {
    for (auto it = e.begin(); it != e.end(); ++it) {
      const std::string p = path.empty() ? it.key() : path + "." + it.key();
      if (!a.contains(it.key())) {
        out.push_back(p + ": removed");
        continue;
      }
      // A value's tolerance scales with the whole answer it belongs to.
      const double s = it.key() == "value" ? scale_of(it.value()) : scale;
      compare(it.value(), a.at(it.key()), p, s, out);
    }
    for (auto it = a.begin(); it != a.end(); ++it) {
      if (!e.contains(it.key()))
        out.push_back((path.empty() ? "" : path + ".") + it.key() + ": added");
    }
    return;
  }
  if (e.is_array()) {
    if (e.size() != a.size()) {
      out.push_back(fmt::format("{}: {} entries -> {}", path, e.size(), a.size()));
      return;
    }
    for (std::size_t i = 0; i < e.size(); ++i) {
      compare(e[i], a[i], fmt::format("{}[{}]", path, i), scale, out);
    }
    return;
  }
  if (e != a) out.push_back(fmt::format("{}: {} -> {}", path, e.dump(), a.dump()));
}

std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

struct Rendered {
  J json;
  std::string json_text, markdown;
};

Rendered render_default(const Problem& p) {
  const Key key = solve(p, parameter_values(p, {}));
  return {key_to_json(key), render_json(key), render_markdown(key)};
}
}  // namespace

std::filesystem::path solutions_dir() { return data_folder("solutions"); }

std::vector<std::string> compare_keys(const J& expected, const J& actual) {
  std::vector<std::string> out;
  compare(expected, actual, "", 0.0, out);
  return out;
}

std::vector<std::string> check_keys(const std::vector<Problem>& problems,
                                    const std::filesystem::path& dir) {
  std::vector<std::string> out;
  std::set<std::string> expected_files;
  for (const auto& p : problems) {
    const Rendered r = render_default(p);
    const auto json_file = dir / (p.id + ".json"), md_file = dir / (p.id + ".md");
    expected_files.insert(json_file.filename().string());
    expected_files.insert(md_file.filename().string());
    if (!std::filesystem::exists(json_file)) {
      out.push_back(json_file.string() + ": missing (run wobble keys --update)");
    } else {
      J stored;
      try {
        stored = J::parse(read_file(json_file));
      } catch (const J::parse_error& e) {
        out.push_back(json_file.string() + ": not valid JSON: " + e.what());
        continue;
      }
      for (const auto& d : compare_keys(stored, r.json))
        out.push_back(json_file.string() + ": " + d);
    }
    if (!std::filesystem::exists(md_file)) {
      out.push_back(md_file.string() + ": missing (run wobble keys --update)");
    } else if (read_file(md_file) != r.markdown) {
      out.push_back(md_file.string() + ": differs from the key the program renders");
    }
  }
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const auto name = entry.path().filename().string();
    const auto ext = entry.path().extension();
    if ((ext == ".json" || ext == ".md") && !expected_files.count(name)) {
      out.push_back(entry.path().string() + ": no problem has this key (stale file)");
    }
  }
  return out;
}

std::vector<std::string> update_keys(const std::vector<Problem>& problems,
                                     const std::filesystem::path& dir) {
  // Compute every key first, so a failing problem leaves every file untouched.
  std::vector<std::pair<std::filesystem::path, std::string>> files;
  for (const auto& p : problems) {
    throw_if_interrupted();
    Rendered r = render_default(p);
    files.emplace_back(dir / (p.id + ".json"), std::move(r.json_text));
    files.emplace_back(dir / (p.id + ".md"), std::move(r.markdown));
  }
  std::filesystem::create_directories(dir);
  // All or nothing: every changed key is staged (written and flushed) before any is renamed in.
  StagedFiles set(/*replace=*/true);
  std::vector<std::string> changed;
  for (const auto& [path, content] : files) {
    if (std::filesystem::exists(path) && read_file(path) == content) continue;
    set.stage(path, content);
    changed.push_back(path.string());
  }
  throw_if_interrupted();
  set.commit();
  return changed;
}

}  // namespace wobble
