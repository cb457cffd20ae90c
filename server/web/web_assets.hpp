#pragma once
/// The dashboard's files (server/web/index.html, app.js, app.css), embedded in the binary at build
/// time by embed.cmake.

#include <span>
#include <string_view>

namespace saasgaps::web {

struct Asset {
  std::string_view path;          ///< "/" for index.html, "/app.js", ...
  std::string_view content_type;
  std::string_view body;
};

std::span<const Asset> assets();

}  // namespace saasgaps::web
