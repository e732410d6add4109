#include "check/answer_shape.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <string>

#include "check/brackets.hpp"
#include "check/judge_internal.hpp"
#include "check/refusal_hints.hpp"
#include "check/unit_arithmetic.hpp"
#include "core/characters.hpp"
#include "core/input_error.hpp"

namespace wobble::check::detail {

namespace {

std::string shape_words(std::size_t rows, std::size_t cols, bool vector, bool matrix) {
  if (matrix) return fmt::format("a {}x{} matrix [[..], ..]", rows, cols);
  if (vector) return fmt::format("a {}-vector [..]", rows);
  return "a number";
}

}  // namespace

bool in_plane_of_two(const Answer& a, sym::ValueText& v) {
  if (a.value.shape != Value::Shape::vector || a.value.data.size() != 3 ||
      !a.named_entries.empty() || a.kind == AnswerKind::principal_moments || !v.is_vector ||
      v.entries.size() != 2)
    return false;
  const ListItems forms = list_items(a.symbolic);
  const bool zero = a.symbolic.empty() ? a.value.data[2] == 0.0
                                       : forms.items.size() == 3 && trim(forms.items[2]) == "0";
  if (!zero || a.value.data[0] == 0.0 || a.value.data[1] == 0.0) return false;
  v.entries.push_back(GiNaC::ex(0));
  v.rows = 3;
  return true;
}

bool moments_on_diagonal(const Answer& a, sym::ValueText& v) {
  if (a.kind != AnswerKind::principal_moments || !v.is_matrix || v.rows != 3 || v.cols != 3)
    return false;
  for (std::size_t r = 0; r < 3; ++r) {
    for (std::size_t c = 0; c < 3; ++c) {
      if (r != c && !v.entries[3 * r + c].is_zero()) return false;
    }
  }
  v = sym::ValueText{3, 1, true, false, {v.entries[0], v.entries[4], v.entries[8]}};
  return true;
}

namespace {

// Where a diagonal tensor is asked for and three entries are given (its diagonal, as a table
// lists the moments): how to write them as the tensor, "diag(0.111, 0.111, 0.006) kg m^2".
std::string diagonal_hint(const Answer& a, const sym::ValueText& v, const std::string& typed,
                          bool numbers_with_unit) {
  if (a.value.shape != Value::Shape::matrix || a.value.rows != 3 || a.value.cols != 3 ||
      !v.is_vector || v.entries.size() != 3)
    return "";
  for (std::size_t i = 0; i < 9; ++i) {
    if (i / 3 != i % 3 && a.value.data[i] != 0.0) return "";
  }
  std::string text = trim(typed);
  if (!text.empty() && opens(text[0])) {
    // One bracket around the entries, a unit at most after it: "(0.1), 0.2, 0.3" has none.
    const std::size_t close = matching(text, 0);
    if (close == std::string::npos || text.find(',', close) != std::string::npos) return "";
    text = text.substr(1, close - 1) + ")" + text.substr(close + 1);
  } else if (const std::size_t comma = text.rfind(',');
             numbers_with_unit && comma != std::string::npos) {
    // "0.111, 0.111, 0.006 kg m^2": the unit is the whole's, after the bracket.
    const std::string last = trim(text.substr(comma + 1));
    char* end = nullptr;
    (void)std::strtod(last.c_str(), &end);
    const std::size_t digits = static_cast<std::size_t>(end - last.c_str());
    text = text.substr(0, comma + 1) + " " + last.substr(0, digits) + ")" +
           (digits < last.size() && last[digits] != ' ' ? " " : "") + last.substr(digits);
  } else {
    text += ")";
  }
  return " (for the tensor with this diagonal write diag(" + printable(text, kQuotedCharacters) +
         "; three entries alone are a vector)";
}

}  // namespace

void check_shape(const Answer& a, const ReadAnswer& p, const std::string& typed) {
  const sym::ValueText& v = p.value;
  const bool key_vec = a.value.shape == Value::Shape::vector;
  const bool key_mat = a.value.shape == Value::Shape::matrix;
  if (key_vec != v.is_vector || key_mat != v.is_matrix || a.value.data.size() != v.entries.size()) {
    // A matrix for a vector is no decimal comma's doing ("[[0.569,0.1,0], ..]" has commas
    // between digits); for the principal moments it is likely the tensor not yet diagonal.
    std::string hint = key_vec && v.is_matrix ? ""
                                              : misreading_hint(a, typed, v.entries.size()) +
                                                    imaginary_hint(a, typed, "");
    if (a.kind == AnswerKind::principal_moments && v.is_matrix)
      hint +=
          " (the principal moments are this matrix's eigenvalues; one with nothing off its "
          "diagonal is read as its diagonal)";
    hint += diagonal_hint(a, v, typed, p.unit && !p.symbolic);
    throw InputError(fmt::format("{}: {} wants {}, not {}{}", kField, a.name,
                                 shape_words(a.value.rows, a.value.cols, key_vec, key_mat),
                                 shape_words(v.rows, v.cols, v.is_vector, v.is_matrix), hint));
  }
}

}  // namespace wobble::check::detail
