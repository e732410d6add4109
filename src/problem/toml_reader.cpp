#include "problem/toml_reader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "core/shapes.hpp"
#include "problem/values.hpp"
#include "symbolic/expression_guard.hpp"
#include "symbolic/units.hpp"

namespace wobble::detail {

namespace {
// Why a formula could not use `name` for a parameter; "" if it can.
std::string unusable_name(const std::string& name) {
  if (!sym::is_identifier(name))
    return "'" + printable(name, 40) +
           "' is no name a formula can use: ASCII letters, digits and '_', not starting with a "
           "digit (the key sets it in Greek by its latex, as latex = \"\\\\alpha\")";
  // GiNaC's reader takes I for the imaginary unit whatever the table says: every formula with
  // the parameter would have a complex value.
  if (name == "I") return "'I' is the imaginary unit in a formula; name it otherwise, as I0 or I_1";
  if (name == "pi" || name == "Pi") return "'" + name + "' is the constant π in a formula";
  // A symbol named sqrt would print as "√" in the key, which reads back as the function.
  if (sym::is_function_name(name))
    return "'" + name + "' is a function in a formula (" + name +
           "(x)); name the parameter otherwise";
  return "";
}

// A parameter's unit, which must be SI: its value is used in the file's expressions, and the
// answers' units assumed, as it is ("200" for unit = "g" would be taken as 200 kg). An angle's
// unit is spelt "rad", as Parameter::is_angle tests it ("radians" is read as rad).
std::string si_parameter_unit(const Reader& r, const toml::node* node, const std::string& text,
                              const std::string& default_text, const std::string& field) {
  Unit unit;
  try {
    unit = parse_unit(text, field);
  } catch (const InputError& e) {
    r.fail(node, field, e.what());
  }
  if (unit.to_si != 1.0) {
    r.fail(node, field,
           "'" + text + "' is not SI; a parameter is in SI units, here unit = \"" +
               si_unit_text(unit) + "\", and its default may carry its own unit: default = \"" +
               default_text + " " + text + "\"");
  }
  return unit.angle && unit.dim == std::array{0, 0, 0} ? "rad" : text;
}
}  // namespace

std::string math_problem(const std::string& markdown) {
  std::size_t open = std::string::npos;  // where the math being read began
  int depth = 0;
  for (std::size_t i = 0; i < markdown.size(); ++i) {
    const char c = markdown[i];
    if (c == '$') {
      if (open != std::string::npos && depth > 0)
        return "the math \"" + printable(markdown.substr(open, i + 1 - open), 40) +
               "\" leaves a '{' unclosed";
      open = open == std::string::npos ? i : std::string::npos;
      depth = 0;
    } else if (open != std::string::npos && c == '\\') {
      ++i;  // \{ \} \\ \$: a character to show, not a group
    } else if (open != std::string::npos && (c == '{' || c == '}')) {
      depth += c == '{' ? 1 : -1;
      if (depth < 0)
        return "the math \"" + printable(markdown.substr(open, i + 1 - open), 40) +
               "\" closes a '}' that no '{' opened";
    }
  }
  if (open == std::string::npos) return "";
  return "a '$' opens math that no '$' closes: \"" + printable(markdown.substr(open), 40) +
         "\" (math is written $...$)";
}

Parameter read_parameter(const Reader& r, const toml::table& t, const std::string& f) {
  r.only_keys(t, f, {"name", "latex", "unit", "description", "default", "range", "fixed"});
  Parameter p;
  p.name = r.string(t, "name", f + ".");
  if (const std::string why = unusable_name(p.name); !why.empty())
    r.fail(t.get("name"), f + ".name", why);
  p.latex = r.string(t, "latex", f + ".", false, p.name);
  p.unit = r.string(t, "unit", f + ".", false, "");
  p.description = r.prose(t, "description", f + ".", false, "");
  if (const toml::node* fixed = t.get("fixed")) {
    if (!fixed->is_boolean()) r.fail(fixed, f + ".fixed", "must be true or false");
    p.fixed = fixed->as_boolean()->get();
  }
  const toml::node* d = t.get("default");
  const std::string text = r.expression(d, f + ".default", &t);
  if (!p.unit.empty()) p.unit = si_parameter_unit(r, t.get("unit"), p.unit, text, f + ".unit");
  const std::string range = r.string(t, "range", f + ".");
  try {
    p.range = parse_interval(range, f + ".range", p);
  } catch (const InputError& e) {
    r.fail(t.get("range"), f + ".range", e.what());
  }
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
    if (a == nullptr) r.wrong(n, "body.masses", "an array of { mass, at } tables");
    for (std::size_t i = 0; i < a->size(); ++i) {
      const std::string f = "body.masses[" + std::to_string(i) + "]";
      const toml::table& t = r.table_at(*a, i, f);
      r.only_keys(t, f, {"mass", "at"});
      b.masses.push_back(
          {r.expression(t.get("mass"), f + ".mass", &t), r.vector3(t.get("at"), f + ".at", &t)});
    }
  }
  if (const toml::node* n = body.get("shapes")) {
    const toml::array* a = n->as_array();
    if (a == nullptr) r.wrong(n, "body.shapes", "an array of shape tables");
    for (std::size_t i = 0; i < a->size(); ++i) {
      const std::string f = "body.shapes[" + std::to_string(i) + "]";
      const toml::table& t = r.table_at(*a, i, f);
      r.only_keys(t, f, {"shape", "mass", "sizes", "center"});
      ShapeSpec s;
      s.shape = r.string(t, "shape", f + ".");
      // The shape and its number of sizes refused here, where the file's line is known.
      ShapeKind kind{};
      try {
        kind = shape_kind_from_name(s.shape);
      } catch (const std::invalid_argument& e) {
        const bool point = s.shape == "point" || s.shape == "particle";
        r.fail(t.get("shape"), f + ".shape",
               e.what() + std::string(point ? "; point masses are body.masses, { mass, at }" : ""));
      }
      s.mass = r.expression(t.get("mass"), f + ".mass", &t);
      const toml::array& sizes = r.array(t, "sizes", f + ".sizes");
      if (const auto& names = shape_size_names(kind); sizes.size() != names.size())
        r.fail(&sizes, f + ".sizes",
               fmt::format("a {} takes {} size{} ({}), got {}", s.shape, names.size(),
                           names.size() == 1 ? "" : "s", fmt::join(names, ", "), sizes.size()));
      for (std::size_t k = 0; k < sizes.size(); ++k) {
        s.sizes.push_back(r.expression(sizes.get(k), f + ".sizes[" + std::to_string(k) + "]", &t));
      }
      if (t.get("center")) s.center = r.vector3(t.get("center"), f + ".center", &t);
      b.shapes.push_back(std::move(s));
    }
  }
  if (const toml::node* n = body.get("tensor")) {
    const toml::array* a = n->as_array();
    if (a == nullptr || a->size() != 3) r.wrong(n, "body.tensor", "3 rows of 3 expressions");
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

std::vector<Parameter> read_parameters(const Reader& r, const toml::table& root) {
  const toml::array& params = r.array(root, "parameters", "parameters");
  Problem p;
  std::set<std::string> names;
  for (std::size_t i = 0; i < params.size(); ++i) {
    const std::string f = "parameters[" + std::to_string(i) + "]";
    p.parameters.push_back(read_parameter(r, r.table_at(params, i, f), f));
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
  return p.parameters;
}

std::vector<std::filesystem::path> toml_files_in(const std::filesystem::path& dir,
                                                 const std::string& what) {
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    if (entry.path().extension() == ".toml") files.push_back(entry.path());
  }
  if (ec) throw InputError(dir.string() + ": cannot read the " + what + " folder");
  std::sort(files.begin(), files.end());
  return files;
}

std::filesystem::path resolve_id_or_file(const std::string& id_or_file,
                                         const std::filesystem::path& dir,
                                         const std::string& what) {
  const std::filesystem::path as_path(id_or_file);
  if (as_path.extension() == ".toml" || id_or_file.find('/') != std::string::npos) return as_path;
  const auto file = dir / (id_or_file + ".toml");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    std::string known;
    for (const auto& f : toml_files_in(dir, what)) {
      known += (known.empty() ? "" : ", ") + f.stem().string();
    }
    const std::string shown =
        id_or_file.size() > 60 ? id_or_file.substr(0, 60) + "..." : id_or_file;
    throw InputError("unknown " + what + " '" + shown + "' (known: " + known + ")");
  }
  return file;
}

namespace {
void add_field_lines(const toml::node& node, const std::string& field,
                     std::map<std::string, int>& lines) {
  if (!field.empty() && node.source().begin.line > 0)
    lines.emplace(field, static_cast<int>(node.source().begin.line));
  if (const toml::table* t = node.as_table()) {
    for (auto&& [key, value] : *t) {
      const std::string name(key.str());
      add_field_lines(value, field.empty() ? name : field + "." + name, lines);
    }
  } else if (const toml::array* a = node.as_array()) {
    for (std::size_t i = 0; i < a->size(); ++i)
      add_field_lines(*a->get(i), field + "[" + std::to_string(i) + "]", lines);
  }
}
}  // namespace

std::map<std::string, int> field_lines_of(const toml::table& root) {
  std::map<std::string, int> lines;
  add_field_lines(root, "", lines);
  return lines;
}

void check_id_is_file_name(const std::string& id, const std::filesystem::path& file) {
  if (id != file.stem().string()) {
    throw InputError(file.string() + ": id: '" + id + "' differs from the file name");
  }
}

toml::table parse_toml_file(const std::filesystem::path& file, const std::string& what) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    const auto status = std::filesystem::status(file, ec);
    if (std::filesystem::is_directory(status)) {
      throw InputError(file.string() + ": is a folder; give a " + what + " file (ID.toml) in it, "
                       "or an id (wobble list)");
    }
    if (std::filesystem::exists(status)) {
      throw InputError(file.string() + ": is not a regular file (a device or pipe); give a " +
                       what + " file");
    }
    throw InputError(file.string() + ": no such " + what + " file");
  }
  // A problem or scene file is a few kilobytes; refuse anything absurd before reading it.
  if (const auto size = std::filesystem::file_size(file, ec); !ec && size > kMaxTomlBytes) {
    throw InputError(file.string() + ": file is " + std::to_string(size) + " bytes; a " + what +
                     " file may have at most 1 MiB");
  }
  std::ifstream in(file, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in && !in.eof()) throw InputError(file.string() + ": cannot read the " + what + " file");
  return parse_toml_text(text, file, what);
}

toml::table parse_toml_text(const std::string& text, const std::filesystem::path& name,
                            const std::string& what) {
  if (text.size() > kMaxTomlBytes) {
    throw InputError(name.string() + ": file is " + std::to_string(text.size()) + " bytes; a " +
                     what + " file may have at most 1 MiB");
  }
  // What Windows' Notepad saves as "Unicode": TOML is UTF-8, and toml++ would say only that the
  // first line holds an invalid UTF-8 sequence.
  if (starts_as_utf16(text)) {
    throw InputError(name.string() + ": the " + what +
                     " file is UTF-16 (its first bytes say so); TOML is UTF-8: save it as UTF-8");
  }
  try {
    return toml::parse(text, name.string());
  } catch (const toml::parse_error& e) {
    throw InputError(name.string() + ":" + std::to_string(e.source().begin.line) +
                     ": malformed TOML: " + std::string(e.description()));
  }
}

}  // namespace wobble::detail
