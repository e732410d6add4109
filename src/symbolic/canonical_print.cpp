#include "symbolic/canonical_print.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace wobble::sym {

namespace {
// LaTeX source longer than this is not stacked in \frac or put under \sqrt, which TeX can
// never break across lines: it is written on one level, (a) / (b) and (x)^{1/2}, so that a
// key's page can wrap it. Measured on the catalog's keys (A4, 2 cm margins, 11 pt, formulas
// shrunk to 70% at most): at 230 characters a fraction still overflowed its line; 200 leaves
// none, while fractions up to about two thirds of a line stay stacked.
constexpr std::size_t kLongLatex = 200;
}  // namespace

namespace {
using GiNaC::ex;
using GiNaC::is_a;
using GiNaC::numeric;

enum class Style { text, latex };

// GiNaC's numeric has no to_string; its stream output of an integer is the plain digits.
std::string str(const numeric& n) {
  std::ostringstream s;
  s << n;
  return s.str();
}

// Binding strength of the printed form, to decide on parentheses.
enum Prec { kSum = 1, kProduct = 2, kPower = 3, kAtom = 4 };

// A printed form and how tightly it binds (Prec).
using Printed = std::pair<std::string, int>;

// A term of a sum as sign and magnitude; `key` is the magnitude's text, by which terms sort.
struct Term {
  bool negative;
  std::string key;
  std::string magnitude;
};

// What a printer keeps of each subexpression for one table and style: its printed form, and
// for a sum its sorted terms (asked for again by the sum's sign, its rank as a factor and its
// printing: a 26-term sum's terms were sorted four times, each negating every negative term).
struct PrintMemo {
  std::map<ex, Printed, GiNaC::ex_is_less> printed;
  std::map<ex, std::vector<Term>, GiNaC::ex_is_less> sums;
  std::size_t size() const { return printed.size() + sums.size(); }
};

// Each subexpression is printed once per table and style: sorting and sign rules look at a
// factor's or a term's text again and again, which without this took time exponential in the
// nesting depth (fuzzing found a 76-character expression taking seconds). Kept across calls: a
// key prints each answer as text and as LaTeX (whose sums are sorted by their text), and
// simplify() measures candidates by their text (the three-atom molecule printed 57 expressions
// in 180 calls). Emptied when large, and only between calls, never under a printer at work.
class PrintMemos {
 public:
  static PrintMemos& here() {
    thread_local PrintMemos memos;
    return memos;
  }
  PrintMemo& of(const SymbolTable& table, Style style) {
    return memos_[{table.version(), style}];
  }
  // At the start of a call: bounds the memory kept.
  void bound() {
    std::size_t entries = 0;
    for (const auto& [key, memo] : memos_) entries += memo.size();
    if (entries > kMaxEntries || memos_.size() > kMaxTables) memos_.clear();
  }

 private:
  static constexpr std::size_t kMaxEntries = 4096, kMaxTables = 16;
  std::map<std::pair<std::uint64_t, Style>, PrintMemo> memos_;
};

class Printer {
 public:
  Printer(const SymbolTable& table, Style style)
      : table_(table), style_(style), memo_(PrintMemos::here().of(table, style)) {}

  std::string print(const ex& e) { return print_prec(e).first; }

 private:
  const SymbolTable& table_;
  Style style_;
  PrintMemo& memo_;
  std::unique_ptr<Printer> text_;  // the text-style printer used for sort keys

  Printer& text_printer() {
    if (!latex()) return *this;
    if (!text_) text_ = std::make_unique<Printer>(table_, Style::text);
    return *text_;
  }

  bool latex() const { return style_ == Style::latex; }

  std::string paren(const std::string& s) const {
    std::string out = latex() ? "\\left(" : "(";
    out += s;
    out += latex() ? "\\right)" : ")";
    return out;
  }

  Printed print_prec(const ex& e) {
    if (const auto it = memo_.printed.find(e); it != memo_.printed.end()) return it->second;
    auto printed = print_prec_uncached(e);
    memo_.printed.emplace(e, printed);
    return printed;
  }

