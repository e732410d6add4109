#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "io/data_dir.hpp"
#include "problem/scene.hpp"
#include "problem/toml_reader.hpp"

namespace wobble {

std::string scene_tolerance_range() {
  // Printed as their exponents: the limits are powers of ten.
  return fmt::format("1e{} to 1e{}", std::lround(std::log10(kMinSceneTolerance)),
                     std::lround(std::log10(kMaxSceneTolerance)));
}

std::string scene_samples_range() { return fmt::format("{} to {}", kMinSamples, kMaxSamples); }

namespace {
using detail::Reader;

Frame read_frame(const Reader& r, const toml::table& t, const std::string& key,
                 const std::string& field) {
  const std::string f = r.string(t, key, field, false, "body");
  if (f == "body") return Frame::body;
  if (f == "space") return Frame::space;
  r.fail(t.get(key), field + key, "'" + f + "' is not a frame (expected body or space)");
}

void read_initial(const Reader& r, const toml::table& root, Scene& s) {
  const toml::node* n = root.get("initial");
  if (n == nullptr || !n->is_table()) r.fail(&root, "initial", "missing (a table)");
  const toml::table& t = *n->as_table();
  r.only_keys(t, "initial",
              {"omega", "omega_frame", "quaternion", "matrix", "euler", "euler_convention"});
  s.omega = r.vector3(t.get("omega"), "initial.omega", &t);
  s.omega_frame = read_frame(r, t, "omega_frame", "initial.");
  OrientationSpec& o = s.orientation;
  int given = 0;
  if (const toml::node* q = t.get("quaternion")) {
    ++given;
    const toml::array* a = q->as_array();
    if (a == nullptr || a->size() != 4)
      r.wrong(q, "initial.quaternion", "4 expressions (w, x, y, z)");
    for (std::size_t i = 0; i < 4; ++i)
      o.quaternion[i] = r.expression(a->get(i), "initial.quaternion[" + std::to_string(i) + "]", q);
    o.kind = OrientationSpec::Kind::quaternion;
  }
  if (const toml::node* m = t.get("matrix")) {
    ++given;
    const toml::array* a = m->as_array();
    if (a == nullptr || a->size() != 3) r.wrong(m, "initial.matrix", "3 rows of 3");
    for (std::size_t i = 0; i < 3; ++i)
      o.matrix[i] = r.vector3(a->get(i), "initial.matrix[" + std::to_string(i) + "]", m);
    o.kind = OrientationSpec::Kind::matrix;
  }
  if (const toml::node* e = t.get("euler")) {
    ++given;
    o.euler = r.vector3(e, "initial.euler", &t);
    o.kind = OrientationSpec::Kind::euler;
  }
  o.convention = r.string(t, "euler_convention", "initial.", false, "zyz");
  if (o.convention != "zyz" && o.convention != "zxz") {
    r.fail(t.get("euler_convention"), "initial.euler_convention",
           "'" + o.convention + "' is not a convention (expected zyz or zxz)");
  }
  if (given > 1) {
    r.fail(&t, "initial", "give the orientation once: quaternion, matrix or euler, not several");
  }
}

void read_effects(const Reader& r, const toml::table& root, Scene& s) {
  const toml::node* n = root.get("effects");
  if (n == nullptr) return;  // none: torque-free
  const toml::table* t = n->as_table();
  if (t == nullptr) r.wrong(n, "effects", "a table of effects");
  for (auto&& [key, node] : *t) {
    const std::string name(key.str());
    const std::string f = "effects." + name;
    const toml::table* e = node.as_table();
    if (name != "gravity" && name != "free_flight" && name != "torque") {
      r.fail(&node, f, "unknown effect (expected gravity, free_flight or torque)");
    }
    if (e == nullptr) r.wrong(&node, f, "a table");
    if (name == "gravity") {
      r.only_keys(*e, f, {"g", "pivot"});
      GravitySpec g;
      if (e->get("g")) g.g = r.expression(e->get("g"), f + ".g", e);
      // Gravity alone turns no body about its centre of mass: the scene is about a fixed point.
      if (e->get("pivot") == nullptr)
        r.fail(e, f + ".pivot",
               "missing: the fixed point the body turns about, in the body frame in m (pivot = "
               "[0, 0, 0], a top's axle end at the origin); a body thrown under gravity is "
               "free_flight");
      g.pivot = r.vector3(e->get("pivot"), f + ".pivot", e);
      s.gravity = g;
    } else if (name == "free_flight") {
      r.only_keys(*e, f, {"g", "position", "velocity"});
      FreeFlightSpec ff;
      if (e->get("g")) ff.g = r.expression(e->get("g"), f + ".g", e);
      if (e->get("position")) ff.position = r.vector3(e->get("position"), f + ".position", e);
      if (e->get("velocity")) ff.velocity = r.vector3(e->get("velocity"), f + ".velocity", e);
      s.free_flight = ff;
    } else {
      r.only_keys(*e, f, {"value", "frame", "brake"});
      // Fixed in the body or in space: two motions, and neither is the obvious default.
      if (e->get("frame") == nullptr)
        r.fail(e, f + ".frame",
               "missing: say whether the torque turns with the body (frame = \"body\") or "
               "stays fixed in space (frame = \"space\")");
      s.torque = TorqueSpec{r.vector3(e->get("value"), f + ".value", e),
                            read_frame(r, *e, "frame", f + "."), false};
      if (const toml::node* b = e->get("brake")) {
        if (!b->is_boolean()) r.fail(b, f + ".brake", "must be true or false");
        s.torque->brake = b->as_boolean()->get();
        if (s.torque->brake && s.torque->frame != Frame::body) {
          r.fail(b, f + ".brake", "a brake is fixed in the body: give frame = \"body\"");
        }
      }
    }
  }
  if (s.gravity && s.free_flight) {
    r.fail(n, "effects", "gravity (about a fixed pivot) and free_flight exclude each other");
  }
}

void read_run(const Reader& r, const toml::table& root, Scene& s) {
  const toml::node* n = root.get("run");
  if (n == nullptr || !n->is_table()) r.fail(&root, "run", "missing (a table)");
  const toml::table& t = *n->as_table();
  r.only_keys(t, "run", {"t_end", "samples", "tolerance", "method", "step", "outputs"});
  s.t_end = r.expression(t.get("t_end"), "run.t_end", &t);
  if (const toml::node* k = t.get("samples")) {
    const auto v = k->value<int64_t>();
    if (!k->is_integer() || !v || *v < kMinSamples || *v > kMaxSamples)
      r.wrong(k, "run.samples", "a whole number from " + scene_samples_range());
    s.samples = static_cast<int>(*v);
  }
  if (const toml::node* k = t.get("tolerance")) {
    const auto v = k->value<double>();
    if (!v || !(*v >= kMinSceneTolerance && *v <= kMaxSceneTolerance))
      r.wrong(k, "run.tolerance", "a number from " + scene_tolerance_range());
    s.tolerance = *v;
  }
  s.method = r.string(t, "method", "run.", false, "auto");
  if (t.get("step")) s.step = r.expression(t.get("step"), "run.step", &t);
  const toml::array& outs = r.array(t, "outputs", "run.outputs");
  if (outs.empty()) r.fail(&t, "run.outputs", "list at least one output");
  for (std::size_t i = 0; i < outs.size(); ++i) {
    const std::string f = "run.outputs[" + std::to_string(i) + "]";
    const toml::node* o = outs.get(i);
    if (!o->is_string()) r.wrong(o, f, "an output name");
    const std::string name = *o->value<std::string>();
    const auto& known = scene_output_names();
    if (std::none_of(known.begin(), known.end(), [&](const auto& k) { return k.first == name; })) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k.first;
      r.fail(o, f, "unknown output '" + name + "' (expected one of: " + list + ")");
    }
    if (std::find(s.outputs.begin(), s.outputs.end(), name) != s.outputs.end())
      r.fail(o, f, "output '" + name + "' listed twice");
    s.outputs.push_back(name);
  }
}
}  // namespace

