#include "web/page_file.hpp"

#include <boost/archive/iterators/base64_from_binary.hpp>
#include <boost/archive/iterators/transform_width.hpp>
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
// runs the page reads woff2), the woff and ttf alternatives dropped. The style names its fonts
// as `url(fonts/NAME.EXT) format('KIND')`, the alternatives separated by commas. (Plain string
// search: GCC 12's <regex> does not build warning-free under the sanitizers.)
std::string katex_style() {
  const std::string css(built_in("katex/katex.min.css"));
  const std::string url = "url(fonts/";
  std::string out;
  std::size_t last = 0;
  for (std::size_t at = css.find(url); at != std::string::npos; at = css.find(url, last)) {
    const std::size_t name_end = css.find(')', at);
    const std::size_t format_end = css.find(')', name_end + 1);
    if (name_end == std::string::npos || format_end == std::string::npos) {
      throw std::logic_error("KaTeX's style names a font in a form this program does not know");
    }
    out.append(css, last, at - last);
    const std::string name = css.substr(at + url.size(), name_end - at - url.size());
    const bool woff2 = name.size() > 6 && name.compare(name.size() - 6, 6, ".woff2") == 0;
    if (woff2) {
      out += "url(data:font/woff2;base64," + base64(built_in("katex/fonts/" + name)) + ")";
      out.append(css, name_end + 1, format_end + 1 - (name_end + 1));
    } else if (!out.empty() && out.back() == ',') {
      out.pop_back();  // the comma before an alternative dropped with it
    }
    last = format_end + 1;
  }
  out.append(css, last);
  return out;
}

// Each `BEFORE PATH AFTER` of the page (PATH an asset) replaced by what `inline_asset` makes of it.
template <class F>
std::string replace_links(const std::string& html, const std::string& before,
                          const std::string& after, F inline_asset) {
  std::string out;
  std::size_t last = 0;
  for (std::size_t at = html.find(before); at != std::string::npos;
       at = html.find(before, last)) {
    const std::size_t path_end = html.find(after, at + before.size());
    if (path_end == std::string::npos) throw std::logic_error("the page has an unclosed link");
    out.append(html, last, at - last);
    out += inline_asset(html.substr(at + before.size(), path_end - at - before.size()));
    last = path_end + after.size();
  }
  out.append(html, last);
  return out;
}
}  // namespace

std::string self_contained_page(const std::string& view_json, const std::string& motion_json,
                                const std::string& key_json) {
  const std::string html = replace_links(
      std::string(built_in("page.html")), "<link rel=\"stylesheet\" href=\"assets/", "\">",
      [](const std::string& path) {
        return "<style>" +
               (path == "katex/katex.min.css" ? katex_style() : std::string(built_in(path))) +
               "</style>";
      });
  bool data_written = false;
  return replace_links(html, "<script src=\"assets/", "\"></script>", [&](const std::string& path) {
    std::string out;
    if (path == "view3d.js" && !data_written) {
      // The problem's data, before the page's own scripts read it.
      out += "<script>const WOBBLE_DATA = " +
             script_text("{\"view\": " + view_json + ", \"motion\": " +
                         (motion_json.empty() ? "null" : motion_json) +
                         ", \"key\": " + (key_json.empty() ? "null" : key_json) + "}") +
             ";</script>\n";
      data_written = true;
    }
    return out + "<script>" + script_text(built_in(path)) + "</script>";
  });
}

}  // namespace wobble::web
