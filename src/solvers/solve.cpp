#include "solvers/solve.hpp"

#include "problem/field_lines.hpp"
#include "problem/values.hpp"
#include "problem/variants.hpp"
#include "solvers/exact_answer.hpp"
#include "solvers/named_mistakes.hpp"
#include "solvers/registry.hpp"

namespace wobble {

Key assemble_parts(const Problem& problem,
                   const std::function<Computed(const std::string& quantity)>& compute) {
  Key key;
  for (const auto& part : problem.parts) {
    PartKey pk{part.id, part.question, {}, {}, {}, {}, {}};
    for (const auto& spec : part.answers) {
      Computed c = compute(spec.quantity);
      append_steps(pk, c.steps);
      if (!c.exists) {
        pk.absent.push_back(spec.name);
        pk.absent_why.push_back(c.steps.empty() ? "" : c.steps.back().text);
        pk.absent_unit.push_back(asked_unit(c.answer));
        continue;
      }
      c.answer.name = spec.name;
      c.answer.check_tolerance = spec.tolerance;
      pk.answers.push_back(std::move(c.answer));
    }
    key.parts.push_back(std::move(pk));
  }
  return key;
}

std::vector<std::string> variant_for(const Problem& problem, long n) {
  return first_valid_variant(problem, n, [&](const std::vector<std::string>& a) {
    (void)solve(problem, parameter_values(problem, a));
  });
}

std::vector<std::string> key_conventions() {
  return {
      "SI units; angles in radians.",
      "Inertia tensor I_ij = Σ m (|r|² δ_ij − r_i r_j), so L = I ω (products of inertia carry a "
      "minus sign).",
      "Principal moments in ascending order; axes as unit columns e1, e2, e3, e1 and e2 with their "
      "largest-magnitude component positive, e3 = e1 × e2 (right-handed).",
  };
}

Key solve(const Problem& problem, const sym::Values& values) {
  const SolverInfo& solver = solver_info(problem.solver);
  begin_route_checks();
  Key key;
  try {
    key = solver.solve(problem, values);
    add_named_mistakes(problem, values, key);
  } catch (const InputError&) {
    rethrow_placed_in_file(problem);
  }
  key.problem = problem.id;
  key.title = problem.title;
  key.source = problem.source;
  key.statement = problem.statement;
  key.notes = problem.notes;
  for (const auto& c : key_conventions()) key.notes.push_back(c);
  for (const auto& p : problem.parameters) {
    key.parameters.push_back({p.name, p.latex, p.unit, p.description, values.at(p.name)});
  }
  return key;
}

}  // namespace wobble