  std::pair<std::string, int> print_prec_uncached(const ex& e) {
    if (is_a<numeric>(e)) return print_numeric(GiNaC::ex_to<numeric>(e));
    if (is_a<GiNaC::symbol>(e)) return {print_symbol(e), kAtom};
    if (is_a<GiNaC::constant>(e)) {
      if (e.is_equal(GiNaC::Pi)) return {latex() ? "\\pi" : "Pi", kAtom};
      throw std::invalid_argument("canonical_print: unsupported constant");
    }
    if (is_a<GiNaC::add>(e)) return {print_sum(e), kSum};
    if (is_a<GiNaC::power>(e) &&
        !(is_a<numeric>(e.op(1)) && GiNaC::ex_to<numeric>(e.op(1)).is_rational())) {
      return print_general_power(e);
    }
    if (is_a<GiNaC::mul>(e) || is_a<GiNaC::power>(e)) return print_product(e);
    if (is_a<GiNaC::function>(e)) return {print_function(e), kAtom};
    throw std::invalid_argument(std::string("canonical_print: unsupported expression ") +
                                GiNaC::ex_to<GiNaC::basic>(e).class_name());
  }

  // base^exponent with an exponent that is not a rational number (2^a, x^y): both sides in
  // parentheses unless atoms. (A product would print it as a factor to the power 1, forever.)
  std::pair<std::string, int> print_general_power(const ex& e) {
    auto [b, bp] = print_prec(e.op(0));
    auto [x, xp] = print_prec(e.op(1));
    if (bp < kAtom) b = paren(b);
    if (latex()) return {b + "^{" + x + "}", kPower};
    return {b + "^" + (xp < kAtom ? paren(x) : x), kPower};
  }

  std::pair<std::string, int> print_numeric(const numeric& n) {
    if (!n.is_real()) throw std::invalid_argument("canonical_print: complex number");
    if (n.is_integer()) {
      std::string s = str(n);
      return {s, n.is_negative() ? kSum : kAtom};
    }
    if (n.is_rational()) {
      const std::string num = str(n.numer()), den = str(n.denom());
      if (latex()) {
        const bool neg = n.is_negative();
        const std::string body = "\\frac{" + (neg ? num.substr(1) : num) + "}{" + den + "}";
        return {neg ? "-" + body : body, neg ? kSum : kAtom};
      }
      return {num + "/" + den, kProduct};
    }
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", n.to_double());
    return {buf, n.is_negative() ? kSum : kAtom};
  }

  std::string print_symbol(const ex& e) const {
    const std::string name = GiNaC::ex_to<GiNaC::symbol>(e).get_name();
    return latex() ? table_.latex_of(name) : name;
  }

  std::string print_function(const ex& e) {
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    std::string args;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      if (i) args += ',';
      args += print(e.op(i));
    }
    if (!latex()) return name + "(" + args + ")";
    static const std::map<std::string, std::string> known{
        {"sin", "\\sin"},     {"cos", "\\cos"},     {"tan", "\\tan"},
        {"atan", "\\arctan"}, {"asin", "\\arcsin"}, {"acos", "\\arccos"},
        {"exp", "\\exp"},     {"log", "\\ln"},      {"atan2", "\\operatorname{atan2}"}};
    if (name == "abs") return "\\left|" + args + "\\right|";
    // K(k), the complete elliptic integral of the first kind, as books write it (and the answer
    // reader reads it); by GiNaC's name where the problem has a symbol K.
    if (name == "EllipticK" && !table_.contains("K")) return "K" + paren(args);
    auto it = known.find(name);
    return (it == known.end() ? "\\operatorname{" + name + "}" : it->second) + paren(args);
  }

  // The terms of a sum, each as sign and magnitude, sorted by the text of the magnitude alone.
  // Sorting ignores signs so that s and -s list their terms in the same order: GiNaC's normal()
  // and factor() return either, depending on hash values that change from run to run (ASLR).
  const std::vector<Term>& sum_terms(const ex& e) {
    if (const auto it = memo_.sums.find(e); it != memo_.sums.end()) return it->second;
    return memo_.sums.emplace(e, sum_terms_uncached(e)).first->second;
  }

