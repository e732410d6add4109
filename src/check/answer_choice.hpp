#pragma once
/// @file
/// Which answer of a part a student's answer is meant for, where the part has several and the
/// student named none: "wobble check asymmetric-top a 'euler_coefficients = [..]'" names it in
/// its label; "wobble check box-corner b 2.5 kg m^2" is right for one moment only.
#include <string>

#include "check/judge.hpp"

namespace wobble::check {

/// The name of the answer of part `part_id` that `text` is meant for: the one its label names
/// (the left of its first '=' or ':', spelt as name_in_key reads names), else for Euler's
/// equations written out the one whose entries are c₁, c₂, c₃ (right or wrong: the equations
/// say what they are), else the only one it is judged right for, else (right for none) the only
/// one it reads as a value of: its shape, and its dimension where it has a unit. "" where the
/// part has one answer or none, where no such part exists, or where none of these decides (right
/// for several, or for none and a value of several): the caller's lookup then asks for a name.
std::string answer_meant(const Context& ctx, const std::string& part_id, const std::string& text,
                         const Options& options);

/// The answer Euler's equations written out are meant for where a line names neither part nor
/// answer ("dω₁/dt = -0.5 ω₂ω₃, dω₂/dt = .."; the label of one equation names none): the key's
/// only answer whose entries are c₁, c₂, c₃. "" where `text` is no such equations or no one
/// answer is of them.
std::string euler_equations_answer(const Context& ctx, const std::string& text);

/// The answer `text` is to be judged as: find_answer's, with the part and the name read as
/// name_in_key reads them ("I₀", "I_0"), and for a part of several answers with no name, the one
/// answer_meant finds. `part_field` and `name_field` name them in a refusal.
/// @throws AnswerNotFound, InputError as find_answer does, and AnswerNotFound where such a part's
/// answer is labelled with a plain word that names none of its answers ("part: part d has no
/// answer 'phidot' (answers: phidot_slow, phidot_fast)").
const Answer& answer_for(const Context& ctx, const std::string& part, const std::string& name,
                         const std::string& text, const Options& options,
                         const std::string& part_field, const std::string& name_field);

}  // namespace wobble::check
