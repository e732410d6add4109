// Every LaTeX key compiles with pdflatex (texlive-latex-base, installed by scripts/setup --tests)
// into pages an instructor can hand out: no overfull line over 1 pt, and in the PDF's text
// (pdftotext, poppler-utils) none of the leaks a reader would see: program syntax, raw names
// with underscores, the stroked ⊮ that amssymb prints for \mathbb{1}.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

#include "cli/run.hpp"
#include "temp_files.hpp"

using namespace wobble::test;
namespace fs = std::filesystem;

namespace {
// The widest overfull box in a pdflatex log, in pt (0 if none). (No std::regex: GCC 12 warns
// inside it under the sanitizer build's -Werror.)
double widest_overfull(const std::string& log) {
  const std::string mark = "Overfull \\hbox (";
  double widest = 0;
  for (auto p = log.find(mark); p != std::string::npos; p = log.find(mark, p + 1)) {
    widest = std::max(widest, std::stod(log.substr(p + mark.size(), 20)));
  }
  return widest;
}

bool word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

// What must never show on a page: GiNaC syntax (a*b, x^2, sin(theta0)), the glyph amssymb
// prints for \mathbb{1}, e-notation. The first one found, or "".
std::string first_leak(const std::string& t) {
  for (const std::string s : {"⊮", "sin(theta", "cos(theta", "sin(alpha", "cos(alpha",
                              "sqrt(", "sin(phi", "cos(phi", "sin(psi", "cos(psi"}) {
    if (t.find(s) != std::string::npos) return s;
  }
  for (std::size_t i = 1; i + 1 < t.size(); ++i) {
    if ((t[i] == '*' || t[i] == '^') && word_char(t[i - 1]) && word_char(t[i + 1])) {
      return t.substr(i - 1, 3);
    }
    const bool e = (t[i] == 'e' || t[i] == 'E') && std::isdigit(static_cast<unsigned char>(t[i - 1]));
    std::size_t k = i + 1;
    if (k < t.size() && (t[k] == '-' || t[k] == '+')) ++k;
    if (e && k < t.size() && std::isdigit(static_cast<unsigned char>(t[k]))) {
      return t.substr(i - 1, k - i + 2);
    }
  }
  return "";
}
}  // namespace

TEST_CASE("every LaTeX key and handout compiles, with no overfull line and no leaked code") {
  WOBBLE_NEEDS_TOOL("pdflatex");
  WOBBLE_NEEDS_TOOL("pdftotext");
  const auto dir = scratch_dir() / "latex";
  std::filesystem::create_directories(dir);
  constexpr double kMaxOverfull_pt = 1.0;  // below a point nothing sticks out visibly
  const auto ids = problem_ids();
  REQUIRE(ids.size() >= 15);
  for (const auto& id : ids) {
    for (const std::string variant : {"", " --variant 3", " --variant 5 --handout"}) {
      const std::string name =
          id + (variant.empty() ? "" : variant.find("handout") != std::string::npos ? "-handout" : "-v3");
      const auto tex = dir / (name + ".tex");
      const RunResult solve = run_shell("'" + std::string(WOBBLE_EXE) + "' solve " + id +
                                        variant + " --format latex > '" + tex.string() + "'");
      REQUIRE(solve.exit_code == 0);
      const RunResult latex = run_shell("cd '" + dir.string() +
                                        "' && pdflatex -interaction=nonstopmode -halt-on-error '" +
                                        tex.filename().string() + "'");
      INFO(name << "\n" << latex.out.substr(latex.out.size() > 3000 ? latex.out.size() - 3000 : 0));
      REQUIRE(latex.exit_code == 0);
      REQUIRE(std::filesystem::exists(dir / (name + ".pdf")));
      REQUIRE(widest_overfull(slurp(dir / (name + ".log"))) <= kMaxOverfull_pt);
      const RunResult text = run_shell("pdftotext '" + (dir / (name + ".pdf")).string() + "' -");
      REQUIRE(text.exit_code == 0);
      const std::string leak = first_leak(text.out);
      INFO("leak: " << leak);
      REQUIRE(leak.empty());
    }
  }
}

TEST_CASE("a LaTeX key includes its sketch and compiles with it, at several angles") {
  WOBBLE_NEEDS_TOOL("pdflatex");
  WOBBLE_NEEDS_TOOL("gnuplot");
  const fs::path dir = scratch_dir() / "latex-figure";
  fs::create_directories(dir);
  for (const std::string alpha : {"2deg", "40deg", "85deg"}) {
    const RunResult r = run_shell("cd '" + dir.string() + "' && '" + WOBBLE_EXE +
                                  "' solve rect-solid --set alpha=" + alpha +
                                  " --format latex --figure sketch.pdf --force > key.tex && "
                                  "pdflatex -interaction=nonstopmode -halt-on-error key.tex");
    INFO(alpha << "\n" << r.out.substr(r.out.size() > 2000 ? r.out.size() - 2000 : 0));
    REQUIRE(r.exit_code == 0);
    REQUIRE_THAT(slurp(dir / "key.tex"),
                 Catch::Contains("\\includegraphics[width=0.62\\linewidth]{sketch.pdf}"));
  }
  // pdflatex cannot include SVG: said before anything is drawn.
  const RunResult svg = run_wobble({"solve", "rect-solid", "--format", "latex", "--figure",
                                    (dir / "s.svg").string()});
  REQUIRE(svg.exit_code == 2);
  REQUIRE_FALSE(fs::exists(dir / "s.svg"));
}