  std::vector<Term> sum_terms_uncached(const ex& e) {
    std::vector<Term> terms;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      const ex t = e.op(i);
      const bool negative = term_negative(t);
      const ex mag = negative ? -t : t;
      // The key is the text form; in text style it is also what is printed (printing it twice
      // at every level of nesting took time exponential in the depth: fuzzing found it).
      Printer& text = text_printer();
      std::string shown = text.print(mag);
      std::string key = shown;
      if (is_a<numeric>(mag)) key.insert(key.begin(), '~');  // numbers sort last
      terms.push_back({negative, key, latex() ? print(mag) : std::move(shown)});
    }
    std::stable_sort(terms.begin(), terms.end(),
                     [](const Term& a, const Term& b) { return a.key < b.key; });
    return terms;
  }

  // The sign a term prints with: its numeric coefficient's, flipped once for every sum factor
  // with an odd integer power whose own lead is negative (print_product moves those signs out).
  bool term_negative(const ex& t) {
    bool negative = coefficient(t).is_negative();
    auto toggle = [&](const ex& f) {
      ex base = f;
      numeric n = 1;
      if (is_a<GiNaC::power>(f) && is_a<numeric>(f.op(1))) {
        base = f.op(0);
        n = GiNaC::ex_to<numeric>(f.op(1));
      }
      if (is_a<GiNaC::add>(base) && n.is_integer() && n.is_odd() && lead_negative(base)) {
        negative = !negative;
      }
    };
    if (is_a<GiNaC::mul>(t)) {
      for (std::size_t i = 0; i < t.nops(); ++i) toggle(t.op(i));
    } else {
      toggle(t);
    }
    return negative;
  }

  // A sum's canonical sign: its first term (by key) positive.
  bool lead_negative(const ex& sum) { return sum_terms(sum).front().negative; }

  // The terms joined, with every sign flipped if `flip`.
  static std::string join_terms(const std::vector<Term>& terms, bool flip) {
    std::string out;
    for (std::size_t i = 0; i < terms.size(); ++i) {
      const bool negative = terms[i].negative != flip;
      if (i == 0) {
        out = (negative ? "-" : "") + terms[i].magnitude;
      } else {
        out += (negative ? " - " : " + ") + terms[i].magnitude;
      }
    }
    return out;
  }

  // The terms joined as join_terms; where the first (by key) is then negative, the positive
  // ones first (each group in key order): "b - a" for -a + b, as a book writes it.
  static std::string join_positive_first(const std::vector<Term>& terms, bool flip) {
    if (terms.front().negative == flip) return join_terms(terms, flip);
    std::vector<Term> ordered;
    for (const bool negative : {false, true}) {
      for (const Term& t : terms) {
        if ((t.negative != flip) == negative) ordered.push_back(t);
      }
    }
    return join_terms(ordered, flip);
  }

  // Whether the sum, its signs flipped if `flip`, has a positive term: its sign can go in.
  static bool has_positive(const std::vector<Term>& terms, bool flip) {
    return std::any_of(terms.begin(), terms.end(),
                       [&](const Term& t) { return t.negative == flip; });
  }

  // A sum whose first term (by key) is negative prints its positive terms first, "ψ - π/2", and
  // as -(...) where it has none. Either way the text depends on the sum alone, not on whether
  // GiNaC holds it as s or as -1 times -s (a number times a sum is distributed).
  std::string print_sum(const ex& e) {
    const auto& terms = sum_terms(e);
    if (has_positive(terms, false)) return join_positive_first(terms, false);
    return "-" + paren(join_terms(terms, true));
  }

  static numeric coefficient(const ex& t) {
    if (is_a<numeric>(t)) return GiNaC::ex_to<numeric>(t);
    if (is_a<GiNaC::mul>(t)) {
      numeric c = 1;
      for (std::size_t i = 0; i < t.nops(); ++i) {
        if (is_a<numeric>(t.op(i))) c *= GiNaC::ex_to<numeric>(t.op(i));
      }
      return c;
    }
    return 1;
  }

  // Sort rank of a factor: symbols by declaration order (then name, for symbols the table does
  // not know), then everything else by its sign-normalised text.
  std::tuple<int, std::size_t, std::string> factor_rank(const ex& base) {
    Printer& text = text_printer();
    if (is_a<GiNaC::symbol>(base)) {
      const std::string name = GiNaC::ex_to<GiNaC::symbol>(base).get_name();
      return {0, table_.order_of(name), name};
    }
    if (is_a<GiNaC::constant>(base)) return {1, 0, ""};
    if (is_a<GiNaC::function>(base)) return {2, 0, text.print(base)};
    if (is_a<GiNaC::power>(base) || is_a<numeric>(base)) return {3, 0, text.print(base)};
    if (is_a<GiNaC::add>(base))
      return {4, 0, join_terms(text.sum_terms(base), lead_negative(base))};
    return {5, 0, text.print(base)};
  }

  // A power base^n with n > 0 as printed inside a product.
  std::string print_power(const ex& base, const numeric& n) {
    if (n == 1) {
      auto [s, p] = print_prec(base);
      return p < kProduct || (p == kProduct && !latex()) ? paren(s) : s;
    }
    if (n == numeric(1, 2)) {
      if (!latex()) return "sqrt(" + print(base) + ")";
      const std::string radicand = print(base);
      // A root over a long expression cannot break across lines: a power 1/2 can.
      if (radicand.size() > kLongLatex) return "\\left(" + radicand + "\\right)^{1/2}";
      return "\\sqrt{" + radicand + "}";
    }
    auto [s, p] = print_prec(base);
    if (latex() && is_a<GiNaC::function>(base) && n.is_integer()) {
      // \sin^{2}\left(\alpha\right), the usual spelling.
      std::string f = s;
      const auto open = f.find("\\left(");
      if (open != std::string::npos)
        return f.substr(0, open) + "^{" + str(n) + "}" + f.substr(open);
    }
    const bool wrap = p < kAtom || is_a<GiNaC::power>(base) || is_a<numeric>(base);
    const std::string b = wrap ? paren(s) : s;
    if (latex()) return b + "^{" + print(n) + "}";
    return b + "^" + (n.is_integer() ? str(n) : "(" + print(n) + ")");
  }

  // (±sum)^n, the sum's signs flipped if `flip`, in parentheses: for a sum whose lead is
  // negative, and for one that takes a product's sign (print_product), positive terms first.
  std::string print_signed_power(const ex& sum, const numeric& n, bool flip) {
    const std::string body = paren(join_positive_first(sum_terms(sum), flip));
    if (n == 1) return body;
    return latex() ? body + "^{" + str(n) + "}" : body + "^" + str(n);
  }

  // True if every \left( in s is closed by its own \right) inside s (so the outer pair is one).
  static bool balanced_inside(const std::string& s) {
    int depth = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (s.compare(i, 6, "\\left(") == 0) ++depth;
      if (s.compare(i, 7, "\\right)") == 0 && --depth < 0) return false;
    }
    return depth == 0;
  }

  std::pair<std::string, int> print_product(const ex& e) {
    numeric coeff = 1;
    std::vector<std::pair<ex, numeric>> factors;  // base, exponent (rational)
    auto add_factor = [&](const ex& f) {
      if (is_a<numeric>(f)) {
        coeff *= GiNaC::ex_to<numeric>(f);
      } else if (is_a<GiNaC::power>(f) && is_a<numeric>(f.op(1)) &&
                 GiNaC::ex_to<numeric>(f.op(1)).is_rational()) {
        factors.emplace_back(f.op(0), GiNaC::ex_to<numeric>(f.op(1)));
      } else {
        factors.emplace_back(f, numeric(1));
      }
    };
    if (is_a<GiNaC::mul>(e)) {
      for (std::size_t i = 0; i < e.nops(); ++i) add_factor(e.op(i));
    } else {
      add_factor(e);
    }
    // Ranked once each (ranking inside the comparison printed every factor O(n log n) times,
    // at every level of nesting).
    {
      using Rank = std::tuple<int, std::size_t, std::string>;
      std::vector<std::pair<Rank, std::pair<ex, numeric>>> ranked;
      for (auto& f : factors) ranked.emplace_back(factor_rank(f.first), std::move(f));
      std::stable_sort(ranked.begin(), ranked.end(),
                       [](const auto& a, const auto& b) { return a.first < b.first; });
      for (std::size_t i = 0; i < ranked.size(); ++i) factors[i] = std::move(ranked[i].second);
    }
    // Sum factors with an integer power carry their sign into the coefficient (see print_sum).
    std::vector<bool> flipped(factors.size(), false);
    for (std::size_t i = 0; i < factors.size(); ++i) {
      const auto& [base, n] = factors[i];
      if (is_a<GiNaC::add>(base) && n.is_integer() && lead_negative(base)) {
        flipped[i] = true;
        if (n.is_odd()) coeff = -coeff;
      }
    }
    // A product's sign goes into its one sum of an odd power that then leads with a positive
    // term: H ω/(1 - H), not -H ω/(H - 1). Not where two or more could take it: -(10 m a² -
    // λ)(5 m a² - λ)(7 m a² - λ) keeps its factors alike.
    std::vector<bool> absorbed(factors.size(), false);
    if (coeff.is_negative()) {
      std::vector<std::size_t> takers;
      for (std::size_t i = 0; i < factors.size(); ++i) {
        const auto& [base, n] = factors[i];
        if (is_a<GiNaC::add>(base) && n.is_integer() && n.is_odd() &&
            has_positive(sum_terms(base), !flipped[i]))
          takers.push_back(i);
      }
      if (takers.size() == 1) {
        absorbed[takers[0]] = true;
        coeff = -coeff;
      }
    }
    const bool negative = coeff.is_negative();
    const numeric c = GiNaC::abs(coeff);
    std::vector<std::string> num, den;
    if (c.numer() != 1) num.push_back(str(c.numer()));
    if (c.denom() != 1) den.push_back(str(c.denom()));
    for (std::size_t i = 0; i < factors.size(); ++i) {
      const auto& [base, n] = factors[i];
      const numeric power = n.is_positive() ? n : -n;
      // A sum's sign flipped to lead positive, or flipped back to take the product's.
      std::string text = flipped[i] || absorbed[i]
                             ? print_signed_power(base, power, flipped[i] != absorbed[i])
                             : print_power(base, power);
      (n.is_positive() ? num : den).push_back(std::move(text));
    }
    const std::string sep = latex() ? " " : "*";
    auto join = [&](const std::vector<std::string>& parts) {
      std::string s;
      for (std::size_t i = 0; i < parts.size(); ++i) s += (i ? sep : "") + parts[i];
      return s.empty() ? std::string("1") : s;
    };
    // In \frac a lone sum needs no parentheses: the bar groups it.
    auto frac_part = [&](const std::vector<std::string>& parts) {
      const std::string open = "\\left(", close = "\\right)";
      if (parts.size() == 1 && parts[0].rfind(open, 0) == 0 &&
          parts[0].size() >= open.size() + close.size() &&
          parts[0].compare(parts[0].size() - close.size(), close.size(), close) == 0 &&
          balanced_inside(
              parts[0].substr(open.size(), parts[0].size() - open.size() - close.size()))) {
        return parts[0].substr(open.size(), parts[0].size() - open.size() - close.size());
      }
      return join(parts);
    };
    std::string body;
    if (den.empty()) {
      body = join(num);
    } else if (latex() && frac_part(num).size() + frac_part(den).size() > kLongLatex) {
      // Too long to stack: a line of its own, (num) / (den), which a page can break.
      body = "\\left(";
      body += frac_part(num);
      body += "\\right) \\big/ \\left(";
      body += frac_part(den);
      body += "\\right)";
    } else if (latex()) {
      body = "\\frac{";  // appended piece by piece: GCC 12 -Wrestrict false positive on "a" + s
      body += frac_part(num);
      body += "}{";
      body += frac_part(den);
      body += '}';
    } else {
      body = join(num);
      body += '/';
      body += den.size() > 1 ? paren(join(den)) : den[0];
    }
    if (negative) {
      body.insert(body.begin(), '-');
      return {body, kSum};
    }
    const bool single = num.size() == 1 && den.empty();
    return {body, single && factors.size() == 1 && factors[0].second == 1 ? kAtom : kProduct};
  }
};
}  // namespace

std::string to_text(const ex& e, const SymbolTable& table) {
  PrintMemos::here().bound();
  return Printer(table, Style::text).print(e);
}

std::string to_latex(const ex& e, const SymbolTable& table) {
  PrintMemos::here().bound();
  return Printer(table, Style::latex).print(e);
}

}  // namespace wobble::sym
