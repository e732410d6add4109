#pragma once
/// @file
/// Renderers of a key. Each returns the whole document as a string, deterministic, ending in a
/// newline. Numbers print with 10 significant digits (format_number) in text, Markdown and LaTeX;
/// JSON carries full double precision.
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "solvers/key.hpp"

namespace wobble {

enum class Format { text, markdown, latex, json };

/// @throws std::invalid_argument for an unknown name (expected text, markdown, latex, json).
Format format_from_name(std::string_view name);

/// Unicode text for a terminal; at `width` columns (0: none), its prose broken at spaces
/// (core/word_wrap.hpp) and its values between them, each answer's lines left whole to be copied.
std::string render_text(const Key& key, std::size_t width = 0);
/// Markdown that renders on a code forge, math in $...$ and $$...$$.
std::string render_markdown(const Key& key);
/// A complete LaTeX document (article, amsmath), compiles with pdflatex.
std::string render_latex(const Key& key);
/// The JSON document (README, "JSON keys").
nlohmann::ordered_json key_to_json(const Key& key);
std::string render_json(const Key& key);

/// `width` is the text's (render_text); the other formats take none.
std::string render(const Key& key, Format format, std::size_t width = 0);

}  // namespace wobble
