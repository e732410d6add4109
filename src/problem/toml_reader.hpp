#pragma once
/// @file
/// Internal to the problem layer: reading TOML with messages "FILE:LINE: FIELD: what", shared by
/// the problem and scene loaders.
#include <toml++/toml.h>

#include <array>
#include <charconv>
#include <filesystem>
#include <map>
#include <set>
#include <string>

#include "core/characters.hpp"
#include "problem/problem.hpp"

namespace wobble::detail {

/// What stops `markdown`'s $...$ math from typesetting: a '$' that opens math never closed, or
/// a brace unbalanced inside one span ('\{' and '\}' are braces to show); "" if none.
std::string math_problem(const std::string& markdown);

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
    // A message that names the field already (a value's reader was told it) names it once.
    const std::string named = field + ": ";
    const bool said = what.compare(0, named.size(), named) == 0;
    throw InputError(where + ": " + named + (said ? what.substr(named.size()) : what));
  }

  // A value of the wrong kind: "expected WHAT, got " the value as written (a number, a string
  // in quotes) or its kind (an array of 2, a table).
  [[noreturn]] void wrong(const toml::node* node, const std::string& field,
                          const std::string& what) const {
    fail(node, field, "expected " + what + ", got " + described(node));
  }

  static std::string described(const toml::node* node) {
    if (node == nullptr) return "nothing";
    if (node->is_string()) return "\"" + printable(*node->value<std::string>(), 40) + "\"";
    if (node->is_integer()) return std::to_string(*node->value<int64_t>());
    if (node->is_floating_point()) {
      char buf[32];
      const auto r = std::to_chars(buf, buf + sizeof buf, *node->value<double>());
      return std::string(buf, r.ptr);
    }
    if (node->is_boolean()) return *node->value<bool>() ? "true" : "false";
    if (const toml::array* a = node->as_array())
      return a->empty() ? "an empty array" : "an array of " + std::to_string(a->size());
    if (node->is_table()) return "a table";
    return "a date or time";
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

  // A string node's text. Files hold plain text: a control character (ESC starts a terminal
  // command, and titles and units are printed) is refused; newlines and tabs are text.
  std::string text(const toml::node* n, const std::string& field) const {
    std::string s = *n->value<std::string>();
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (s[i] != '\n' && s[i] != '\t' && is_control_at(s, i))
        fail(n, field, "contains " + character_name(s, i) + "; a file holds plain text");
    }
    return s;
  }

  std::string string(const toml::table& t, const std::string& key, const std::string& field,
                     bool required = true, const std::string& fallback = "") const {
    const toml::node* n = t.get(key);
    if (n == nullptr) {
      if (required) fail(&t, field + key, "missing");
      return fallback;
    }
    if (n->is_string()) return text(n, field + key);
    wrong(n, field + key, "a string");
  }

  // Text shown to students (a title, a question, a statement): where required, a blank one is
  // refused as a missing one is.
  std::string words(const toml::table& t, const std::string& key, const std::string& field,
                    bool required = true, const std::string& fallback = "") const {
    const std::string s = string(t, key, field, required, fallback);
    if (required && s.find_first_not_of(" \t\n") == std::string::npos)
      fail(t.get(key), field + key, "empty; it is shown to students");
    return s;
  }

  // Markdown with $...$ math (a statement, a question, a hint, a description): every LaTeX
  // renderer would stop at math left open or a brace left unclosed ("$\frac{1}{2$"), pdflatex
  // with no PDF and KaTeX with red text; refused here, naming the field and the math.
  std::string prose(const toml::table& t, const std::string& key, const std::string& field,
                    bool required = true, const std::string& fallback = "") const {
    const std::string s = words(t, key, field, required, fallback);
    if (const std::string why = math_problem(s); !why.empty()) fail(t.get(key), field + key, why);
    return s;
  }

  // An expression: a string, or a number written as its shortest round-trip text.
  std::string expression(const toml::node* n, const std::string& field,
                         const toml::node* parent) const {
    if (n == nullptr) fail(parent, field, "missing");
    if (n->is_string()) return text(n, field);
    if (n->is_integer()) return std::to_string(*n->value<int64_t>());
    if (n->is_floating_point()) {
      char buf[32];
      auto r = std::to_chars(buf, buf + sizeof buf, *n->value<double>());
      return std::string(buf, r.ptr);
    }
    wrong(n, field, "an expression (a string such as \"2*m\") or a number");
  }

  std::array<std::string, 3> vector3(const toml::node* n, const std::string& field,
                                     const toml::node* parent) const {
    if (n == nullptr) fail(parent, field, "missing");
    const toml::array* a = n->as_array();
    if (a == nullptr || a->size() != 3) wrong(n, field, "an array of 3 expressions");
    std::array<std::string, 3> out;
    for (std::size_t i = 0; i < 3; ++i) {
      out[i] = expression(a->get(i), field + "[" + std::to_string(i) + "]", n);
    }
    return out;
  }

  const toml::table& table_at(const toml::array& a, std::size_t i, const std::string& field) const {
    const toml::table* t = a.get(i)->as_table();
    if (t == nullptr) wrong(a.get(i), field, "a table");
    return *t;
  }

  const toml::array& array(const toml::table& t, const std::string& key,
                           const std::string& field) const {
    const toml::node* n = t.get(key);
    if (n == nullptr) fail(&t, field, "missing");
    const toml::array* a = n->as_array();
    if (a == nullptr) wrong(n, field, "an array");
    return *a;
  }

 private:
  std::filesystem::path file_;
};

/// A parameter table [[parameters]] (name, latex, unit, description, default, range).
Parameter read_parameter(const Reader& r, const toml::table& t, const std::string& f);
/// The [body] table: masses, shapes or a tensor.
BodySpec read_body(const Reader& r, const toml::table& body);
/// Every [[parameters]] entry of root, names unique, symbols valid.
std::vector<Parameter> read_parameters(const Reader& r, const toml::table& root);
/// A folder of definitions (problems/, scenes/): its .toml files, sorted.
/// @throws InputError naming the folder if it cannot be read.
std::vector<std::filesystem::path> toml_files_in(const std::filesystem::path& dir,
                                                 const std::string& what);
/// The file an argument names: itself if it looks like a path (ends in .toml or has a '/'),
/// else dir/ID.toml. @throws InputError "unknown WHAT 'ID' (known: ...)" if that file is absent.
std::filesystem::path resolve_id_or_file(const std::string& id_or_file,
                                         const std::filesystem::path& dir, const std::string& what);
/// @throws InputError unless a catalog file's id equals its file name.
void check_id_is_file_name(const std::string& id, const std::filesystem::path& file);

/// The line of every field of a document, named as messages name fields ("motion.omega",
/// "body.shapes[0].sizes[2]"): problem/field_lines.hpp.
std::map<std::string, int> field_lines_of(const toml::table& root);

/// The most a problem or scene file may hold: a few kilobytes are usual.
inline constexpr std::size_t kMaxTomlBytes = std::size_t{1} << 20;

/// Refuses files over 1 MiB, then parses. @throws InputError "FILE:LINE: malformed TOML: ...".
toml::table parse_toml_file(const std::filesystem::path& file, const std::string& what);
/// The same for text already read; `name` stands for the file in messages.
toml::table parse_toml_text(const std::string& text, const std::filesystem::path& name,
                            const std::string& what);

}  // namespace wobble::detail
