#include "solvers/inertia_body.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "core/shapes.hpp"
#include "core/validity.hpp"
#include "symbolic/canonical_print.hpp"
#include "symbolic/quantity.hpp"
#include "symbolic/shape_integrals.hpp"

namespace wobble {

namespace {
// Parses and evaluates expressions of the body; failures are ExpressionErrors naming `field`.
// Each quantity may carry a unit of its own ("200 g", "4 cm", "2.5 g cm^2"), converted exactly
// (symbolic/quantity.hpp): the key stays exact.
struct Evaluator {
  const sym::SymbolTable& table;
  GiNaC::lst at;

  GiNaC::ex parse(const std::string& text, const std::string& field,
                  const std::string& si_unit) const {
    return sym::parse_quantity(table, text, field, si_unit);
  }
  double value(const GiNaC::ex& e, const std::string& field) const {
    return sym::evaluate(e, at, field);
  }
  double positive(const GiNaC::ex& e, const std::string& text, const std::string& field) const {
    const double v = value(e, field);
    if (!(v > 0.0)) {
      throw InputError(fmt::format(
          "{}: \"{}\" is {:.10g} at these parameter values; it must be > 0", field, text, v));
    }
    return v;
  }
  // A position (m).
  sym::SymVec3 vec(const std::array<std::string, 3>& text, const std::string& field,
                   Vec3& numeric) const {
    sym::SymVec3 out;
    for (std::size_t i = 0; i < 3; ++i) {
      const std::string f = field + "[" + std::to_string(i) + "]";
      out[i] = parse(text[i], f, "m");
      numeric[static_cast<Eigen::Index>(i)] = value(out[i], f);
    }
    return out;
  }
};

std::string vec_text(const sym::SymVec3& v, const sym::SymbolTable& t) {
  std::string s = "(";  // appended piece by piece: GCC 12 -Wrestrict false positive on "a" + s
  s += sym::to_text(v[0], t);
  s += ", ";
  s += sym::to_text(v[1], t);
  s += ", ";
  s += sym::to_text(v[2], t);
  return s + ")";
}
std::string vec_latex(const sym::SymVec3& v, const sym::SymbolTable& t) {
  return "\\left(" + sym::to_latex(v[0], t) + ", " + sym::to_latex(v[1], t) + ", " +
         sym::to_latex(v[2], t) + "\\right)";
}

void add_point_masses(const Problem& problem, const Evaluator& ev, InertiaBody& body,
                      std::vector<sym::SymMassProperties>& exact_parts,
                      std::vector<MassProperties>& numeric_parts) {
  const auto& masses = problem.body.masses;
  std::vector<Vec3> positions;
  std::vector<sym::SymPointMass> exact;
  std::vector<PointMass> numeric;
  for (std::size_t i = 0; i < masses.size(); ++i) {
    const std::string f = "body.masses[" + std::to_string(i) + "]";
    const GiNaC::ex m = ev.parse(masses[i].mass, f + ".mass", "kg");
    const double m_kg = ev.positive(m, masses[i].mass, f + ".mass");
    Vec3 r;
    const sym::SymVec3 r_exact = ev.vec(masses[i].at, f + ".at", r);
    for (std::size_t j = 0; j < positions.size(); ++j) {
      // Coinciding within rounding of the positions' own size: the same point.
      // (stableNorm: at positions of 1e-200 m the squares underflow and every pair "coincides".)
      const double scale = std::max({r.stableNorm(), positions[j].stableNorm(), 1e-300});
      constexpr double kSamePointUlps = 8;  // a few roundings of each coordinate
      if ((r - positions[j]).stableNorm() <=
          kSamePointUlps * std::numeric_limits<double>::epsilon() * scale) {
        throw InputError(fmt::format(
            "{}.at: coincides with body.masses[{}].at (both at ({:.6g}, {:.6g}, {:.6g}) m)", f, j,
            r.x(), r.y(), r.z()));
      }
    }
    positions.push_back(r);
    exact.push_back({m, r_exact});
    numeric.push_back({m_kg, r});
  }
  if (masses.empty()) return;
  exact_parts.push_back(sym::mass_properties(exact));
  numeric_parts.push_back(mass_properties(numeric));
  const auto& t = ev.table;
  std::string text = "Point masses:";
  std::string latex = "\\begin{array}{ll}";
  for (const auto& p : exact) {
    text += ' ';
    text += sym::to_text(p.mass, t);
    text += " at ";
    text += vec_text(p.r_O, t);
    text += ';';
    latex += sym::to_latex(p.mass, t) + " & \\text{at } " + vec_latex(p.r_O, t) + "\\\\ ";
  }
  text.pop_back();
  latex += "\\end{array}";
  body.steps.push_back({text, latex, "Point masses:"});
  body.steps.push_back(
      {"Each mass contributes m (|r|^2 δ_ij − r_i r_j): I_xx = Σ m (y² + z²), I_xy = −Σ m x y, "
       "and cyclically.",
       "I_{ij} = \\sum_p m_p\\left(|r_p|^2\\delta_{ij} - r_{p,i}\\,r_{p,j}\\right)",
       "Each mass contributes to the tensor:"});
}

// How a shape lies in its frame, as the step's label says it (shapes.hpp's table): "edges along
// x, y, z" for a box, "axis along z" for a cone; "" for a ball, which lies any way.
std::string placement_words(ShapeKind kind) {
  switch (kind) {
    case ShapeKind::box:
      return " with its edges along x, y, z";
    case ShapeKind::plate:
      return " with its edges along x and y";
    case ShapeKind::rod:
      return " along z";
    case ShapeKind::disc:
    case ShapeKind::cylinder:
    case ShapeKind::cone:
    case ShapeKind::ring:
      return " with its axis along z";
    case ShapeKind::sphere:
    case ShapeKind::shell:
      return "";
  }
  return "";
}

void add_shapes(const Problem& problem, const Evaluator& ev, InertiaBody& body,
                std::vector<sym::SymMassProperties>& exact_parts,
                std::vector<MassProperties>& numeric_parts) {
  const auto& t = ev.table;
  for (std::size_t i = 0; i < problem.body.shapes.size(); ++i) {
    const auto& s = problem.body.shapes[i];
    const std::string f = "body.shapes[" + std::to_string(i) + "]";
    ShapeKind kind{};
    try {
      kind = shape_kind_from_name(s.shape);
    } catch (const std::invalid_argument& e) {
      throw InputError(f + ".shape: " + e.what());
    }
    const auto& size_names = shape_size_names(kind);
    if (s.sizes.size() != size_names.size()) {
      throw InputError(fmt::format("{}.sizes: a {} takes {} sizes ({}), got {}", f, s.shape,
                                   size_names.size(), fmt::join(size_names, ", "), s.sizes.size()));
    }
    const GiNaC::ex m = ev.parse(s.mass, f + ".mass", "kg");
    const double m_kg = ev.positive(m, s.mass, f + ".mass");
    std::vector<GiNaC::ex> sizes;
    std::vector<double> sizes_m;
    for (std::size_t k = 0; k < s.sizes.size(); ++k) {
      const std::string sf = f + ".sizes[" + std::to_string(k) + "]";
      sizes.push_back(ev.parse(s.sizes[k], sf, "m"));
      sizes_m.push_back(ev.positive(sizes.back(), s.sizes[k], sf));
    }
    Vec3 c;
    const sym::SymVec3 c_exact = ev.vec(s.center, f + ".center", c);
    const auto derivation = sym::derive_shape_inertia(kind, m, sizes);
    exact_parts.push_back(sym::placed(m, derivation.I_cm, c_exact));
    MassProperties numeric;
    numeric.mass_kg = m_kg;
    numeric.r_cm_m = c;
    numeric.I_O = shift_from_cm(shape_inertia_about_cm(kind, m_kg, sizes_m), m_kg, c);
    numeric_parts.push_back(numeric);

    // "sides a, b, c" or "sides a = 2*L, b = L, c = L": a size the problem names as the shape
    // does is not written again ("M = M" said nothing).
    std::string size_text;
    const auto named = [&](const std::string& name, const GiNaC::ex& value) {
      return sym::to_text(value, t) == name ? name : name + " = " + sym::to_latex(value, t);
    };
    std::string size_latex = named("M", m);
    for (std::size_t k = 0; k < sizes.size(); ++k) {
      const std::string value = sym::to_text(sizes[k], t);
      size_text += (k ? ", " : "") + size_names[k] + (value == size_names[k] ? "" : " = " + value);
      size_latex += ",\\quad " + named(size_names[k], sizes[k]);
    }
    size_latex += ",\\quad \\text{centre } " + vec_latex(c_exact, t);
    body.steps.push_back(
        {fmt::format("A uniform {} of mass {} (sizes {}), centre at {}; axes along x, "
                     "y, z. Second moments S_ii = ∫ x_i² dm about its centre:",
                     s.shape, sym::to_text(m, t), size_text, vec_text(c_exact, t)),
         size_latex,
         fmt::format("A uniform {}{}; its mass, sizes and centre (the second moments S_ii = "
                     "∫ x_i² dm about the centre follow):",
                     s.shape, placement_words(kind))});
    for (const auto& st : derivation.steps) body.steps.push_back({st.text, st.latex});
    const GiNaC::matrix Ic = sym::normalized(derivation.I_cm);
    body.steps.push_back({"About its centre: I_cm = diag(" + sym::to_text(Ic(0, 0), t) + ", " +
                              sym::to_text(Ic(1, 1), t) + ", " + sym::to_text(Ic(2, 2), t) + ")",
                          "I_{\\mathrm{cm}} = \\operatorname{diag}\\left(" +
                              sym::to_latex(Ic(0, 0), t) + ", " + sym::to_latex(Ic(1, 1), t) +
                              ", " + sym::to_latex(Ic(2, 2), t) + "\\right)",
                          "About its centre:"});
    body.steps.push_back(
        {"Parallel-axis theorem to the origin: I_O = I_cm + M (|d|² 1 − d dᵀ), d = " +
             vec_text(c_exact, t),
         "I_O = I_{\\mathrm{cm}} + M\\left(|d|^2\\,\\mathbf{1} - d\\,d^{T}\\right),\\quad d = " +
             vec_latex(c_exact, t),
         "Parallel-axis theorem to the origin:"});
  }
}

void set_tensor(const Problem& problem, const Evaluator& ev, InertiaBody& body) {
  const auto& rows = *problem.body.tensor;
  body.has_mass = false;
  Mat3 numeric;
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = 0; j < 3; ++j) {
      const std::string f = fmt::format("body.tensor[{}][{}]", i, j);
      body.exact.I_O(i, j) = GiNaC::normal(ev.parse(rows[i][j], f, "kg m^2"));
      numeric(i, j) = ev.value(body.exact.I_O(i, j), f);
    }
  }
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = i + 1; j < 3; ++j) {
      if (!sym::is_identically_zero(body.exact.I_O(i, j) - body.exact.I_O(j, i))) {
        throw InputError(
            fmt::format("body.tensor: not symmetric: [{}][{}] = \"{}\" but [{}][{}] = "
                        "\"{}\"",
                        i, j, rows[i][j], j, i, rows[j][i]));
      }
    }
  }
  try {
    check_inertia_tensor(numeric);
  } catch (const InvalidInertiaTensor& e) {
    throw InputError(std::string("body.tensor: ") + e.what());
  }
  body.numeric.I_O = numeric;
  body.steps.push_back({"The tensor is given.", ""});
}
}  // namespace

