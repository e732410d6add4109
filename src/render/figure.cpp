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

// The view: gnuplot's "set view 72, 28" turns the scene about z by 28 degrees, so a world
// vector's horizontal screen direction is x cos 28 + y sin 28 (measured on the drawn axes).
constexpr double kViewRotX_deg = 72, kViewRotZ_deg = 28;
double screen_dx(const Vec3& v) {
  const double rz = kViewRotZ_deg * M_PI / 180;
  return v.x() * std::cos(rz) + v.y() * std::sin(rz);
}

// Text for gnuplot's enhanced mode: "θ_L" and "Ω_body" with true subscripts, every other special
// character escaped.
std::string enhanced(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    // A one-letter symbol's subscript (θ_L, Ω_body, e_3): a Greek letter, or an ASCII letter
    // that starts its word.
    const bool after_greek = i > 0 && static_cast<unsigned char>(text[i - 1]) >= 0x80;
    const bool after_letter =
        i > 0 && std::isalpha(static_cast<unsigned char>(text[i - 1])) &&
        (i < 2 || !std::isalnum(static_cast<unsigned char>(text[i - 2])));
    if (c == '_' && (after_greek || after_letter)) {
      std::size_t j = i + 1;
      while (j < text.size() && std::isalnum(static_cast<unsigned char>(text[j]))) ++j;
      out += "_{" + text.substr(i + 1, j - i - 1) + "}";
      i = j - 1;
    } else if (c == '_' || c == '^' || c == '@' || c == '&' || c == '~' || c == '{' || c == '}') {
      out += "\\\\";
      out += c;
    } else if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else {
      out += c;
    }
  }
  return out;
}

// A label just beyond the tip of an arrow from `from` to `to`, on the side the arrow points
// to on the screen, so that its text runs away from the arrow instead of across it.
std::string label_beyond(int tag, const Vec3& from, const Vec3& to, const std::string& text,
                         const std::string& colour) {
  const Vec3 dir = (to - from).normalized();
  const bool leftwards = screen_dx(dir) < -0.05;
  return fmt::format("set label {} \"{}\" at {} {} tc rgb \"{}\" front\n", tag, enhanced(text),
                     xyz(to + 0.07 * dir), leftwards ? "right" : "left", colour);
}

// An arrow tangent to the rim of the cone about `axis` through `through`, at the rim point turned
// by `turn` rad from it (so the two cones' arrows do not overlap at w), in the sense `sign`.
std::string precession_arrow(int tag, const Vec3& axis, const Vec3& through, double turn,
                             double sign, const std::string& colour, const std::string& label) {
  // A rim this small (w along the axis: no wobble) has no tangent worth drawing.
  constexpr double kSmallestRim = 1e-9;
  if (sign == 0.0 || (through - through.dot(axis) * axis).norm() < kSmallestRim) return "";
  const Vec3 tip = Eigen::AngleAxisd(turn, axis) * through;
  const Vec3 tangent = (sign > 0 ? 1.0 : -1.0) * axis.cross(tip).normalized();
  const Vec3 to = tip + 0.3 * tangent;
  return fmt::format("set arrow {} from {} to {} lw 2 lc rgb \"{}\" front\n", tag, xyz(tip),
                     xyz(to), colour) +
         label_beyond(tag, tip, to, label, colour);
}

// The extent the drawing needs: the arrows and both cones' rims, with room for labels.
struct Extent {
  double xy = 0, zlo = 0, zhi = 0;
  void add(const Vec3& p) {
    xy = std::max({xy, std::abs(p.x()), std::abs(p.y())});
    zlo = std::min(zlo, p.z());
    zhi = std::max(zhi, p.z());
  }
  void add_rim(const Vec3& axis, double half_angle, double len) {
    const Vec3 p = perpendicular(axis), q = axis.cross(p);
    for (int k = 0; k < 36; ++k) {
      const double v = 2 * M_PI * k / 36;
      add(len * (std::cos(half_angle) * axis +
                 std::sin(half_angle) * (std::cos(v) * p + std::sin(v) * q)));
    }
  }
};
}  // namespace

