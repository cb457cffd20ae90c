#pragma once
/// The dashboard's files (server/web/index.html, app.js, app.css) and the OpenAPI document
/// (schemas/openapi.json), embedded in the binary at build time by embed.cmake and served as they are.

#include <span>
#include <string_view>

namespace saasgaps::web {

struct Asset {
  std::string_view path;          ///< "/" for index.html, "/app.js", "/openapi.json", ...
  std::string_view content_type;
  std::string_view body;
};

std::span<const Asset> assets();

}  // namespace saasgaps::web