InertiaBody build_inertia_body(const Problem& problem, const sym::SymbolTable& table,
                               const sym::Values& values) {
  const Evaluator ev{table, sym::substitution(table, values)};
  InertiaBody body;
  if (problem.body.tensor) {
    set_tensor(problem, ev, body);
    return body;
  }
  std::vector<sym::SymMassProperties> exact_parts;
  std::vector<MassProperties> numeric_parts;
  add_point_masses(problem, ev, body, exact_parts, numeric_parts);
  add_shapes(problem, ev, body, exact_parts, numeric_parts);
  body.exact = exact_parts.size() == 1 ? exact_parts[0] : sym::combine(exact_parts);
  body.numeric = combine(numeric_parts);
  return body;
}

void require_rotating_body(const std::string& file, const Vec3& moments_kgm2,
                           const std::string& who) {
  const double largest = moments_kgm2.cwiseAbs().maxCoeff();
  const double smallest = moments_kgm2.minCoeff();
  // Rounding leaves a rod's zero moment at ~eps times the others: a few dozen eps at most.
  constexpr double kZeroMomentUlps = 64;
  if (smallest > kZeroMomentUlps * std::numeric_limits<double>::epsilon() * largest) return;
  const std::string what =
      largest > 0.0
          ? fmt::format("a rod, all its mass on one line, or as thin as one to double precision "
                        "(a pivot far away): its smallest moment, {:.3g} kg m^2, is 0 within the "
                        "rounding of the largest, {:.3g} kg m^2",
                        smallest, largest)
                    : std::string("a point: all its mass is at one point, so every moment is 0");
  throw InputError(fmt::format("{}: body: {} needs a body that can spin about every axis; this "
                               "one is {}",
                               file, who, what));
}

}  // namespace wobble
