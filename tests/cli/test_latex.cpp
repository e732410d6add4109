// Every LaTeX key compiles with pdflatex (texlive-latex-base, installed by scripts/setup --tests)
// into pages an instructor can hand out: no overfull line over 1 pt, and in the PDF's text
// (pdftotext, poppler-utils) none of the leaks a reader would see: program syntax, raw names
// with underscores, the stroked ⊮ that amssymb prints for \mathbb{1}.
#include <catch2/catch.hpp>
#include <regex>

#include "cli/run.hpp"
#include "problem/load.hpp"
#include "temp_files.hpp"

using namespace wobble::test;

namespace {
// The widest overfull box in a pdflatex log, in pt (0 if none).
double widest_overfull(const std::string& log) {
  static const std::regex overfull(R"(Overfull \\hbox \(([0-9.]+)pt too wide\))");
  double widest = 0;
  for (auto it = std::sregex_iterator(log.begin(), log.end(), overfull);
       it != std::sregex_iterator(); ++it) {
    widest = std::max(widest, std::stod((*it)[1].str()));
  }
  return widest;
}
}  // namespace

TEST_CASE("every LaTeX key and handout compiles, with no overfull line and no leaked code") {
  const auto dir = scratch_dir() / "latex";
  std::filesystem::create_directories(dir);
  // Things that must never show on a page: GiNaC syntax (a*b, x^2, sin(theta0)), the glyph
  // amssymb prints for \mathbb{1}, e-notation.
  static const std::regex leaks(R"(\w\*\w|\w\^\w|\b(sin|cos|tan|sqrt)\((theta|phi|psi|alpha)|⊮|\d[eE][-+]?\d)");
  constexpr double kMaxOverfull_pt = 1.0;  // below a point nothing sticks out visibly
  for (const auto& p : wobble::load_catalog()) {
    for (const std::string variant : {"", " --variant 3", " --variant 5 --handout"}) {
      const std::string name =
          p.id + (variant.empty() ? "" : variant.find("handout") != std::string::npos ? "-handout" : "-v3");
      const auto tex = dir / (name + ".tex");
      const RunResult solve = run_shell("'" + std::string(WOBBLE_EXE) + "' solve " + p.id +
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
      std::smatch m;
      const bool leaked = std::regex_search(text.out, m, leaks);
      INFO("leak: " << (leaked ? m.str() : ""));
      REQUIRE_FALSE(leaked);
    }
  }
}
