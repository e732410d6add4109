#pragma once
/// @file
/// The page's files, built into the program at build time: KaTeX (its script, style and fonts,
/// from Debian's libjs-katex and fonts-katex), three.js and its orbit controls (libjs-three),
/// and wobble's own page (src/web/page). An installed program serves and inlines them with no
/// network and no file beside it.
#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace wobble::web {

/// Every built-in file by the path the page asks for ("katex/katex.min.js", "page.js").
const std::map<std::string, std::string_view>& embedded_files();

struct Asset {
  std::string_view bytes;
  std::string content_type;
};

/// The file at exactly `path` (no normalisation: "../x" or "a//b" name no file), with its
/// content type from its extension; nothing for any other path.
std::optional<Asset> asset(const std::string& path);

}  // namespace wobble::web
