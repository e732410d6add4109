#include "symbolic/shape_integrals.hpp"

#include <stdexcept>

namespace wobble::sym {

namespace {
using GiNaC::ex;

ex integrate(const GiNaC::symbol& x, const ex& lo, const ex& hi, const ex& f) {
  return GiNaC::integral(x, lo, hi, f).eval_integ();
}

// Second moments (diagonal of S) of a uniform shape of the given mass.
std::array<ex, 3> second_moments(wobble::ShapeKind kind, const ex& M, const std::vector<ex>& s,
                                 std::vector<ShapeDerivation::Step>& steps) {
  const GiNaC::symbol x("x"), y("y"), z("z"), r("r");
  using K = wobble::ShapeKind;
  switch (kind) {
    case K::box: {
      auto over_box = [&](const ex& f) {
        return integrate(z, -s[2] / 2, s[2] / 2,
                         integrate(y, -s[1] / 2, s[1] / 2, integrate(x, -s[0] / 2, s[0] / 2, f)));
      };
      const ex rho = M / over_box(1);
      steps.push_back(
          {"S_xx = M/(abc) ∫∫∫ x² dz dy dx over −a/2..a/2, −b/2..b/2, −c/2..c/2; likewise S_yy, "
           "S_zz",
           "S_{xx} = \\frac{M}{abc}\\int_{-a/2}^{a/2}\\int_{-b/2}^{b/2}\\int_{-c/2}^{c/2} x^2\\,"
           "dz\\,dy\\,dx, \\text{ likewise } S_{yy}, S_{zz}"});
      return {rho * over_box(x * x), rho * over_box(y * y), rho * over_box(z * z)};
    }
    case K::plate: {
      auto over_plate = [&](const ex& f) {
        return integrate(y, -s[1] / 2, s[1] / 2, integrate(x, -s[0] / 2, s[0] / 2, f));
      };
      const ex sigma = M / over_plate(1);
      steps.push_back({"S_xx = M/(ab) ∫∫ x² dy dx over −a/2..a/2, −b/2..b/2; S_zz = 0 (thin)",
                       "S_{xx} = \\frac{M}{ab}\\int_{-a/2}^{a/2}\\int_{-b/2}^{b/2} x^2\\,dy\\,dx, "
                       "S_{zz} = 0 \\text{ (thin)}"});
      return {sigma * over_plate(x * x), sigma * over_plate(y * y), ex(0)};
    }
    case K::rod: {
      const ex lambda = M / integrate(z, -s[0] / 2, s[0] / 2, 1);
      steps.push_back({"S_zz = M/L ∫ z² dz over −L/2..L/2; S_xx = S_yy = 0",
                       "S_{zz} = \\frac{M}{L}\\int_{-L/2}^{L/2} z^2\\,dz, S_{xx} = S_{yy} = 0"});
      return {ex(0), ex(0), lambda * integrate(z, -s[0] / 2, s[0] / 2, z * z)};
    }
    case K::disc: {
      const ex ring = 2 * GiNaC::Pi * r;  // area of the ring of radius r per dr
      const ex sigma = M / integrate(r, 0, s[0], ring);
      const ex radial = sigma * integrate(r, 0, s[0], r * r * ring);
      steps.push_back(
          {"S_xx = S_yy = ½ ∫ r² dm = ½ M/(π R²) ∫ r² 2π r dr over 0..R; S_zz = 0 (thin)",
           "S_{xx} = S_{yy} = \\frac{1}{2}\\int r^2\\,dm = \\frac{1}{2}\\,\\frac{M}{\\pi R^2}"
           "\\int_0^R r^2\\,2\\pi r\\,dr, S_{zz} = 0 \\text{ (thin)}"});
      return {radial / 2, radial / 2, ex(0)};
    }
    case K::cylinder: {
      const ex shell = 2 * GiNaC::Pi * r;
      auto over = [&](const ex& f) {
        return integrate(z, -s[1] / 2, s[1] / 2, integrate(r, 0, s[0], f * shell));
      };
      const ex rho = M / over(1);
      steps.push_back(
          {"S_xx = S_yy = ½ M/(π R² h) ∫∫ r² 2π r dr dz over 0..R, −h/2..h/2; S_zz = M/(π R² h) ∫∫ "
           "z² 2π r dr dz",
           "S_{xx} = S_{yy} = \\frac{1}{2}\\,\\frac{M}{\\pi R^2 h}\\int_{-h/2}^{h/2}\\int_0^R "
           "r^2\\,2\\pi r\\,dr\\,dz, S_{zz} = \\frac{M}{\\pi R^2 h}\\int\\int z^2\\,2\\pi "
           "r\\,dr\\,dz"});
      return {rho * over(r * r) / 2, rho * over(r * r) / 2, rho * over(z * z)};
    }
    case K::sphere: {
      const ex shell = 4 * GiNaC::Pi * r * r;
      const ex rho = M / integrate(r, 0, s[0], shell);
      const ex each = rho * integrate(r, 0, s[0], r * r * shell) / 3;
      steps.push_back({"S_xx = S_yy = S_zz = ⅓ ∫ r² dm = ⅓ M/(4/3 π R³) ∫ r² 4π r² dr over 0..R",
                       "S_{xx} = S_{yy} = S_{zz} = \\frac{1}{3}\\int r^2\\,dm = \\frac{1}{3}\\,"
                       "\\frac{M}{\\frac{4}{3}\\pi R^3}\\int_0^R r^2\\,4\\pi r^2\\,dr"});
      return {each, each, each};
    }
    case K::cone: {
      // Apex up at z = 3h/4, base at z = -h/4 (the centre of mass at 0): radius R (3h/4 - z)/h.
      const ex top = 3 * s[1] / 4, bottom = -s[1] / 4;
      const ex radius = s[0] * (top - z) / s[1];
      const ex shell = 2 * GiNaC::Pi * r;
      auto over = [&](const ex& f) {
        return integrate(z, bottom, top, integrate(r, 0, radius, f * shell));
      };
      const ex rho = M / over(1);
      steps.push_back(
          {"Apex at z = 3h/4, base at z = −h/4, radius R (3h/4 − z)/h: S_xx = S_yy = ½ ρ ∫∫ r² 2π r "
           "dr dz, S_zz = ρ ∫∫ z² 2π r dr dz, ρ = M/(π R² h/3)",
           "S_{xx} = S_{yy} = \\frac{\\rho}{2}\\int_{-h/4}^{3h/4}\\int_0^{R(3h/4 - z)/h} "
           "r^2\\,2\\pi r\\,dr\\,dz,\\ S_{zz} = \\rho\\int\\int z^2\\,2\\pi r\\,dr\\,dz"});
      return {rho * over(r * r) / 2, rho * over(r * r) / 2, rho * over(z * z)};
    }
    case K::ring: {
      // All the mass at radius R in the x-y plane, dm = M/(2π R) ds along its length s; by
      // symmetry S_xx = S_yy = ½ ∫ (x² + y²) dm = ½ ∫ R² dm (GiNaC integrates polynomials only).
      const GiNaC::symbol arc("s");
      const ex lambda = M / integrate(arc, 0, 2 * GiNaC::Pi * s[0], 1);
      const ex radial = lambda * integrate(arc, 0, 2 * GiNaC::Pi * s[0], s[0] * s[0]);
      steps.push_back(
          {"S_xx = S_yy = ½ ∫ r² dm = ½ M/(2π R) ∫ R² ds over the length 0..2π R; "
           "S_zz = 0 (thin)",
           "S_{xx} = S_{yy} = \\frac{1}{2}\\int r^2\\,dm = \\frac{1}{2}\\,"
           "\\frac{M}{2\\pi R}\\int_0^{2\\pi R} R^2\\,ds, S_{zz} = 0 \\text{ (thin)}"});
      return {radial / 2, radial / 2, ex(0)};
    }
    case K::shell: {
      // All the mass at radius R. Between heights z and z + dz (z = R u) lies the area 2π R² du
      // whatever u (Archimedes), so dm = M/2 du; by symmetry S_xx = S_yy = S_zz.
      const GiNaC::symbol u("u");
      const ex band = 2 * GiNaC::Pi * s[0] * s[0];
      const ex sigma = M / integrate(u, -1, 1, band);
      const ex each = sigma * integrate(u, -1, 1, s[0] * s[0] * u * u * band);
      steps.push_back(
          {"S_zz = M/(4π R²) ∫ (R u)² 2π R² du over u = cos θ in −1..1; S_xx = S_yy = S_zz",
           "S_{zz} = \\frac{M}{4\\pi R^2}\\int_{-1}^{1} (R u)^2\\,2\\pi R^2\\,du,\\ u = "
           "\\cos\\theta;\\ S_{xx} = S_{yy} = S_{zz}"});
      return {each, each, each};
    }
  }
  throw std::logic_error("derive_shape_inertia: unhandled shape kind");
}
}  // namespace

ShapeDerivation derive_shape_inertia(wobble::ShapeKind kind, const GiNaC::ex& mass,
                                     const std::vector<GiNaC::ex>& sizes) {
  if (sizes.size() != wobble::shape_size_names(kind).size()) {
    throw std::invalid_argument("derive_shape_inertia: wrong number of sizes");
  }
  ShapeDerivation out;
  const auto S = second_moments(kind, mass, sizes, out.steps);
  const ex trace = S[0] + S[1] + S[2];
  for (unsigned i = 0; i < 3; ++i) out.I_cm(i, i) = GiNaC::normal(trace - S[i]);
  out.steps.push_back({"I = tr(S) 1 − S", "I = \\operatorname{tr}(S)\\,\\mathbf{1} - S"});
  return out;
}

}  // namespace wobble::sym
