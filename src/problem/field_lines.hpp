#pragma once
/// @file
/// Where each field of a problem or scene file is, so that a refusal found only when the file is
/// solved or set up (an expression naming no parameter, a unit of another dimension, a body that
/// does not turn) names the file and line as the loader's own refusals do: "FILE:LINE: FIELD:
/// what". A field is named as the messages name it: tables' keys joined by '.', an array's
/// elements by [i] ("motion.omega", "body.shapes[0].sizes[2]", "initial.omega[1]").
///
/// A problem or scene loaded from the catalog by its id names no line: CI checks those files
/// whole, so what is refused at solve time comes from the values set on the command line.
#include <string>

#include "problem/problem.hpp"

namespace wobble {

/// `message` led by "FILE:LINE: " when it begins with a field the file holds ("motion.omega:
/// ...", or "initial.omega[2]: ..." where the array is one field), or with the file and such a
/// field ("FILE: body: ..."); else `message` unchanged (a file from the catalog, one built in
/// code, a message that names no field of the file).
std::string placed_in_file(const Problem& problem, const std::string& message);

/// "FILE:LINE: FIELD" (or "FILE: FIELD" where the file does not hold it), to name a field in a
/// message written by a layer that knows no file.
std::string field_in_file(const Problem& problem, const std::string& field);

/// Called in a catch block: rethrows the InputError in flight placed in `problem`'s file, its
/// type kept where nothing is added (a WorkLimitReached, which callers tell apart, as it is).
[[noreturn]] void rethrow_placed_in_file(const Problem& problem);

}  // namespace wobble
