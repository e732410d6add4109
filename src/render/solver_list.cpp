#include "render/solver_list.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

namespace wobble {

namespace {
// "principal_moments" and the frame, as one column: "vector (body)".
std::string kind_text(const QuantityInfo& q) {
  std::string s = kind_name(q.kind);
  if (q.frame != AnswerFrame::none) s += fmt::format(" ({})", frame_name(q.frame));
  if (q.sign == SignConvention::sense_of_precession) s += ", signed";
  return s;
}
}  // namespace

std::string solver_list_text(const std::vector<SolverInfo>& solvers) {
  std::size_t name_w = 8, kind_w = 4, unit_w = 4;
  for (const auto& s : solvers) {
    for (const auto& q : s.quantities) {
      name_w = std::max(name_w, q.name.size());
      kind_w = std::max(kind_w, kind_text(q).size());
      unit_w = std::max(unit_w, q.unit.size());
    }
  }
  std::string out;
  for (const auto& s : solvers) {
    out += fmt::format("{}: {}\n", s.name, s.summary);
    out += fmt::format("  [motion]: {}\n", s.motion_keys.empty()
                                                ? std::string("none")
                                                : fmt::format("{}", fmt::join(s.motion_keys, ", ")));
    std::vector<std::string> extras;
    if (s.sketch != nullptr) extras.emplace_back("--figure");
    if (s.cross_checked_by_simulation) extras.emplace_back("--cross-check");
    if (!extras.empty()) out += fmt::format("  solve options: {}\n", fmt::join(extras, ", "));
    out += fmt::format("  {:<{}}  {:<{}}  {:<{}}  {}\n", "quantity", name_w, "kind", kind_w,
                       "unit", unit_w, "meaning");
    for (const auto& q : s.quantities) {
      out += fmt::format("  {:<{}}  {:<{}}  {:<{}}  {}\n", q.name, name_w, kind_text(q), kind_w,
                         q.unit.empty() ? "1" : q.unit, unit_w, q.description);
    }
  }
  return out;
}

}  // namespace wobble
