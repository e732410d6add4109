#include "symbolic/inertia_sym.hpp"

#include <cstddef>

#include "symbolic/expression.hpp"

namespace wobble::sym {

GiNaC::matrix normalized(const GiNaC::matrix& m) {
  GiNaC::matrix out(m.rows(), m.cols());
  for (unsigned i = 0; i < m.rows(); ++i) {
    for (unsigned j = 0; j < m.cols(); ++j) {
      // A symmetric tensor's entry below the diagonal is the one above, already simplified
      // (the three-atom molecule's product of inertia about its centre of mass took 0.4 ms).
      const bool mirrored = j < i && j < m.rows() && i < m.cols() && m(i, j).is_equal(m(j, i));
      out(i, j) = mirrored ? out(j, i) : simplify(m(i, j));
    }
  }
  return out;
}

GiNaC::matrix parallel_axis_term(const GiNaC::ex& mass, const SymVec3& d) {
  const GiNaC::ex d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  GiNaC::matrix out(3, 3);
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = 0; j < 3; ++j) out(i, j) = mass * ((i == j ? d2 : 0) - d[i] * d[j]);
  }
  return out;
}

SymMassProperties mass_properties(const std::vector<SymPointMass>& masses) {
  std::vector<SymMassProperties> parts;
  for (const auto& p : masses) parts.push_back(placed(p.mass, GiNaC::matrix(3, 3), p.r_O));
  return combine(parts);
}

SymMassProperties placed(const GiNaC::ex& mass, const GiNaC::matrix& I_cm, const SymVec3& r_cm) {
  SymMassProperties out;
  out.mass = mass;
  out.r_cm = r_cm;
  out.I_O = normalized(I_cm.add(parallel_axis_term(mass, r_cm)));
  return out;
}

SymMassProperties combine(const std::vector<SymMassProperties>& parts) {
  SymMassProperties total;
  SymVec3 first{0, 0, 0};
  GiNaC::matrix I(3, 3);
  for (const auto& p : parts) {
    total.mass += p.mass;
    for (std::size_t i = 0; i < 3; ++i) first[i] += p.mass * p.r_cm[i];
    I = I.add(p.I_O);
  }
  total.mass = simplify(total.mass);
  for (std::size_t i = 0; i < 3; ++i) total.r_cm[i] = simplify(first[i] / total.mass);
  total.I_O = normalized(I);
  return total;
}

}  // namespace wobble::sym