std::string top_sketch_script(const TopSketch& s, const std::filesystem::path& out_path) {
  const double lw = 1.0, lL = 1.2, le3 = 1.35;
  const Vec3 w = lw * s.omega, L = lL * s.L, e3 = le3 * s.e3;
  // Ranges from what is drawn, so that every arrow and both axes stay in view at any alpha.
  Extent ext;
  for (const Vec3& v : {w, L, e3, Vec3(0.8, 0, 0), Vec3(0, 0.8, 0)}) ext.add(1.15 * v);
  ext.add_rim(s.e3, s.body_half_angle, lw * 1.15);
  ext.add_rim(s.L, s.space_half_angle, lw * 1.15);
  const double xy = ext.xy + 0.25;
  std::string g;
  g += "set encoding utf8\n";
  g += gnuplot_terminal(out_path, 760, 680);
  g += fmt::format("set output \"{}\"\n", gnuplot_quote(out_path.string()));
  g += fmt::format("set title \"{}\" enhanced\n", enhanced(s.title));
  g += fmt::format("set view {}, {}, 1.5\nset view equal xyz\nunset border\nunset tics\n"
                   "set key bottom right\n",
                   kViewRotX_deg, kViewRotZ_deg);
  g += fmt::format("set xrange [{0:.3f}:{1:.3f}]\nset yrange [{0:.3f}:{1:.3f}]\n"
                   "set zrange [{2:.3f}:{3:.3f}]\nset xyplane at {2:.3f}\n",
                   -xy, xy, std::min(0.0, ext.zlo - 0.1), ext.zhi + 0.15);
  // Space axes, thin and grey.
  g += "set arrow 10 from 0,0,0 to 0.8,0,0 lc rgb \"#999999\" dt 2\n";
  // Space-axis labels a line below their tips: w and L lie in the x-z plane above the x axis,
  // and cover it at large alpha.
  g += "set label 10 \"x\" at 0.8,0,0 offset 0,-1 tc rgb \"#999999\" front\n";
  g += "set arrow 11 from 0,0,0 to 0,0.8,0 lc rgb \"#999999\" dt 2\n";
  g += "set label 11 \"y\" at 0,0.8,0 offset 0,-1 tc rgb \"#999999\" front\n";
  // The three vectors.
  g += fmt::format("set arrow 1 from 0,0,0 to {} lw 3 lc rgb \"black\" front\n", xyz(e3));
  g += label_beyond(1, Vec3::Zero(), e3, "e_3", "black");
  g += fmt::format("set arrow 2 from 0,0,0 to {} lw 3 lc rgb \"#1f5fbf\" front\n", xyz(w));
  g += label_beyond(2, Vec3::Zero(), w, "ω", "#1f5fbf");
  g += fmt::format("set arrow 3 from 0,0,0 to {} lw 3 lc rgb \"#c62828\" front\n", xyz(L));
  g += label_beyond(3, Vec3::Zero(), L, "L", "#c62828");
  // Precession: w about e3 in the body (sign of Omega_body), w and e3 about L in space (+).
  g += precession_arrow(4, s.e3, w, -2.2, s.body_rate, "#1f5fbf", "Ω_body");
  g += precession_arrow(5, s.L, w, 1.7, s.space_rate, "#c62828", "Ω_space");
  g += fmt::format("set label 6 \"{} body\" at graph 0.02, graph 0.06 noenhanced\n", s.kind);
  g += "set parametric\nset urange [0:1]\nset vrange [0:2*pi]\nset isosamples 4, 41\nset samples "
       "41\n";
  g += "splot " +
       cone(s.e3, s.body_half_angle, lw, "lc rgb \"#1f5fbf\" dt 3", "body cone (about e_3)") +
       ", \\\n      " +
       cone(s.L, s.space_half_angle, lw, "lc rgb \"#c62828\" dt 1", "space cone (about L)") + "\n";
  return g;
}

void write_top_sketch(const TopSketch& sketch, const std::filesystem::path& out) {
  draw_with_gnuplot(
      [&](const std::filesystem::path& svg) { return top_sketch_script(sketch, svg); }, out);
}

}  // namespace wobble
