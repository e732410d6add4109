// Every LaTeX key compiles with pdflatex (texlive-latex-base, installed by scripts/setup --tests).
#include <catch2/catch.hpp>

#include "cli/run.hpp"
#include "problem/load.hpp"
#include "temp_files.hpp"

using namespace wobble::test;

TEST_CASE("every problem's LaTeX key compiles with pdflatex") {
  const auto dir = scratch_dir() / "latex";
  std::filesystem::create_directories(dir);
  for (const auto& p : wobble::load_catalog()) {
    const auto tex = dir / (p.id + ".tex");
    const RunResult solve = run_shell("'" + std::string(WOBBLE_EXE) + "' solve " + p.id +
                                      " --format latex > '" + tex.string() + "'");
    REQUIRE(solve.exit_code == 0);
    const RunResult latex = run_shell("cd '" + dir.string() +
                                      "' && pdflatex -interaction=nonstopmode -halt-on-error '" +
                                      tex.filename().string() + "'");
    INFO(p.id << "\n" << latex.out.substr(latex.out.size() > 3000 ? latex.out.size() - 3000 : 0));
    REQUIRE(latex.exit_code == 0);
    REQUIRE(std::filesystem::exists(dir / (p.id + ".pdf")));
  }
}
