#include "problem/load.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <set>

#include "problem/values.hpp"

#ifndef WOBBLE_SOURCE_DIR
#error "WOBBLE_SOURCE_DIR must be defined by the build"
#endif

namespace wobble {

namespace {
// Builds messages "FILE:LINE: FIELD: what".
class Reader {
 public:
  explicit Reader(std::filesystem::path file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const toml::node* node, const std::string& field,
                         const std::string& what) const {
    std::string where = file_.string();
    if (node != nullptr && node->source().begin.line > 0) {
      where += ":" + std::to_string(node->source().begin.line);
    }
    throw InputError(where + ": " + field + ": " + what);
  }

  void only_keys(const toml::table& t, const std::string& field,
                 const std::set<std::string>& allowed) const {
    for (auto&& [key, node] : t) {
      if (!allowed.count(std::string(key.str()))) {
        std::string list;
        for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
        fail(&node, field.empty() ? std::string(key.str()) : field + "." + std::string(key.str()),
             "unknown key (expected one of: " + list + ")");
      }
    }
  }

  std::string string(const toml::table& t, const std::string& key, const std::string& field,
                     bool required = true, const std::string& fallback = "") const {
    const toml::node* n = t.get(key);
    if (n == nullptr) {
      if (required) fail(&t, field + key, "missing");
      return fallback;
    }
    if (auto s = n->value<std::string>(); s && n->is_string()) return *s;
    fail(n, field + key, "expected a string");
  }

  // An expression: a string, or a number written as its shortest round-trip text.
  std::string expression(const toml::node* n, const std::string& field,
                         const toml::node* parent) const {
    if (n == nullptr) fail(parent, field, "missing");
    if (n->is_string()) return *n->value<std::string>();
    if (n->is_integer()) return std::to_string(*n->value<int64_t>());
    if (n->is_floating_point()) {
      char buf[32];
      auto r = std::to_chars(buf, buf + sizeof buf, *n->value<double>());
      return std::string(buf, r.ptr);
    }
    fail(n, field, "expected an expression (a string such as \"2*m\") or a number");
  }

  std::array<std::string, 3> vector3(const toml::node* n, const std::string& field,
                                     const toml::node* parent) const {
    if (n == nullptr) fail(parent, field, "missing");
    const toml::array* a = n->as_array();
    if (a == nullptr || a->size() != 3) fail(n, field, "expected an array of 3 expressions");
    std::array<std::string, 3> out;
    for (std::size_t i = 0; i < 3; ++i) {
      out[i] = expression(a->get(i), field + "[" + std::to_string(i) + "]", n);
    }
    return out;
  }

  const toml::table& table_at(const toml::array& a, std::size_t i, const std::string& field,
                              const toml::node* parent) const {
    const toml::table* t = a.get(i)->as_table();
    if (t == nullptr) fail(parent, field, "expected a table");
    return *t;
  }

  const toml::array& array(const toml::table& t, const std::string& key,
                           const std::string& field) const {
    const toml::node* n = t.get(key);
    if (n == nullptr) fail(&t, field, "missing");
    const toml::array* a = n->as_array();
    if (a == nullptr) fail(n, field, "expected an array");
    return *a;
  }

