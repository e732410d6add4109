#pragma once
/// @file
/// Reading a key's symbolic text back: a scalar expression, a vector "[x, y, z]" or a matrix
/// "[[a, b], [c, d]]" whose entries are GiNaC expressions in the declared symbols.
#include <ginac/ginac.h>

#include <string>
#include <vector>

#include "symbolic/expression.hpp"

namespace wobble::sym {

struct ValueText {
  std::size_t rows = 1, cols = 1;  ///< scalar 1x1; vector n x 1 (is_vector)
  bool is_vector = false, is_matrix = false;
  std::vector<GiNaC::ex> entries;  ///< row-major
};

/// @throws ExpressionError naming `field`: unbalanced brackets, ragged rows, a bad entry, or
///         nesting deeper than a matrix.
ValueText parse_value_text(const std::string& text, const SymbolTable& table,
                           const std::string& field);

}  // namespace wobble::sym
