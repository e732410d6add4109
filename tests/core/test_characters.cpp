// Characters named in messages as typed; what would drive a terminal, or is no UTF-8, as '?'.
#include <catch2/catch.hpp>

#include "core/characters.hpp"
#include "core/word_wrap.hpp"

using namespace wobble;

TEST_CASE("a character is named as typed, with its code point and length") {
  std::size_t bytes = 0;
  REQUIRE(character_name("5é", 1, &bytes) == "'é' (U+00E9)");
  REQUIRE(bytes == 2);
  REQUIRE(character_name("ok ✓", 3, &bytes) == "'✓' (U+2713)");
  REQUIRE(bytes == 3);
  REQUIRE(character_name("𝜔", 0, &bytes) == "'𝜔' (U+1D714)");
  REQUIRE(bytes == 4);
  REQUIRE(character_name("x", 0) == "'x' (U+0078)");
}

TEST_CASE("controls are named by code point, never printed; stray bytes by value") {
  std::size_t bytes = 0;
  REQUIRE(character_name("a\x1b[31m", 1, &bytes) == "the control character U+001B");
  REQUIRE(bytes == 1);
  REQUIRE(character_name("\x7f", 0) == "the control character U+007F");
  REQUIRE(character_name("\xc2\x9b", 0, &bytes) == "the control character U+009B");  // C1 CSI
  REQUIRE(bytes == 2);
  REQUIRE(character_name("\xff", 0, &bytes) == "the byte 0xFF, which is no UTF-8");
  REQUIRE(bytes == 1);
  REQUIRE(character_name("\xc3", 0) == "the byte 0xC3, which is no UTF-8");  // cut short
  REQUIRE(character_name("\xed\xa0\x80", 0) == "the byte 0xED, which is no UTF-8");  // surrogate
  // What a terminal may obey, and what it prints.
  REQUIRE(is_control_at("a\x1b", 1));
  REQUIRE(is_control_at("\xc2\x9b", 0));
  REQUIRE(is_control_at("\x7f", 0));
  REQUIRE_FALSE(is_control_at("é", 0));
  REQUIRE_FALSE(is_control_at("\xff", 0));  // no UTF-8: named as a byte, not a control
  REQUIRE_FALSE(is_control_at(" ", 0));
}

TEST_CASE("printable text keeps what was typed and stops at a length") {
  REQUIRE(printable("m·R²/4 é", 40) == "m·R²/4 é");
  REQUIRE(printable("a\x1b[2Jb\xc2\x9b\xff", 40) == "a?[2Jb??");
  REQUIRE(printable("αβγδε", 3) == "αβγ...");
  REQUIRE(printable("abc", 3) == "abc");
  REQUIRE(printable("", 3).empty());
}

TEST_CASE("trim drops the spaces, tabs and line ends around a text; ascii_lower only letters") {
  REQUIRE(trim(" \t 5 cm \r\n") == "5 cm");
  REQUIRE(trim(" \t\r\n").empty());
  REQUIRE(trim("a") == "a");
  REQUIRE(ascii_lower("DOP853 Quit") == "dop853 quit");
  REQUIRE(ascii_lower("ÉA") == "Éa");  // bytes of a UTF-8 character are left as they are
}

TEST_CASE("digits grouped by threes are found and written without their separators") {
  REQUIRE(digits_ungrouped("26 233 128.66 s") == "26233128.66");
  REQUIRE(digits_ungrouped("26\u2009233\u2009128.66 s") == "26233128.66");  // thin spaces
  REQUIRE(digits_ungrouped("26\u202F233 kg") == "26233");                   // narrow no-break space
  REQUIRE(digits_ungrouped("26,233,128.66s") == "26233128.66");
  REQUIRE(digits_ungrouped("-1,234.5") == "-1234.5");  // one comma, then a point: a group
  REQUIRE(digits_ungrouped("26 233 128,66 s") == "26233128.66");  // and a decimal comma
  // Not so grouped: an entry of two digits, four leading digits, mixed separators, a comma
  // alone (it may be a decimal comma), what follows being no unit, numbers side by side.
  for (const char* other : {"1 4", "26 23", "2623 128", "26,233 128", "1,234", "1,234 s", "26 2331",
                            "", " ", "abc", "0.16 s", "(1, 234, 567)"}) {
    INFO(other);
    REQUIRE(digits_ungrouped(other).empty());
  }
}

TEST_CASE("a lone comma before three digits may be a decimal comma or group thousands") {
  CHECK(decimal_comma_or_grouping("437,200 min") == "437200");
  CHECK(decimal_comma_or_grouping("-1,600s") == "-1600");
  CHECK(decimal_comma_or_grouping(" 12,500") == "12500");
  // A decimal comma only: a leading 0, four digits before or after, an exponent; no number.
  for (const char* decimal : {"0,160 s", "1600,500 s", "1,6000 s", "1,600e-3 s", "1,60 s",
                              "1,600,000 s", "1.600 s", ""}) {
    INFO(decimal);
    CHECK(decimal_comma_or_grouping(decimal).empty());
  }
}

TEST_CASE("columns count what a terminal shows: a combining mark takes none") {
  CHECK(columns("") == 0);
  CHECK(columns("kg m²") == 5);
  CHECK(columns("ψ̇0") == 2);     // ψ and the combining dot above, then 0
  CHECK(columns("x̂ + v⃗") == 5);  // a hat (U+0302) and an arrow (U+20D7) on their letters
  CHECK(columns("a\xC3"
                "b") == 3);  // a byte that is no UTF-8 shows as one '?'
}

TEST_CASE("a line is broken at its spaces to the width, after its indents") {
  CHECK(word_wrapped("one two three", 0, "  ", "    ") == "  one two three\n");
  CHECK(word_wrapped("one two three", 11, "  ", "    ") == "  one two\n    three\n");
  // Exactly the width fits; a word wider than a line stays whole on its own.
  CHECK(word_wrapped("abc def", 7, "", "") == "abc def\n");
  CHECK(word_wrapped("a abcdefghij b", 5, "", "  ") == "a\n  abcdefghij\n  b\n");
  // Columns, not bytes: "ψ̇ = 2" is five columns in nine bytes.
  CHECK(word_wrapped("ψ̇ = 2 rad/s", 5, "", "") == "ψ̇ = 2\nrad/s\n");
  // A text of several lines: each broken, the later ones after `rest`.
  CHECK(word_wrapped("a b\nc d", 3, "> ", "  ") == "> a\n  b\n  c\n  d\n");
}

TEST_CASE("a document is reflowed: paragraphs joined and broken again, indented lines kept apart") {
  const std::string text =
      "Title line\n"
      "\n"
      "A statement broken\n"
      "where the file broke it.\n"
      "- an item\n"
      "\n"
      "(b) A question that is long\n"
      "\n"
      "Values:\n"
      "  m = 1 kg   (the mass of it)\n"
      "   \n";
  CHECK(reflowed(text, 0) == text);
  CHECK(reflowed(text, 20) ==
        "Title line\n"
        "\n"
        "A statement broken\n"
        "where the file broke\n"
        "it.\n"
        "- an item\n"
        "\n"
        "(b) A question that\n"
        "    is long\n"
        "\n"
        "Values:\n"
        "  m = 1 kg   (the\n"
        "    mass of it)\n"
        "\n");
}
