#include "web/assets.hpp"

namespace wobble::web {

namespace {
std::string content_type(const std::string& path) {
  const auto dot = path.rfind('.');
  const std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  if (ext == "js") return "text/javascript; charset=utf-8";
  if (ext == "css") return "text/css; charset=utf-8";
  if (ext == "html") return "text/html; charset=utf-8";
  if (ext == "woff2") return "font/woff2";
  return "application/octet-stream";
}
}  // namespace

std::optional<Asset> asset(const std::string& path) {
  const auto& files = embedded_files();
  const auto it = files.find(path);
  if (it == files.end()) return std::nullopt;
  return Asset{it->second, content_type(path)};
}

}  // namespace wobble::web
