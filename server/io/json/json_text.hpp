#pragma once
/// JSON text that can always be written. nlohmann::json::dump() throws type_error 316 on a string
/// that is not valid UTF-8; strings reach documents from outside the parser too (HTTP headers,
/// exception messages, a damaged database), and an exception while writing an error response has
/// nowhere to go. Every serialisation in server/ goes through here: invalid bytes become U+FFFD.

#include <string>

#include <nlohmann/json.hpp>

namespace saasgaps::io {

/// json.dump(indent) with invalid UTF-8 replaced by U+FFFD instead of throwing.
std::string json_text(const nlohmann::json& value, int indent = -1);

}  // namespace saasgaps::io
