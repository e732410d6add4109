#include "export/html_text.hpp"

#include "symbolic/unicode_notation.hpp"

namespace wobble::exports {

std::string html_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string statement_html(const std::string& statement, const std::string& open,
                           const std::string& close) {
  std::string out = "<p>";
  bool math = false, code = false;
  for (std::size_t i = 0; i < statement.size(); ++i) {
    const char c = statement[i];
    if (c == '$') {
      out += math ? close : open;
      math = !math;
    } else if (c == '`' && !math) {
      out += code ? "</code>" : "<code>";
      code = !code;
    } else if (c == '\n' && i + 1 < statement.size() && statement[i + 1] == '\n' && !math) {
      out += "</p>\n<p>";
      ++i;
    } else if (c == '\n') {
      out += ' ';
    } else {
      out += html_escape(std::string(1, c));
    }
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out + "</p>\n";
}

std::string inline_html(const std::string& text, const std::string& open,
                        const std::string& close) {
  const std::string p = statement_html(text, open, close);  // "<p>...</p>\n"
  return p.substr(3, p.size() - 3 - 5);
}

std::string unit_html(const std::string& unit) { return html_escape(sym::to_unicode(unit)); }

}  // namespace wobble::exports
