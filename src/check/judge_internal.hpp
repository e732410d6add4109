#pragma once
/// @file
/// What the two halves of the judge share, inside the check layer only: judge.cpp reads an
/// answer and judges a number, a vector or a matrix by its values; expression_judge.cpp judges
/// an answer in the symbols as a function of the parameters. Both hold values to the same
/// tolerances (Judge) and say why a value is wrong the same way (diagnose).
#include <optional>
#include <string>
#include <vector>

#include "check/answer_reading.hpp"
#include "check/axes_judge.hpp"
#include "check/judge.hpp"
#include "symbolic/units.hpp"

namespace wobble::check::detail {

/// The option an answer is given by, as refusals name it.
inline const std::string kField = "--answer";

/// One answer's judging: its tolerance, the scale of its zeros, where its axes stand.
struct Judge {
  const Context& ctx;
  const Answer& a;
  const Options& opt;
  double scale;
  AxesLayout layout = AxesLayout::rows_or_columns;  // where principal axes are in the matrix

  bool close(double v, double k) const {
    if (opt.sigfigs) {
      const double ref = k != 0.0 ? std::abs(k) : scale;
      const double place = std::pow(10.0, std::floor(std::log10(ref)) - *opt.sigfigs + 1);
      return std::abs(v - k) <= 0.5 * place * (1 + kHalfUnitSlack);
    }
    return std::abs(v - k) <= opt.rel_tol * (k != 0.0 ? std::abs(k) : scale);
  }
  // For directions (principal axes): the sine of the angle an axis may be off, from the
  // relative tolerance or half a unit in the last of N significant figures.
  double angle_tolerance() const {
    return opt.sigfigs ? 0.5 * std::pow(10.0, 1 - *opt.sigfigs) : opt.rel_tol;
  }
  bool all_close(const std::vector<double>& v, const std::vector<double>& k) const {
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (!close(v[i], k[i])) return false;
    }
    return true;
  }
};

/// Principal axes by meaning (axes_judge.hpp): the sine of the angle within the tolerance.
Verdict judge_axes_answer(const Judge& j, const std::vector<double>& got);

/// Euler angles are the same up to whole turns (angles_up_to_turns, judge.hpp): ψ = 340° is
/// the key's ψ = −20°.
/// Whether `got` is right with some entries whole turns off the key's, and the names of those
/// entries ("ψ"); never where `a` is no vector of angles. For the diagnosis, `got` with each
/// entry that is right whole turns off taken as the key's, and each other one turn off moved to
/// the key's range (ψ = 340.5° is off by 0.5°, not "-17 times its right value"), where every
/// entry then lies within a quarter turn of the key's; otherwise as typed (130 for 130° read as
/// radians, 1000 times the angles).
struct OnKeysTurns {
  bool right = false;
  std::vector<std::string> moved;
  std::vector<double> for_diagnosis;
};
OnKeysTurns on_keys_turns(const Judge& j, const std::vector<double>& got);

/// " (ψ differs from the key's by whole turns: the same angle)", for the entries `moved`.
std::string whole_turns_note(const std::vector<std::string>& moved);

/// Proper Euler angles (the first and the last turn about one axis, as every vector of angles
/// in the catalog is) on the other branch: "(220°, −30°, 250°)" for the key's (40°, 30°, 70°)
/// is the same rotation, R_z(φ + π) R_y(−θ) R_z(ψ + π) = R_z(φ) R_y(θ) R_z(ψ), but wrong in the
/// key's convention (θ = arccos R₃₃, in [0, π]). The line that says so; nullopt where `got`
/// (radians) is not so, up to whole turns, or `a` is no vector of angles.
std::optional<std::string> other_branch(const Judge& j, const std::vector<double>& got);

/// Why values `v` are not the key's `k` (diagnosis.hpp), each line one finding.
std::vector<std::string> diagnose(const Judge& j, const Unit& key_unit,
                                  const std::vector<double>& v, const std::vector<double>& k);

/// "cos(30)" for cos 30°: where a numeric answer calls a function and reading some of its
/// numbers in degrees makes its values the key's (to j's tolerance, after `to_key`, the factor
/// of its unit), the line that says which; nullopt otherwise. (Without a function, a number in
/// degrees is the diagnosis's "this is the angle in degrees".)
std::optional<std::string> degrees_in_numbers(const Judge& j, const std::string& typed,
                                              double to_key);

/// An answer in the symbols (`p` as read from `typed`): proved equal to the key's closed form,
/// or judged at the set values and three more parameter points.
Verdict judge_symbolic(const Context& ctx, const Answer& a, const std::string& typed,
                       const ReadAnswer& p, const Options& opt, AxesLayout layout);

}  // namespace wobble::check::detail
