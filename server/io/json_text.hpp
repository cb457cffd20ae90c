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

/// True when `text` is well-formed UTF-8 (RFC 3629: no overlong forms, surrogates or code points
/// above U+10FFFF).
bool is_utf8(std::string_view text);

}  // namespace saasgaps::io
