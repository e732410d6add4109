#include "check/expression_dimension.hpp"

#include <algorithm>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "symbolic/unicode_notation.hpp"
#include "symbolic/units.hpp"

namespace wobble::check {

namespace {
// Powers of mass, length and time as rationals, so that sqrt(m^2) is a mass on the way.
using Powers = std::array<GiNaC::numeric, 3>;

struct Dimension {
  bool mixed = false;
  Powers powers{0, 0, 0};
  bool none() const { return powers[0].is_zero() && powers[1].is_zero() && powers[2].is_zero(); }
};

class Reader {
 public:
  explicit Reader(std::map<std::string, Powers> parameters) : parameters_(std::move(parameters)) {}

  // Nothing for a symbol that is no parameter or a node of a kind no answer has.
  std::optional<Dimension> operator()(const GiNaC::ex& e) const {
    if (GiNaC::is_a<GiNaC::numeric>(e) || GiNaC::is_a<GiNaC::constant>(e)) return Dimension{};
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
      const auto it = parameters_.find(GiNaC::ex_to<GiNaC::symbol>(e).get_name());
      if (it == parameters_.end()) return std::nullopt;
      return Dimension{false, it->second};
    }
    if (GiNaC::is_a<GiNaC::add>(e)) return sum(e);
    if (GiNaC::is_a<GiNaC::mul>(e)) return product(e);
    if (GiNaC::is_a<GiNaC::power>(e)) return power(e.op(0), e.op(1));
    if (GiNaC::is_a<GiNaC::function>(e)) return function(e);
    return std::nullopt;
  }

 private:
  static Dimension mixed() { return Dimension{true, {0, 0, 0}}; }

  std::optional<Dimension> sum(const GiNaC::ex& e) const {
    std::optional<Dimension> first;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      const auto d = (*this)(e.op(i));
      if (!d) return std::nullopt;
      if (d->mixed || (first && d->powers != first->powers)) return mixed();
      if (!first) first = d;
    }
    return first ? *first : Dimension{};
  }

  std::optional<Dimension> product(const GiNaC::ex& e) const {
    Dimension out;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      const auto d = (*this)(e.op(i));
      if (!d) return std::nullopt;
      if (d->mixed) return mixed();
      for (std::size_t k = 0; k < 3; ++k) out.powers[k] += d->powers[k];
    }
    return out;
  }

  std::optional<Dimension> power(const GiNaC::ex& base, const GiNaC::ex& exponent) const {
    const auto b = (*this)(base);
    const auto x = (*this)(exponent);
    if (!b || !x) return std::nullopt;
    if (b->mixed || x->mixed || !x->none()) return mixed();
    if (b->none()) return Dimension{};
    if (!GiNaC::is_a<GiNaC::numeric>(exponent) ||
        !GiNaC::ex_to<GiNaC::numeric>(exponent).is_rational()) {
      return mixed();  // m^alpha: a quantity with a unit to a power that varies
    }
    Dimension out = *b;
    for (auto& p : out.powers) p *= GiNaC::ex_to<GiNaC::numeric>(exponent);
    return out;
  }

  std::optional<Dimension> function(const GiNaC::ex& e) const {
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    std::vector<Dimension> args;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      const auto d = (*this)(e.op(i));
      if (!d) return std::nullopt;
      if (d->mixed) return mixed();
      args.push_back(*d);
    }
    if (name == "abs" && args.size() == 1) return args[0];
    // atan2(y, x): the angle of (x, y), whose coordinates share a unit.
    if (name == "atan2" && args.size() == 2) {
      return args[0].powers == args[1].powers ? Dimension{} : mixed();
    }
    for (const auto& a : args) {
      if (!a.none()) return mixed();
    }
    return Dimension{};
  }

  std::map<std::string, Powers> parameters_;
};

bool has_symbol(const GiNaC::ex& e) {
  if (GiNaC::is_a<GiNaC::symbol>(e)) return true;
  for (std::size_t i = 0; i < e.nops(); ++i) {
    if (has_symbol(e.op(i))) return true;
  }
  return false;
}
// As Unit::dimension_words, with fractions: "mass^(1/2) × length"; "a pure number" for none.
std::string words(const Powers& powers) {
  static const char* word[] = {"mass", "length", "time"};
  std::string num, den;
  for (std::size_t k = 0; k < 3; ++k) {
    if (powers[k].is_zero()) continue;
    const GiNaC::numeric p = GiNaC::abs(powers[k]);
    std::string w = word[k];
    if (p != 1) {
      std::ostringstream s;
      s << p;
      w += p.is_integer() ? "^" + s.str() : "^(" + s.str() + ")";
    }
    std::string& side = powers[k].is_positive() ? num : den;
    side += (side.empty() ? "" : " × ") + w;
  }
  if (num.empty() && den.empty()) return "a pure number";
  if (num.empty()) num = "1";
  return sym::to_unicode(den.empty() ? num : num + " / " + den);
}
}  // namespace

std::optional<ExpressionDimension> expression_dimension(const GiNaC::ex& e, const Key& key) {
  // A plain number's unit is not written ("[m R² ω sin α/4, 0, 0.0139]"): its dimension is not
  // known.
  if (!has_symbol(e)) return std::nullopt;
  std::map<std::string, Powers> parameters;
  for (const auto& p : key.parameters) {
    Powers powers{0, 0, 0};
    if (!p.unit.empty()) {
      if (!is_unit(p.unit)) return std::nullopt;
      const auto dim = parse_unit(p.unit, "unit of " + p.name).dim;
      for (std::size_t k = 0; k < 3; ++k) powers[k] = dim[k];
    }
    parameters.emplace(p.name, powers);
  }
  const auto d = Reader(std::move(parameters))(e);
  if (!d) return std::nullopt;
  ExpressionDimension out;
  out.mixed = d->mixed;
  if (out.mixed) return out;
  out.words = words(d->powers);
  if (std::all_of(d->powers.begin(), d->powers.end(),
                  [](const GiNaC::numeric& p) { return p.is_integer(); })) {
    out.dim = {d->powers[0].to_int(), d->powers[1].to_int(), d->powers[2].to_int()};
  }
  return out;
}

}  // namespace wobble::check
