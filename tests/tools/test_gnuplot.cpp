// Figures and plots drawn with gnuplot (label gnuplot; skipped without it).
#include <fmt/format.h>

#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli/run.hpp"
#include "temp_files.hpp"

using namespace wobble::test;
namespace fs = std::filesystem;

TEST_CASE("solve --figure draws the sketch with gnuplot, never overwrites without --force") {
  WOBBLE_NEEDS_TOOL("gnuplot");
  const fs::path svg = scratch_dir() / "figure" / "plate.svg";
  fs::create_directories(svg.parent_path());
  fs::remove(svg);
  const RunResult r =
      run_wobble({"solve", "flying-plate", "--figure", svg.string(), "--part", "c"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const std::string content = slurp(svg);
  REQUIRE_THAT(content, Catch::StartsWith("<?xml") && Catch::Contains("<svg"));
  // Labels with true subscripts (gnuplot's enhanced text: a smaller, lowered tspan), never a
  // literal underscore.
  const std::string sub = "<tspan font-family=\"Helvetica\"  font-size=\"12.0\" dy=\"4.50px\">";
  for (const std::string& label : std::vector<std::string>{
           ">e</tspan>" + sub + "3", ">ω</tspan>", ">L</tspan>", ">Ω</tspan>" + sub + "body",
           ">Ω</tspan>" + sub + "space", "body cone", "space cone"}) {
    CHECK_THAT(content, Catch::Contains(label));
  }
  CHECK_THAT(content, !Catch::Contains("Ω_") && !Catch::Contains("e3<"));
  // No temporary files left beside it.
  for (const auto& entry : fs::directory_iterator(svg.parent_path())) {
    CHECK(entry.path().filename().string()[0] != '.');
  }
  // An existing file is kept unless --force.
  std::ofstream(svg) << "mine\n";
  const RunResult again = run_wobble({"solve", "flying-plate", "--figure", svg.string()});
  REQUIRE(again.exit_code == 2);
  REQUIRE_THAT(again.err, Catch::Contains("exists; use --force"));
  REQUIRE(slurp(svg) == "mine\n");
  REQUIRE(run_wobble({"solve", "rect-solid", "--figure", svg.string(), "--force"}).exit_code == 0);
  REQUIRE_THAT(slurp(svg), Catch::Contains("prolate body"));
  // Problems without a sketch say so.
  const RunResult none = run_wobble({"solve", "taylor-10-35", "--figure", svg.string(), "--force"});
  REQUIRE(none.exit_code == 2);
  REQUIRE_THAT(none.err, Catch::Contains("has no sketch"));
  // A file name is never a command line: quotes and a semicolon are just characters (gnuplot
  // is started without a shell).
  const fs::path odd = svg.parent_path() / "it's; touch pwned.svg";
  REQUIRE(run_wobble({"solve", "flying-plate", "--figure", odd.string()}).exit_code == 0);
  REQUIRE_THAT(slurp(odd), Catch::Contains("<svg"));
  REQUIRE_FALSE(fs::exists("pwned.svg"));
  REQUIRE_FALSE(fs::exists(svg.parent_path() / "pwned.svg"));
  // PNG and PDF by the extension; anything else is refused before drawing.
  const fs::path png = svg.parent_path() / "plate.png", pdf = svg.parent_path() / "plate.pdf";
  REQUIRE(run_wobble({"solve", "flying-plate", "--figure", png.string(), "--force"}).exit_code ==
          0);
  REQUIRE(slurp(png).substr(1, 3) == "PNG");
  REQUIRE(run_wobble({"solve", "flying-plate", "--figure", pdf.string(), "--force"}).exit_code ==
          0);
  REQUIRE(slurp(pdf).substr(0, 5) == "%PDF-");
  const RunResult gif =
      run_wobble({"solve", "flying-plate", "--figure", (svg.parent_path() / "p.gif").string()});
  REQUIRE(gif.exit_code == 2);
  REQUIRE_THAT(gif.err, Catch::Contains(".svg, .png or .pdf"));
}

TEST_CASE("simulate --plot draws the outputs with gnuplot") {
  WOBBLE_NEEDS_TOOL("gnuplot");
  const fs::path svg = scratch_dir() / "simulate" / "top.svg";
  fs::create_directories(svg.parent_path());
  fs::remove(svg);
  const RunResult r = run_wobble({"simulate", "heavy-top", "--plot", svg.string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const std::string content = slurp(svg);
  REQUIRE_THAT(content, Catch::Contains("<svg") && Catch::Contains("tilt θ (euler_zyz)") &&
                            Catch::Contains("euler_zyz (unwrapped)") &&
                            Catch::Contains("|invariant error| [J]") &&
                            !Catch::Contains("err_p_psi"));  // exactly zero: left out
  const fs::path png = svg.parent_path() / "top.png";
  REQUIRE(run_wobble({"simulate", "heavy-top", "--plot", png.string(), "--force"}).exit_code == 0);
  REQUIRE(slurp(png).substr(1, 3) == "PNG");
}

