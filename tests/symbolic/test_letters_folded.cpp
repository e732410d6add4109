// Letters as mathematical typesetting styles them, read as the letters they are: what a word
// processor's equation or a PDF gives when copied. Each styled block is checked at its ends and
// at its holes, so an offset off by one letter cannot pass.
#include <catch2/catch.hpp>
#include <string>
#include <utility>
#include <vector>

#include "symbolic/unicode_notation.hpp"

using wobble::sym::letters_folded;
using wobble::sym::to_ascii;

TEST_CASE("styled Latin letters and digits fold to ASCII, each style at its ends") {
  for (const auto& [styled, plain] : std::vector<std::pair<std::string, std::string>>{
           {"𝐀", "A"},     // bold, the block's first
           {"𝐳", "z"},     // bold, last
           {"𝐼", "I"},     // italic
           {"𝑧", "z"},     // italic, last
           {"ℎ", "h"},     // italic h, from Letterlike Symbols
           {"𝙰", "A"},     // monospace, the last style
           {"𝚣", "z"},     // monospace, the Latin's last letter
           {"𝟎", "0"},     // bold digits, first
           {"𝟗", "9"},     // bold nine
           {"𝟿", "9"}}) {  // monospace nine, the block's last
    INFO(styled);
    REQUIRE(letters_folded(styled) == plain);
  }
}

TEST_CASE("styled and variant Greek letters fold to the usual Greek letter") {
  for (const auto& [styled, plain] : std::vector<std::pair<std::string, std::string>>{
           {"𝚨", "Α"},  // bold capital alpha, the Greek's first
           {"𝛀", "Ω"},  // bold capital omega
           {"𝛚", "ω"},  // bold omega
           {"𝜔", "ω"},  // italic omega
           {"𝜃", "θ"},  // italic theta
           {"𝜗", "θ"},  // italic theta symbol
           {"𝜖", "ε"},  // italic lunate epsilon
           {"𝜑", "φ"},  // italic phi
           {"𝜙", "φ"},  // italic phi symbol
           {"𝟉", "ϖ"},  // sans-serif bold italic varpi, the Greek's last: no π, so no fold
           {"ϵ", "ε"},
           {"ϑ", "θ"},
           {"ϕ", "φ"},
           {"ϱ", "ρ"},
           {"ς", "σ"}}) {
    INFO(styled);
    REQUIRE(letters_folded(styled) == plain);
  }
  // ∂ and ∇ are no letters: they stay, for the expression guard to name.
  REQUIRE(letters_folded("𝜕") == "∂");
}

TEST_CASE("two styled letters in a row are two symbols; invisible operators are read") {
  REQUIRE(letters_folded("𝑚𝑅²") == "m R²");
  REQUIRE(letters_folded("𝐼₁𝜔₁") == "I₁ω₁");  // a subscript between: already apart
  REQUIRE(letters_folded("2𝑚") == "2m");      // a digit is no letter
  REQUIRE(letters_folded("cos\u2061𝛼") == "cos α");
  REQUIRE(letters_folded("2\u2062𝑚") == "2*m");
  REQUIRE(letters_folded("a\u200bb") == "ab");
  // The spacing dot above after a letter is Newton's dot, as a PDF gives it; alone it stays.
  REQUIRE(letters_folded("φ˙") == "φ\u0307");
  REQUIRE(letters_folded("𝜓˙") == "ψ\u0307");
  REQUIRE(letters_folded("˙x") == "˙x");
  REQUIRE(to_ascii("θ˙₀") == "thetadot0");
  // Plain text is left as it was, bytes that are no UTF-8 included.
  REQUIRE(letters_folded("mR^2 ω \xff") == "mR^2 ω \xff");
  REQUIRE(to_ascii("𝑚𝑅²/𝟒") == "m R^2/4");
}
