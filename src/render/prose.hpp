#pragma once
/// @file
/// A key's prose (its notes, steps and conventions) as each format sets it. The solvers write
/// prose in ASCII and Unicode as a terminal shows it ("dw1/dt = c1 w2 w3", "Ω2 Ω3 > 0"); a page
/// sets the names in it as its formulas do ($\dot\omega_1$ ...), a terminal or a Markdown file
/// as the Unicode its questions print ("dω₁/dt = c₁ ω₂ ω₃").
///
/// Conventions: wobble's ASCII name for ω is w ("w", "w1", "w_i", "dw1/dt"); an indexed letter
/// ("I1", "e3", "c2") carries its index as a subscript; a name the answers use ("k2",
/// "angles_zxz") is the name `check --name` takes and is shown as typed.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "solvers/key.hpp"

namespace wobble::detail {

/// A quantity's name as LaTeX math when it reads as a symbol with a subscript: "Omega_body" ->
/// "\Omega_{\mathrm{body}}", "theta_min" -> "\theta_{\mathrm{min}}", "p_phi" -> "p_{\phi}",
/// "I_xy" -> "I_{xy}", "L0_space" -> "L_{0,\mathrm{space}}"; a size as books write it,
/// "L_magnitude" -> "\lvert L\rvert", and a rate at t = 0, "dw_dt0" -> "\dot{\omega}(0)"; nullopt
/// for a name that is words ("principal_axes", "max_angle").
std::optional<std::string> name_latex(const std::string& name);

/// An answer's name as the symbol a LaTeX key heads it with: name_latex's, and for a name
/// without an underscore a letter and its index ("I0" -> "I_0", "omega3" -> "\omega_3", "I",
/// "k"); nullopt for words and for a square's name ("k2", k²).
std::optional<std::string> answer_symbol_latex(const std::string& name);

/// The names a key's prose uses, for setting it as its formulas are: the parameters' LaTeX by
/// name ("w1" -> "\omega_1", "alpha" -> "\alpha"), and the answers' names (a prose word that is
/// one and reads as no symbol is the name `check --name` takes: shown as typed).
struct ProseNames {
  std::map<std::string, std::string> parameter_latex;
  std::vector<std::string> answers;
};
ProseNames prose_names(const Key& key);

/// Plain text with Unicode symbols for LaTeX text mode: escapes specials, maps Σ -> $\Sigma$ ...
/// Names in the prose become math as the key's formulas set them: a parameter by its LaTeX (one
/// with a digit, an underscore or a Greek name; "a" stays a word), a subscripted name
/// ("Omega_space", "Ω_space", "p_φ") by name_latex, an indexed letter ("I1", "e3", "c2") with
/// its index as a subscript, wobble's ASCII ω ("w", "w1", "w_i", "dw1/dt") as ω, and an
/// answer's name in typewriter type.
std::string latex_text(const std::string& s, const ProseNames& names = {});

/// How a format without math shows an answer's name in prose: as typed (a terminal) or as code
/// (Markdown, as its answer headings show the name).
enum class AnswerNameStyle { plain, code };

/// Prose with its names in the Unicode a terminal key's questions print: the same names
/// latex_text sets as math ("dw1/dt = c1 w2 w3" -> "dω₁/dt = c₁ ω₂ ω₃", "Ω2" -> "Ω₂",
/// "θ̇0" -> "θ̇₀", "Omega_space" -> "Ω_space"); everything else as it is.
std::string unicode_text(const std::string& s, const ProseNames& names,
                         AnswerNameStyle answer_names);

}  // namespace wobble::detail
