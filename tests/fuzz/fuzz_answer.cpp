// Students' answers: numbers with units, vectors, matrices and expressions, judged against a
// number, a vector and a matrix of real keys; against a rotation and a vector of angles of the
// PHY 711 problem, whose key names Taylor's φ, θ, ψ for its α, β, γ, and its L in the primed basis,
// which reads the steps' primed ω₁′, ω₂′, ω₃′ (a prime after a name); against the heavy top's
// p_phi, whose key reads I₁, I₃, ω₃ as its steps write them, and its theta_max, a bound, which
// reads an inequality, a range or an interval; and against the flying plate's t_max, which reads
// an earlier vector's magnitude (π/|Ω_space|); and against the cone's centre of mass, a length
// in h, which reads "-0.75 h ẑ" as the height, no number of hours; against the Earth's Euler
// period, which reads d after a number as days (the problem has no symbol d); and against the
// tennis racket's flip interval, which reads the steps' λ and the energy's T.
#include <set>
#include <string>
#include <utility>

#include "check/judge.hpp"
#include "fuzz_common.hpp"
#include "problem/values.hpp"
#include "solvers/catalog.hpp"
#include "solvers/solve.hpp"

namespace {
struct Fixture {
  explicit Fixture(const std::string& id, std::set<std::string> judged_)
      : problem(wobble::find_problem(id)),
        values(wobble::parameter_values(problem, {})),
        key(wobble::solve(problem, values)),
        table(problem.symbol_table()),
        judged(std::move(judged_)) {}
  wobble::Problem problem;
  wobble::sym::Values values;
  wobble::Key key;
  wobble::sym::SymbolTable table;
  std::set<std::string> judged;  // the answers each input is judged as
};
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const Fixture plate("flying-plate", {"I0", "I", "L0_body", "angle_L_e3", "t_max"});
  static const Fixture phy711("euler-angles-phy711", {"R_phy711", "angles_phy711", "L_primed"});
  static const Fixture top("heavy-top", {"p_phi", "theta_max"});
  // A length whose symbol h spells a unit (hours): the symbol read where the unit's dimension
  // is wrong.
  static const Fixture cone("solid-cone", {"center_of_mass"});
  static const Fixture earth("earth-free-precession", {"precession_period_body"});
  static const Fixture racket("tennis-racket", {"flip_interval"});
  const std::string text = wobble::fuzz::text_of(data, size);
  for (const Fixture* f : {&plate, &phy711, &top, &cone, &earth, &racket}) {
    for (const auto& part : f->key.parts) {
      for (const auto& a : part.answers) {
        if (f->judged.count(a.name) == 0) continue;
        for (const bool sigfigs : {false, true}) {
          wobble::check::Options o;
          if (sigfigs) o.sigfigs = 3;
          wobble::fuzz::expect_clean([&] {
            (void)wobble::check::judge({f->key, f->table, f->values}, a, text, o);
          });
        }
      }
    }
  }
  return 0;
}