const std::vector<std::pair<std::string, std::string>>& scene_output_names() {
  static const std::vector<std::pair<std::string, std::string>> names{
      {"omega_body", "angular velocity, body frame, rad/s"},
      {"omega_space", "angular velocity, space frame, rad/s"},
      {"L_body", "angular momentum about the turning point, body frame, kg m^2/s"},
      {"L_space", "angular momentum about the turning point, space frame, kg m^2/s"},
      {"e1_space", "principal axis e1 (least moment) in space"},
      {"e2_space", "principal axis e2 in space"},
      {"e3_space", "principal axis e3 (largest moment) in space"},
      {"euler_zyz", "Euler angles phi, theta, psi, z-y-z (Taylor), rad"},
      {"euler_zxz", "Euler angles phi, theta, psi, z-x-z (Goldstein), rad"},
      {"kinetic_energy", "rotational kinetic energy (+ translational in free flight), J"},
      {"total_energy", "kinetic + potential energy, J"},
      {"invariant_errors", "deviation of each conserved quantity from its value at t = 0"},
      {"com_position", "centre of mass in space, m"},
  };
  return names;
}

namespace {
Scene load_scene_table(const toml::table& root, const std::filesystem::path& file) {
  Reader r(file);
  r.only_keys(root, "",
              {"id", "title", "description", "parameters", "body", "initial", "effects", "run"});
  Scene s;
  Problem& p = s.model;
  p.file = file;
  p.solver = "scene";
  p.id = r.string(root, "id", "");
  p.title = r.words(root, "title", "");
  p.statement = r.prose(root, "description", "", false, "");
  if (root.get("parameters")) p.parameters = detail::read_parameters(r, root);
  const toml::node* body = root.get("body");
  if (body == nullptr || !body->is_table()) r.fail(&root, "body", "missing (a table)");
  p.body = detail::read_body(r, *body->as_table());
  read_initial(r, root, s);
  read_effects(r, root, s);
  read_run(r, root, s);
  p.field_lines = detail::field_lines_of(root);
  return s;
}
}  // namespace

Scene load_scene(const std::filesystem::path& file) {
  return load_scene_table(detail::parse_toml_file(file, "scene"), file);
}

Scene load_scene_text(const std::string& text, const std::filesystem::path& name) {
  return load_scene_table(detail::parse_toml_text(text, name, "scene"), name);
}

std::filesystem::path scenes_dir() { return data_folder("scenes"); }

std::vector<Scene> load_scenes() {
  std::vector<Scene> out;
  for (const auto& f : detail::toml_files_in(scenes_dir(), "scene")) {
    out.push_back(load_scene(f));
    out.back().model.from_catalog = true;
    detail::check_id_is_file_name(out.back().model.id, f);
  }
  return out;
}

Scene find_scene(const std::string& id_or_file) {
  const auto file = detail::resolve_id_or_file(id_or_file, scenes_dir(), "scene");
  Scene s = load_scene(file);
  s.model.from_catalog = file.string() != id_or_file;  // named by its id
  return s;
}

}  // namespace wobble
