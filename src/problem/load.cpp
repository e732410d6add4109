#include "problem/load.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdlib>
#include <set>

#include "io/data_dir.hpp"
#include "problem/toml_reader.hpp"
#include "problem/values.hpp"


namespace wobble {

namespace {
using detail::Reader;
using namespace detail;

// An answer's `mistakes`: [{ value, what, remedy }, ..], each of the three a string that says
// something. The value is read when the problem is solved, against the answer's unit.
std::vector<MistakeSpec> read_mistakes(const Reader& r, const toml::node* n,
                                       const std::string& af) {
  const std::string f = af + ".mistakes";
  const toml::array* list = n->as_array();
  if (list == nullptr) r.wrong(n, f, "a list of { value, what, remedy } tables");
  std::vector<MistakeSpec> out;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string mf = f + "[" + std::to_string(i) + "]";
    const toml::table* t = list->get(i)->as_table();
    if (t == nullptr) r.wrong(list->get(i), mf, "a { value, what, remedy } table");
    r.only_keys(*t, mf, {"value", "what", "remedy"});
    MistakeSpec m;
    m.value = r.expression(t->get("value"), mf + ".value", t);
    m.what = r.string(*t, "what", mf + ".");
    m.remedy = r.string(*t, "remedy", mf + ".");
    for (const auto& [key, text] : {std::pair{"value", &m.value}, std::pair{"what", &m.what},
                                    std::pair{"remedy", &m.remedy}}) {
      if (trim(*text).empty()) r.fail(t->get(key), mf + "." + key, "is empty");
    }
    m.field = mf;
    out.push_back(std::move(m));
  }
  return out;
}

PartSpec read_part(const Reader& r, const toml::table& t, const std::string& f) {
  r.only_keys(t, f, {"id", "question", "answers", "hint"});
  PartSpec p;
  p.id = r.string(t, "id", f + ".");
  // Typed after the problem's id (wobble check ID a ANSWER, --part a): one word.
  const bool word = !p.id.empty() && std::all_of(p.id.begin(), p.id.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
  if (!word)
    r.fail(t.get("id"), f + ".id",
           "'" + printable(p.id, 40) +
               "' is no part id: ASCII letters, digits and '_', as students type it (a, b, 2c)");
  p.question = r.prose(t, "question", f + ".");
  p.hint = r.prose(t, "hint", f + ".", false, "");
  const toml::array& answers = r.array(t, "answers", f + ".answers");
  if (answers.empty()) r.fail(&t, f + ".answers", "a part needs at least one answer");
  for (std::size_t i = 0; i < answers.size(); ++i) {
    const std::string af = f + ".answers[" + std::to_string(i) + "]";
    const toml::node* n = answers.get(i);
    if (n->is_string()) {
      const std::string name = r.text(n, af);
      p.answers.push_back({name, name, std::nullopt});
    } else if (const toml::table* at = n->as_table()) {
      r.only_keys(*at, af, {"name", "quantity", "tolerance", "mistakes"});
      AnswerSpec a;
      a.name = r.string(*at, "name", af + ".");
      a.quantity = r.string(*at, "quantity", af + ".", false, a.name);
      if (const toml::node* tn = at->get("tolerance")) {
        // 0.02, or "2%" as a tolerance is said.
        const auto v =
            tn->is_string() ? percent_as_fraction(*tn->value<std::string>()) : tn->value<double>();
        if (!v || !(*v > 0.0 && *v < 1.0))
          r.wrong(tn, af + ".tolerance", "a relative tolerance between 0 and 1 (0.05 is 5%)");
        const std::string typed = tn->is_string() ? "\"" + *tn->value<std::string>() + "\"" : "";
        if (const std::string why = tolerance_too_fine(*v, typed); !why.empty())
          r.fail(tn, af + ".tolerance", why);
        a.tolerance = *v;
      }
      if (const toml::node* mn = at->get("mistakes")) a.mistakes = read_mistakes(r, mn, af);
      p.answers.push_back(a);
    } else {
      r.wrong(n, af, "an answer name or a { name, quantity, tolerance, mistakes } table");
    }
  }
  return p;
}
const SolverSchema& schema_for(const Reader& r, const toml::table& root, const std::string& solver,
                               const SolverSchemas& schemas) {
  std::vector<std::string> known;
  for (const auto& s : schemas) {
    if (s.name == solver) return s;
    known.push_back(s.name);
  }
  r.fail(root.get("solver"), "solver",
         fmt::format("unknown solver '{}' (known: {})", solver, fmt::join(known, ", ")));
}

// The [motion] table: exactly the keys the solver takes (its registry row), each an expression.
std::optional<MotionSpec> read_motion(Reader& r, const toml::table& root,
                                      const SolverSchema& solver) {
  const toml::node* n = root.get("motion");
  const auto& keys = solver.motion_keys;
  if (keys.empty()) {
    if (n != nullptr) r.fail(n, "motion", "the " + solver.name + " solver takes no [motion] table");
    return std::nullopt;
  }
  const std::string wanted = "a table { " + fmt::format("{}", fmt::join(keys, ", ")) + " }";
  if (n == nullptr) r.fail(&root, "motion", "missing (" + wanted + ")");
  const toml::table* t = n->as_table();
  if (t == nullptr) r.wrong(n, "motion", wanted);
  r.only_keys(*t, "motion", {keys.begin(), keys.end()});
  MotionSpec m;
  for (const auto& key : keys) {
    m.exprs[key] = r.expression(t->get(key), "motion." + key, t);
  }
  return m;
}

// Every answer's quantity is one the solver computes: a typo is refused here, with its line.
void check_quantities(const Reader& r, const toml::array& answers, const std::string& field,
                      const PartSpec& part, const SolverSchema& solver) {
  const auto& known = solver.quantities;
  for (std::size_t k = 0; k < part.answers.size(); ++k) {
    const std::string& q = part.answers[k].quantity;
    if (std::find(known.begin(), known.end(), q) != known.end()) continue;
    r.fail(answers.get(k), field + ".answers[" + std::to_string(k) + "]",
           fmt::format("unknown quantity '{}' for the {} solver (it computes: {})", q, solver.name,
                       fmt::join(known, ", ")));
  }
}
}  // namespace

namespace {
Problem load_problem_table(const toml::table& root, const std::filesystem::path& file,
                           const SolverSchemas& schemas);
}  // namespace

Problem load_problem(const std::filesystem::path& file, const SolverSchemas& schemas) {
  return load_problem_table(parse_toml_file(file, "problem"), file, schemas);
}

Problem load_problem_text(const std::string& text, const std::filesystem::path& name,
                          const SolverSchemas& schemas) {
  return load_problem_table(parse_toml_text(text, name, "problem"), name, schemas);
}

namespace {
Problem load_problem_table(const toml::table& root, const std::filesystem::path& file,
                           const SolverSchemas& schemas) {
  Reader r(file);
  r.only_keys(root, "",
              {"id", "title", "source", "statement", "solver", "notes", "parameters", "body",
               "motion", "parts"});
  Problem p;
  p.file = file;
  p.id = r.string(root, "id", "");
  p.title = r.words(root, "title", "");
  p.source = r.string(root, "source", "", false, "");
  p.statement = r.prose(root, "statement", "");
  p.solver = r.string(root, "solver", "");
  const SolverSchema& solver = schema_for(r, root, p.solver, schemas);
  if (const toml::node* n = root.get("notes")) {
    const toml::array* a = n->as_array();
    if (a == nullptr) r.wrong(n, "notes", "an array of strings");
    for (std::size_t i = 0; i < a->size(); ++i) {
      if (!a->get(i)->is_string())
        r.wrong(a->get(i), "notes[" + std::to_string(i) + "]", "a string");
      p.notes.push_back(r.text(a->get(i), "notes[" + std::to_string(i) + "]"));
    }
  }
  p.parameters = read_parameters(r, root);
  const toml::node* body = root.get("body");
  if (body == nullptr || !body->is_table()) r.fail(&root, "body", "missing (a table)");
  p.body = read_body(r, *body->as_table());
  p.motion = read_motion(r, root, solver);
  const toml::array& parts = r.array(root, "parts", "parts");
  std::set<std::string> ids, answer_names;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const std::string f = "parts[" + std::to_string(i) + "]";
    p.parts.push_back(read_part(r, r.table_at(parts, i, f), f));
    if (!ids.insert(p.parts.back().id).second) {
      r.fail(parts.get(i), f + ".id",
             "part id '" + p.parts.back().id + "' is used twice; give each part its own");
    }
    // `check --name` finds an answer by its name: two of one name would hide the second.
    const toml::array& answers = *r.table_at(parts, i, f).get_as<toml::array>("answers");
    check_quantities(r, answers, f, p.parts.back(), solver);
    for (std::size_t k = 0; k < p.parts.back().answers.size(); ++k) {
      const std::string& name = p.parts.back().answers[k].name;
      if (!answer_names.insert(name).second) {
        r.fail(answers.get(k), f + ".answers[" + std::to_string(k) + "]",
               "answer name '" + name + "' is used twice; give one a name of its own "
               "({ name = \"...\", quantity = \"" + p.parts.back().answers[k].quantity + "\" })");
      }
    }
  }
  if (p.parts.empty()) r.fail(&root, "parts", "a problem needs at least one part");
  p.field_lines = field_lines_of(root);
  return p;
}
}  // namespace

std::filesystem::path problems_dir() { return data_folder("problems"); }

Problem find_problem(const std::string& id_or_file, const SolverSchemas& schemas) {
  const auto file = resolve_id_or_file(id_or_file, problems_dir(), "problem");
  Problem p = load_problem(file, schemas);
  p.from_catalog = file.string() != id_or_file;  // named by its id
  return p;
}

std::vector<Problem> load_catalog(const SolverSchemas& schemas) {
  std::vector<Problem> out;
  for (const auto& f : toml_files_in(problems_dir(), "problem")) {
    out.push_back(load_problem(f, schemas));
    out.back().from_catalog = true;
    check_id_is_file_name(out.back().id, f);
  }
  return out;
}

}  // namespace wobble