 private:
  std::filesystem::path file_;
};

Parameter read_parameter(const Reader& r, const toml::table& t, const std::string& f) {
  r.only_keys(t, f, {"name", "latex", "unit", "description", "default", "range"});
  Parameter p;
  p.name = r.string(t, "name", f + ".");
  p.latex = r.string(t, "latex", f + ".", false, p.name);
  p.unit = r.string(t, "unit", f + ".", false, "");
  p.description = r.string(t, "description", f + ".", false, "");
  const std::string range = r.string(t, "range", f + ".");
  try {
    p.range = parse_interval(range, f + ".range");
  } catch (const InputError& e) {
    r.fail(t.get("range"), f + ".range", e.what());
  }
  const toml::node* d = t.get("default");
  const std::string text = r.expression(d, f + ".default", &t);
  try {
    p.default_value = parse_parameter_value(p, text, f + ".default");
  } catch (const InputError& e) {
    r.fail(d, f + ".default", e.what());
  }
  return p;
}

BodySpec read_body(const Reader& r, const toml::table& body) {
  r.only_keys(body, "body", {"masses", "shapes", "tensor"});
  BodySpec b;
  if (const toml::node* n = body.get("masses")) {
    const toml::array* a = n->as_array();
    if (a == nullptr) r.fail(n, "body.masses", "expected an array of { mass, at } tables");
    for (std::size_t i = 0; i < a->size(); ++i) {
      const std::string f = "body.masses[" + std::to_string(i) + "]";
      const toml::table& t = r.table_at(*a, i, f, n);
      r.only_keys(t, f, {"mass", "at"});
      b.masses.push_back(
          {r.expression(t.get("mass"), f + ".mass", &t), r.vector3(t.get("at"), f + ".at", &t)});
    }
  }
  if (const toml::node* n = body.get("shapes")) {
    const toml::array* a = n->as_array();
    if (a == nullptr) r.fail(n, "body.shapes", "expected an array of shape tables");
    for (std::size_t i = 0; i < a->size(); ++i) {
      const std::string f = "body.shapes[" + std::to_string(i) + "]";
      const toml::table& t = r.table_at(*a, i, f, n);
      r.only_keys(t, f, {"shape", "mass", "sizes", "center"});
      ShapeSpec s;
      s.shape = r.string(t, "shape", f + ".");
      s.mass = r.expression(t.get("mass"), f + ".mass", &t);
      const toml::array& sizes = r.array(t, "sizes", f + ".sizes");
      for (std::size_t k = 0; k < sizes.size(); ++k) {
        s.sizes.push_back(r.expression(sizes.get(k), f + ".sizes[" + std::to_string(k) + "]", &t));
      }
      if (t.get("center")) s.center = r.vector3(t.get("center"), f + ".center", &t);
      b.shapes.push_back(std::move(s));
    }
  }
  if (const toml::node* n = body.get("tensor")) {
    const toml::array* a = n->as_array();
    if (a == nullptr || a->size() != 3)
      r.fail(n, "body.tensor", "expected 3 rows of 3 expressions");
    std::array<std::array<std::string, 3>, 3> rows;
    for (std::size_t i = 0; i < 3; ++i) {
      rows[i] = r.vector3(a->get(i), "body.tensor[" + std::to_string(i) + "]", n);
    }
    b.tensor = rows;
    if (!b.masses.empty() || !b.shapes.empty()) {
      r.fail(n, "body.tensor", "a tensor given directly cannot be combined with masses or shapes");
    }
  }
  if (b.masses.empty() && b.shapes.empty() && !b.tensor) {
    r.fail(&body, "body", "needs masses, shapes or a tensor");
  }
  return b;
}

PartSpec read_part(const Reader& r, const toml::table& t, const std::string& f) {
  r.only_keys(t, f, {"id", "question", "answers"});
  PartSpec p;
  p.id = r.string(t, "id", f + ".");
  p.question = r.string(t, "question", f + ".");
  const toml::array& answers = r.array(t, "answers", f + ".answers");
  if (answers.empty()) r.fail(&t, f + ".answers", "a part needs at least one answer");
  for (std::size_t i = 0; i < answers.size(); ++i) {
    const std::string af = f + ".answers[" + std::to_string(i) + "]";
    const toml::node* n = answers.get(i);
    if (n->is_string()) {
      const std::string name = *n->value<std::string>();
      p.answers.push_back({name, name});
    } else if (const toml::table* at = n->as_table()) {
      r.only_keys(*at, af, {"name", "quantity"});
      AnswerSpec a;
      a.name = r.string(*at, "name", af + ".");
      a.quantity = r.string(*at, "quantity", af + ".", false, a.name);
      p.answers.push_back(a);
    } else {
      r.fail(n, af, "expected an answer name or a { name, quantity } table");
    }
  }
  return p;
}
}  // namespace

Problem load_problem(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    throw InputError(file.string() + ": no such problem file");
  }
  // A problem file is a few kilobytes; refuse anything absurd before reading it.
  constexpr std::uintmax_t kMaxFileBytes = 1 << 20;
  if (const auto size = std::filesystem::file_size(file, ec); !ec && size > kMaxFileBytes) {
    throw InputError(file.string() + ": file is " + std::to_string(size) +
                     " bytes; a problem file may have at most 1 MiB");
  }
  toml::table root;
  try {
    root = toml::parse_file(file.string());
  } catch (const toml::parse_error& e) {
    throw InputError(file.string() + ":" + std::to_string(e.source().begin.line) +
                     ": malformed TOML: " + std::string(e.description()));
  }
  Reader r(file);
  r.only_keys(root, "",
              {"id", "title", "source", "statement", "solver", "notes", "parameters", "body",
               "motion", "parts"});
  Problem p;
  p.file = file;
  p.id = r.string(root, "id", "");
  p.title = r.string(root, "title", "");
  p.source = r.string(root, "source", "", false, "");
  p.statement = r.string(root, "statement", "");
  p.solver = r.string(root, "solver", "");
  if (const toml::node* n = root.get("notes")) {
    const toml::array* a = n->as_array();
    if (a == nullptr) r.fail(n, "notes", "expected an array of strings");
    for (std::size_t i = 0; i < a->size(); ++i) {
      if (!a->get(i)->is_string())
        r.fail(n, "notes[" + std::to_string(i) + "]", "expected a string");
      p.notes.push_back(*a->get(i)->value<std::string>());
    }
  }
  const toml::array& params = r.array(root, "parameters", "parameters");
  std::set<std::string> names;
  for (std::size_t i = 0; i < params.size(); ++i) {
    const std::string f = "parameters[" + std::to_string(i) + "]";
    p.parameters.push_back(read_parameter(r, r.table_at(params, i, f, &root), f));
    if (!names.insert(p.parameters.back().name).second) {
      r.fail(params.get(i), f + ".name",
             "parameter '" + p.parameters.back().name + "' declared twice");
    }
  }
  try {
    (void)p.symbol_table();
  } catch (const std::invalid_argument& e) {
    r.fail(&params, "parameters", e.what());
  }
  const toml::node* body = root.get("body");
  if (body == nullptr || !body->is_table()) r.fail(&root, "body", "missing (a table)");
  p.body = read_body(r, *body->as_table());
  if (const toml::node* n = root.get("motion")) {
    const toml::table* t = n->as_table();
    if (t == nullptr) r.fail(n, "motion", "expected a table { omega, alpha }");
    r.only_keys(*t, "motion", {"omega", "alpha"});
    p.motion = MotionSpec{r.expression(t->get("omega"), "motion.omega", t),
                          r.expression(t->get("alpha"), "motion.alpha", t)};
  }
  const toml::array& parts = r.array(root, "parts", "parts");
  std::set<std::string> ids;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const std::string f = "parts[" + std::to_string(i) + "]";
    p.parts.push_back(read_part(r, r.table_at(parts, i, f, &root), f));
    if (!ids.insert(p.parts.back().id).second) r.fail(parts.get(i), f + ".id", "part id repeated");
  }
  if (p.parts.empty()) r.fail(&root, "parts", "a problem needs at least one part");
  return p;
}

