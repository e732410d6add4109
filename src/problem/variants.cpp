#include "problem/variants.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>

#include "core/input_error.hpp"

namespace wobble {

namespace {
std::uint64_t fnv1a(const std::string& s) {
  std::uint64_t h = 1469598103934665603ULL;
  for (const unsigned char c : s) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  return h;
}

// SplitMix64 (Steele, Lea, Flood 2014): one well-mixed 64-bit value per seed.
std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

// A uniform number in [0, 1) from the top 53 bits.
double unit_draw(const std::string& id, const std::string& name, long n, int draw) {
  // Draw 0 keeps the seed of the first version (pinned variants stay as they were).
  const std::string seed = id + '\0' + name + '\0' + std::to_string(n) +
                           (draw == 0 ? std::string() : '\0' + std::to_string(draw));
  const std::uint64_t bits = splitmix64(fnv1a(seed));
  return static_cast<double>(bits >> 11) * 0x1.0p-53;
}

std::string two_digits(double x) {
  if (x == 0.0) return "0";
  const int e = static_cast<int>(std::floor(std::log10(std::abs(x))));
  const double place = std::pow(10.0, e - 1);
  const double rounded = std::round(x / place) * place;
  // "260", as a handout writes a spin, not "2.6e+02": from 10 to a million the two digits are
  // whole tens or more; beyond, and below 1e-4, the exponent is clearer.
  if (e >= 1 && e < 6) return fmt::format("{:.0f}", rounded);
  return fmt::format("{:.{}g}", rounded, 2);
}
}  // namespace

std::vector<std::string> variant_assignments(const Problem& problem, long n, int draw) {
  if (n < 1 || n > 1000000) {
    throw InputError(fmt::format("--variant: {} is out of range (expected 1 to 1000000)", n));
  }
  std::vector<std::string> out;
  for (const auto& p : problem.parameters) {
    if (p.fixed) continue;  // a physical constant keeps its value in every variant
    const double u = unit_draw(problem.id, p.name, n, draw);
    const Interval& r = p.range;
    const double d = p.default_value;
    double x;
    if (std::isfinite(r.lo) && std::isfinite(r.hi) && r.lo <= 0.0 && (d <= 0.0 || r.hi <= 2 * d)) {
      x = r.lo + u * (r.hi - r.lo);  // a finite range such as an angle's: uniform over it
    } else if (d > 0.0) {
      x = d * std::pow(4.0, u - 0.5);  // log-uniform over [d/2, 2d]
    } else {
      x = d;  // nothing to vary around
    }
    std::string text;
    for (int attempt = 0; attempt < 2; ++attempt) {
      text = p.is_angle() ? fmt::format("{}deg", std::lround(x * 180 / M_PI)) : two_digits(x);
      const double shown = p.is_angle()
                               ? static_cast<double>(std::lround(x * 180 / M_PI)) * M_PI / 180
                               : std::stod(text);
      if (r.contains(shown)) break;
      x = d;  // rounding left the range (an open end): fall back to the default
      text = fmt::format("{:.17g}", d);
    }
    out.push_back(p.name + "=" + text);
  }
  return out;
}

std::vector<std::string> first_valid_variant(
    const Problem& problem, long n,
    const std::function<void(const std::vector<std::string>&)>& accept) {
  std::string last;
  for (int draw = 0; draw < kVariantDraws; ++draw) {
    const std::vector<std::string> a = variant_assignments(problem, n, draw);
    try {
      accept(a);
      return a;
    } catch (const InputError& e) {
      last = e.what();
    }
  }
  throw InputError(
      fmt::format("--variant {}: none of {} draws from the parameters' ranges makes "
                  "a valid problem (the last: {}); narrow the ranges in {}",
                  n, kVariantDraws, last, problem.file.string()));
}

}  // namespace wobble
