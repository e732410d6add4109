#include "render/figure.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include "render/gnuplot.hpp"

namespace wobble {

namespace {
std::string xyz(const Vec3& v) {
  return fmt::format("{:.6f},{:.6f},{:.6f}", v.x(), v.y(), v.z());
}

// A unit vector perpendicular to a (a unit).
Vec3 perpendicular(const Vec3& a) {
  const Vec3 helper = std::abs(a.y()) < 0.9 ? Vec3::UnitY() : Vec3::UnitX();
  return helper.cross(a).normalized();
}

// A cone of half angle h about the unit axis a, of slant length len, as gnuplot parametric
// functions of (u, v): u along the generators, v around.
std::string cone(const Vec3& a, double h, double len, const std::string& style,
                 const std::string& title) {
  const Vec3 p = perpendicular(a), q = a.cross(p);
  auto coord = [&](int i) {
    return fmt::format("u*{len:.6f}*({c:.6f}*{a:.6f} + {s:.6f}*(cos(v)*{p:.6f} + sin(v)*{q:.6f}))",
                       fmt::arg("len", len), fmt::arg("c", std::cos(h)), fmt::arg("a", a[i]),
                       fmt::arg("s", std::sin(h)), fmt::arg("p", p[i]), fmt::arg("q", q[i]));
  };
  return fmt::format("{}, {}, {} with lines {} title \"{}\"", coord(0), coord(1), coord(2), style,
                     title);
}

// An arrow tangent to the rim of the cone about `axis` through `through`, at the rim point turned
// by `turn` rad from it (so the two cones' arrows do not overlap at w), in the sense `sign`.
std::string precession_arrow(int tag, const Vec3& axis, const Vec3& through, double turn,
                             double sign, const std::string& colour, const std::string& label) {
  if (sign == 0.0 || (through - through.dot(axis) * axis).norm() < 1e-9) return "";
  const Vec3 tip = Eigen::AngleAxisd(turn, axis) * through;
  const Vec3 tangent = (sign > 0 ? 1.0 : -1.0) * axis.cross(tip).normalized();
  const Vec3 to = tip + 0.3 * tangent;
  return fmt::format(
      "set arrow {} from {} to {} lw 2 lc rgb \"{}\" front\n"
      "set label {} \"{}\" at {} tc rgb \"{}\" noenhanced front\n",
      tag, xyz(tip), xyz(to), colour, tag, label, xyz(to + 0.06 * tangent), colour);
}
}  // namespace

std::string top_sketch_script(const TopSketch& s, const std::filesystem::path& svg_path) {
  const double lw = 1.0, lL = 1.2, le3 = 1.35;
  const Vec3 w = lw * s.omega, L = lL * s.L, e3 = le3 * s.e3;
  std::string g;
  g += "set encoding utf8\n";
  g += fmt::format(
      "set terminal svg size 760,680 dynamic font \"Helvetica,15\" background rgb \"white\"\n");
  g += fmt::format("set output \"{}\"\n", svg_path.string());
  g += fmt::format("set title \"{}\" noenhanced\n", s.title);
  g +=
      "set view 72, 28, 1.25\nset view equal xyz\nunset border\nunset tics\nset key bottom right\n";
  g += "set xrange [-0.9:0.9]\nset yrange [-0.9:0.9]\nset zrange [0:1.45]\nset xyplane at 0\n";
  // Space axes, thin and grey.
  g += "set arrow 10 from 0,0,0 to 0.8,0,0 lc rgb \"#999999\" dt 2\nset label 10 \"x\" at 0.86,0,0 "
       "tc rgb \"#999999\"\n";
  g += "set arrow 11 from 0,0,0 to 0,0.8,0 lc rgb \"#999999\" dt 2\nset label 11 \"y\" at 0,0.86,0 "
       "tc rgb \"#999999\"\n";
  // The three vectors.
  g += fmt::format("set arrow 1 from 0,0,0 to {} lw 3 lc rgb \"black\" front\n", xyz(e3));
  g += fmt::format("set label 1 \"e3\" at {} noenhanced front\n", xyz(e3 + Vec3(0.04, 0, 0.05)));
  g += fmt::format("set arrow 2 from 0,0,0 to {} lw 3 lc rgb \"#1f5fbf\" front\n", xyz(w));
  g += fmt::format("set label 2 \"ω\" at {} tc rgb \"#1f5fbf\" noenhanced front\n",
                   xyz(w + Vec3(0.06, 0, 0.0)));
  g += fmt::format("set arrow 3 from 0,0,0 to {} lw 3 lc rgb \"#c62828\" front\n", xyz(L));
  g += fmt::format("set label 3 \"L\" at {} tc rgb \"#c62828\" noenhanced front\n",
                   xyz(L + Vec3(0.05, 0, 0.03)));
  // Precession: w about e3 in the body (sign of Omega_body), w and e3 about L in space (+).
  g += precession_arrow(4, s.e3, w, -2.2, s.body_rate, "#1f5fbf", "Ω_body");
  g += precession_arrow(5, s.L, w, 1.7, s.space_rate, "#c62828", "Ω_space");
  g += fmt::format("set label 6 \"{} body\" at graph 0.02, graph 0.06 noenhanced\n", s.kind);
  g += "set parametric\nset urange [0:1]\nset vrange [0:2*pi]\nset isosamples 4, 41\nset samples "
       "41\n";
  g += "splot " +
       cone(s.e3, s.body_half_angle, lw, "lc rgb \"#1f5fbf\" dt 3", "body cone (about e3)") +
       ", \\\n      " +
       cone(s.L, s.space_half_angle, lw, "lc rgb \"#c62828\" dt 1", "space cone (about L)") + "\n";
  return g;
}

void write_top_sketch(const TopSketch& sketch, const std::filesystem::path& out) {
  draw_svg_with_gnuplot(
      [&](const std::filesystem::path& svg) { return top_sketch_script(sketch, svg); }, out);
}

}  // namespace wobble