std::filesystem::path problems_dir() {
  if (const char* env = std::getenv("WOBBLE_PROBLEMS"); env != nullptr && *env != '\0') return env;
  return std::filesystem::path(WOBBLE_SOURCE_DIR) / "problems";
}

Problem find_problem(const std::string& id_or_file) {
  const std::filesystem::path as_path(id_or_file);
  if (as_path.extension() == ".toml" || id_or_file.find('/') != std::string::npos) {
    return load_problem(as_path);
  }
  const auto file = problems_dir() / (id_or_file + ".toml");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    std::string known;
    for (const auto& p : load_catalog()) known += (known.empty() ? "" : ", ") + p.id;
    throw InputError("unknown problem '" + id_or_file + "' (known: " + known + ")");
  }
  return load_problem(file);
}

std::vector<Problem> load_catalog() {
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(problems_dir(), ec)) {
    if (entry.path().extension() == ".toml") files.push_back(entry.path());
  }
  if (ec) throw InputError(problems_dir().string() + ": cannot read the problem folder");
  std::sort(files.begin(), files.end());
  std::vector<Problem> out;
  for (const auto& f : files) {
    out.push_back(load_problem(f));
    if (out.back().id != f.stem().string()) {
      throw InputError(f.string() + ": id: '" + out.back().id + "' differs from the file name");
    }
  }
  return out;
}

}  // namespace wobble
