#pragma once
/// @file
/// Which answer of a part a student's answer is meant for, where the part has several and the
/// student named none: "wobble check asymmetric-top a 'euler_coefficients = [..]'" names it in
/// its label; "wobble check box-corner b 2.5 kg m^2" is right for one moment only.
#include <string>

#include "check/judge.hpp"

namespace wobble::check {

/// The name of the answer of part `part_id` that `text` is meant for: the one its label names
/// (the left of its first '=' or ':', spelt as name_in_key reads names), else the only one it
/// is judged right for. "" where the part has one answer or none, where no such part exists,
/// or where neither decides (no label of an answer, right for none or for several): the
/// caller's lookup then asks for a name.
std::string answer_meant(const Context& ctx, const std::string& part_id, const std::string& text,
                         const Options& options);

}  // namespace wobble::check
