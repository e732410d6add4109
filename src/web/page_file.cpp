#include "web/page_file.hpp"

#include <boost/archive/iterators/base64_from_binary.hpp>
#include <boost/archive/iterators/transform_width.hpp>
#include <regex>
#include <stdexcept>

#include "web/assets.hpp"

namespace wobble::web {

namespace {
std::string base64(std::string_view bytes) {
  using namespace boost::archive::iterators;
  using Encoder = base64_from_binary<transform_width<const char*, 6, 8>>;
  std::string out(Encoder(bytes.data()), Encoder(bytes.data() + bytes.size()));
  out.append((3 - bytes.size() % 3) % 3, '=');  // the iterators leave the padding out
  return out;
}

std::string_view built_in(const std::string& path) {
  const auto a = asset(path);
  if (!a) throw std::logic_error("the page links an asset the program lacks: " + path);
  return a->bytes;
}

// Text inside <script> ends at the first "</script": written as "<\/script" it means the same
// to JavaScript (in a string, a regular expression or a comment) and no longer ends the element.
std::string script_text(std::string_view text) {
  std::string out(text);
  for (std::size_t at = 0; (at = out.find("</", at)) != std::string::npos; at += 3) {
    out.replace(at, 2, "<\\/");
  }
  return out;
}

// KaTeX's style with its fonts inlined: each font's woff2 as a data: URL (every browser that
// runs the page reads woff2), the woff and ttf alternatives dropped.
std::string katex_style() {
  std::string css(built_in("katex/katex.min.css"));
  static const std::regex others(R"(,url\(fonts/[A-Za-z0-9_-]+\.(woff|ttf)\) format\('(woff|truetype)'\))");
  css = std::regex_replace(css, others, "");
  static const std::regex woff2(R"(url\(fonts/([A-Za-z0-9_-]+\.woff2)\))");
  std::string out;
  auto begin = std::sregex_iterator(css.begin(), css.end(), woff2);
  std::size_t last = 0;
  for (auto it = begin; it != std::sregex_iterator(); ++it) {
    out.append(css, last, it->position() - last);
    out += "url(data:font/woff2;base64," + base64(built_in("katex/fonts/" + (*it)[1].str())) + ")";
    last = it->position() + it->length();
  }
  out.append(css, last);
  return out;
}
}  // namespace

std::string self_contained_page(const std::string& view_json, const std::string& motion_json,
                                const std::string& key_json) {
  std::string html(built_in("page.html"));
  static const std::regex link(R"re(<link rel="stylesheet" href="assets/([^"]+)">)re");
  static const std::regex script(R"re(<script src="assets/([^"]+)"></script>)re");
  std::string out;
  std::size_t last = 0;
  std::smatch m;
  for (auto it = html.cbegin(); std::regex_search(it, html.cend(), m, link);
       it = m.suffix().first) {
    const auto at = static_cast<std::size_t>(m.position() + (it - html.cbegin()));
    out.append(html, last, at - last);
    const std::string path = m[1].str();
    out += "<style>" + (path == "katex/katex.min.css" ? katex_style() : std::string(built_in(path))) +
           "</style>";
    last = at + m.length();
  }
  out.append(html, last);
  html.swap(out);
  out.clear();
  last = 0;
  bool data_written = false;
  for (auto it = html.cbegin(); std::regex_search(it, html.cend(), m, script);
       it = m.suffix().first) {
    const auto at = static_cast<std::size_t>(m.position() + (it - html.cbegin()));
    out.append(html, last, at - last);
    const std::string path = m[1].str();
    if (path == "view3d.js" && !data_written) {
      // The problem's data, before the page's own scripts read it.
      out += "<script>const WOBBLE_DATA = " +
             script_text("{\"view\": " + view_json + ", \"motion\": " +
                         (motion_json.empty() ? "null" : motion_json) +
                         ", \"key\": " + (key_json.empty() ? "null" : key_json) + "}") +
             ";</script>\n";
      data_written = true;
    }
    out += "<script>" + script_text(built_in(path)) + "</script>";
    last = at + m.length();
  }
  out.append(html, last);
  return out;
}

}  // namespace wobble::web
