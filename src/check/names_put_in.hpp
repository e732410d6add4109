#pragma once
/// @file
/// Names in an answer that are no symbols of the problem but that its key knows, read as what
/// they stand for, each with the line that says so: an earlier answer's name as its closed form
/// ("I₀ diag(1, 1, 2)", "π/Ω_space_rate", "R_zyzᵀ", "π/|Ω_space|"), a convention's names as the
/// parameters they are (PHY 711's Taylor φ, θ, ψ for its α, β, γ), and the names the key's steps
/// write as their exact forms (the heavy top's I₁, I₃, ω₃). Each reading starts from the reader's
/// refusal of the answer as typed (its message names the name it could not read), and each gives
/// the text to judge in its place; the judge (judge.cpp) judges it and adds the line.
#include <optional>
#include <string>

#include "check/judge.hpp"

namespace wobble::check::detail {

/// The name a reader's message quotes after `what` ("undefined symbol 'T'"), or "".
std::string quoted_after(const std::string& message, const std::string& what);
/// The name a reader's message says is undefined ("undefined symbol 'T'"), or "".
std::string undefined_name(const std::string& message);
/// undefined_name, or the text the reader took for a unit and refused: after a value it takes a
/// word for its unit ("ψ̇₀ I₃", "2 L0_body"), where a name may be meant.
std::string refused_name(const std::string& message);
/// The symbol the LaTeX reader's message says is none of the problem's, as drawn
/// ("\Omega_{space}"), or "".
std::string latex_unknown_symbol(const std::string& message);
/// The LaTeX reader's refusal `with` more names than the problem's symbols, listing those as its
/// refusal `without` them does ("Q is not one of this problem's symbols (M, R, ..)"); `with` as
/// it is where either names no symbol.
InputError problem_listed(const std::string& with, const std::string& without);
/// A name as the key's DefinedName spells it: "I_3" and "I3" alike, and "w3" as ω₃ ("omega3").
std::string defined_spelling(const std::string& word);
/// The part of `key` whose answers include the one named `name` (answer names are unique in a
/// key), or nullptr.
const PartKey* part_answering(const Key& key, const std::string& name);

/// The answer named `name` (or begun by it: Omega for Omega_body_rate) that `a` may be written
/// in terms of: one with a closed form, of a part before a's or of a's own, not `a` itself; or
/// nullptr.
const Answer* referable_answer(const Context& ctx, const Answer& a, const std::string& name);

/// An answer's text with forms put in for names (plain text the reader reads), and the line of
/// feedback that says which; `when_right` ends that line where the answer is judged right (": right
/// as far as your I3 is"), which a wrong one is not.
struct Referenced {
  std::string text, note, when_right;
};

/// `text` with another answer's name, the one the reader's `message` refused, written as the
/// key's closed form (a number's in brackets, a vector's or matrix's in its own, a vector's
/// magnitude in |..| or norm(..) as the root of its squares), and the line that says so; nullopt
/// where that name is no answer `a` may be written in terms of (of a part before a's or a's own,
/// not a itself), or the text does not spell it as a name of its own (LaTeX is left alone).
std::optional<Referenced> answer_referenced(const Context& ctx, const Answer& a,
                                            const std::string& text, const std::string& message);

/// `text` with the convention's names (key.hpp's ConventionName: Taylor's φ for PHY 711's α)
/// written as the parameters they are here, and the line that says which.
std::optional<Referenced> convention_named(const Context& ctx, const std::string& text,
                                           const std::string& message);

/// `text` with the names the key's steps write for quantities of this problem (key.hpp's
/// DefinedName: the heavy top's I₁, I₃, ω₃) as their exact forms, and the line that says so.
/// Never the answer's own name: ω₃ for ω₃ is no working.
std::optional<Referenced> defined_named(const Context& ctx, const Answer& a,
                                        const std::string& text, const std::string& message);

/// `text` with the primed names the key's steps write (DefinedName "omega1'": the Euler-angle
/// top's ω₁′, along the line-of-nodes basis) as their exact forms, and the line that says so.
/// Plain text, found before the reader reads it (it takes a prime after a name for no part of
/// it): ω₁', ω₁′, ω_1', w1', ω'₁, and run together with a symbol (I₁ω₁'). Never one of the
/// answer's own entries.
std::optional<Referenced> primed_named(const Context& ctx, const Answer& a,
                                       const std::string& text);

/// `text` with the names an earlier answer gives its entries (key.hpp's named_entries: the
/// asymmetric top's Ω₂, Ω₃ of its spin about e₁, Euler's c₁, c₂, c₃) as their exact forms, and
/// the line that says so. Each name is the entry of the last answer before `a` that gives it (the
/// rate about e₁ comes after that axis's pair). Not a symbol of the problem.
std::optional<Referenced> entry_named(const Context& ctx, const Answer& a, const std::string& text,
                                      const std::string& message);

}  // namespace wobble::check::detail
