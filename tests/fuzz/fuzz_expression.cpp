// Expressions (parameters, positions, symbolic answers): parse, evaluate, print, simplify.
#include "fuzz_common.hpp"
#include "symbolic/canonical_print.hpp"
#include "symbolic/expression.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const wobble::sym::SymbolTable table = [] {
    wobble::sym::SymbolTable t;
    t.declare("m", "m", wobble::sym::SymbolSign::positive);
    t.declare("a", "a", wobble::sym::SymbolSign::positive);
    t.declare("alpha", "\\alpha", wobble::sym::SymbolSign::real);
    return t;
  }();
  wobble::fuzz::expect_clean([&] {
    const GiNaC::ex e = table.parse(wobble::fuzz::text_of(data, size), "expression");
    const wobble::sym::Values v{{"m", 0.3}, {"a", 1.7}, {"alpha", 0.4}};
    (void)wobble::sym::evaluate(e, wobble::sym::substitution(table, v), "expression");
    (void)wobble::sym::to_text(e, table);
    (void)wobble::sym::to_latex(e, table);
    (void)wobble::sym::is_identically_zero(e);
  });
  return 0;
}
