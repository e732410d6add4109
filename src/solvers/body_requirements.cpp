#include "solvers/body_requirements.hpp"

#include <fmt/format.h>

#include "symbolic/canonical_print.hpp"

namespace wobble {

namespace {
std::string file_of(const BodyContext& b) { return b.problem.file.string(); }

std::string instead_text(const std::string& instead) {
  return instead.empty() ? "" : "; such a body needs solver = \"" + instead + "\"";
}
}  // namespace

GiNaC::matrix tensor_about_centre(const BodyContext& b) {
  const auto& e = b.body.exact;
  if (!b.body.has_mass) return sym::normalized(e.I_O);
  return sym::normalized(e.I_O.sub(sym::parallel_axis_term(e.mass, e.r_cm)));
}

void require_mass(const BodyContext& b, const std::string& who) {
  if (!b.body.has_mass) {
    throw InputError(fmt::format(
        "{}: body: {} needs masses or shapes (a mass and its centre), not a tensor given",
        file_of(b), who));
  }
}

void require_principal_axes_along_xyz(const BodyContext& b, const GiNaC::matrix& I,
                                      const std::string& who, const std::string& about,
                                      const std::string& instead) {
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = i + 1; j < 3; ++j) {
      if (sym::is_identically_zero(I(i, j))) continue;
      throw InputError(fmt::format(
          "{}: body: {} needs the principal axes along x, y, z {}, but I_{}{} = {}{}",
          file_of(b), who, about, "xyz"[i], "xyz"[j], sym::to_text(I(i, j), b.table),
          instead_text(instead)));
    }
  }
}

void require_symmetric_about_z(const BodyContext& b, const GiNaC::matrix& I,
                               const std::string& who, const std::string& about,
                               const std::string& instead) {
  require_principal_axes_along_xyz(b, I, who, about, instead);
  if (sym::is_identically_zero(I(0, 0) - I(1, 1))) return;
  throw InputError(fmt::format(
      "{}: body: {} needs a body symmetric about z, but {} I_xx = {} and I_yy = {}{}",
      file_of(b), who, about, sym::to_text(I(0, 0), b.table), sym::to_text(I(1, 1), b.table),
      instead_text(instead)));
}

void require_centre_on_z(const BodyContext& b, const std::string& who) {
  for (unsigned i = 0; i < 2; ++i) {
    if (sym::is_identically_zero(b.body.exact.r_cm[i])) continue;
    throw InputError(fmt::format(
        "{}: body: {} needs the centre of mass on the z axis, but its {} is {}", file_of(b), who,
        "xy"[i], sym::to_text(b.body.exact.r_cm[i], b.table)));
  }
}

}  // namespace wobble
